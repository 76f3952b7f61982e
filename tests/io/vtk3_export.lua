-- sim:vtk of a 3D run (issue 34 item 1): a ball and a box of two materials,
-- trilinear basis, written every 1e-3 to t = 3e-3. The state is printed as
-- PRE lines (the positions at the start of the last step, for the grid's
-- reference) and REF lines (body, x, y, z, vx, vy, vz, sxx, syy, szz, syz,
-- sxz, sxy, rho, mass) for tests/io/vtk3_check.py, which reads the files
-- back with VTK's own reader and with meshio and compares them.
local out = lamina.param("out", "out/vtk3_export/run")
local sim = lamina.sim{ dim = 3, basis = "linear", domain = {0, 0, 0, 1, 0.8, 0.6}, cell = 0.1,
                        dt = 5e-5, gravity = {0, 0, -9.81} }
local a = sim:body{ material = lamina.elastic{ rho = 1000, E = 1e5, nu = 0.3 }, name = "ball",
                    region = lamina.ball{ center = {0.3, 0.3, 0.3}, radius = 0.15 },
                    velocity = function(x, y, z)   -- three distinct shears: the stress order shows
                      return 1 + (z - 0.3), 0.5 + 0.3 * (x - 0.3), -0.2 * (x - 0.3) + 0.1 * (y - 0.3)
                    end }
local b = sim:body{ material = lamina.elastic{ rho = 500, E = 2e5, nu = 0.25 }, name = "box",
                    region = lamina.box{ min = {0.6, 0.4, 0.2}, max = {0.8, 0.6, 0.4} },
                    velocity = {-1, 0, 0.3} }
sim:vtk{ file = out, every = 0.001 }
sim:run{ t_end = 0.003 - 5e-5 }
local pre = {}
for k, body in ipairs{a, b} do
  local q = body:particles()
  for i = 1, q.n do
    pre[#pre + 1] = string.format("PRE %d %.17g %.17g %.17g %.17g", k, q.x[i], q.y[i], q.z[i],
                                  q.mass[i])
  end
end
sim:step(1)
print(table.concat(pre, "\n"))
print(string.format("GRID h 0.1 nx 10 ny 8 nz 6 steps %d", sim.nstep))
print(string.format("META t %.17g", sim.t))
for k, body in ipairs{a, b} do
  local q = body:particles()
  for i = 1, q.n do
    print(string.format("REF %d" .. string.rep(" %.17g", 14), k, q.x[i], q.y[i], q.z[i],
      q.vx[i], q.vy[i], q.vz[i], q.sxx[i], q.syy[i], q.szz[i], q.syz[i], q.sxz[i], q.sxy[i],
      q.rho[i], q.mass[i]))
  end
end
