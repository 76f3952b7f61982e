-- sim:vtk of a 3D run with membranes (issue 34 item 2), for
-- tests/io/vtk3_membrane.py: a balloon under pressure (a sphere, its
-- normals from the construction, [N] Fig 11) and a pre-tensioned sheet
-- pinned at its edges beside a box, written every 1e-3 to t = 2e-3. Prints
-- MREF lines (membrane, x, y, z, vx, vy, vz, nx, ny, nz, tension, area,
-- mass, t11, t22, t12) of the last state, and COUNT lines (the points of
-- each membrane, the pinned ones) for the check, which reads the files back
-- with VTK's reader and meshio.
local out = lamina.param("out", "out/vtk3_membrane/run")
local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, 1, 1, 1}, cell = 0.1, dt = 5e-4 }
sim:body{ material = lamina.elastic{ rho = 1000, E = 1e6, nu = 0.3 }, velocity = {0, 0, -1},
          region = lamina.box{ min = {0.1, 0.1, 0.7}, max = {0.3, 0.3, 0.9} } }
local skin = lamina.membrane{ rho = 1000, E = 1e6, nu = 0.3, thickness = 1e-3, law = "plane_stress" }
local ms = {
  sim:membrane{ material = skin, spacing = 0.05, pressure = 100, normals = "quadratic",
                surface = lamina.sphere{ center = {0.55, 0.5, 0.6}, radius = 0.2 } },
  sim:membrane{ material = skin, spacing = 0.05, initial_strain = 0.01, pin = "edges", pressure = -30,
                surface = lamina.rect3{ origin = {0.2, 0.2, 0.2}, u = {0.6, 0, 0}, v = {0, 0.6, 0.1} } },
}
sim:vtk{ file = out, every = 0.001 }
sim:run{ t_end = 0.002 }
print(string.format("META t %.17g", sim.t))
for k, m in ipairs(ms) do
  local p = m:particles()
  print(string.format("COUNT %d %d", k, p.n))
  for i = 1, p.n do
    print(string.format("MREF %d" .. string.rep(" %.17g", 15), k, p.x[i], p.y[i], p.z[i],
      p.vx[i], p.vy[i], p.vz[i], p.nx[i], p.ny[i], p.nz[i], p.tension[i], p.area[i], p.mass[i],
      p.t11[i], p.t22[i], p.t12[i]))
  end
end
