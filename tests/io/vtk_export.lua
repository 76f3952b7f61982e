-- sim:vtk (issue 20 item 1): a disk, a gas block and a membrane arc, written
-- every 1e-3 to t = 3e-3. The particle state at the end is printed as REF
-- lines (body, x, y, vx, vy, sxx, syy, sxy, rho, mass, p, nx, ny) for
-- tests/io/vtk_check.py, which reads the files back with meshio and with
-- VTK's own readers and compares them with these values.
local out = lamina.param("out", "out/vtk_export/run")
local sim = lamina.sim{basis = "linear", domain = {0, 0, 1, 1}, cell = 0.1, dt = 5e-5}
local el = lamina.elastic{rho = 1000, E = 1e5, nu = 0.3}
local disk = sim:body{material = el, region = lamina.disk{center = {0.3, 0.3}, radius = 0.15},
                      velocity = {1, 0.5}, name = "disk"}
local air = lamina.gas{rho = 1, p = 1000}
local gas = sim:body{material = air, name = "gas",
                     region = lamina.rect{x0 = 0.6, y0 = 0.6, x1 = 0.9, y1 = 0.9}}
local skin = lamina.membrane{rho = 0.5, E = 1e6, thickness = 0.1}
local m = sim:membrane{force = "point", material = skin, count = 12, name = "m", initial_strain = 0.001,
                       curve = lamina.arc{center = {0.5, 0.5}, radius = 0.45, from = 200, to = 250}}
sim:vtk{file = out, every = 0.001}
-- the positions at the start of the last step: the grid file holds that
-- step's nodal mass, sum over p of m_p N_i(x_p), which vtk_check.py
-- computes from these PRE lines (body, x, y, mass) with the linear basis
sim:run{t_end = 0.003 - 5e-5}
local pre = {}
for b, body in ipairs{disk, gas, m} do
  local q = body:particles()
  for i = 1, q.n do
    pre[#pre + 1] = string.format("PRE %d %.17g %.17g %.17g", b, q.x[i], q.y[i], q.mass[i])
  end
end
sim:step(1)
print(table.concat(pre, "\n"))
print(string.format("GRID x0 0 y0 0 h 0.1 nx 10 ny 10 steps %d", sim.nstep))
print(string.format("META t %.17g membrane_points %d", sim.t, #m))
for b, body in ipairs{disk, gas, m} do
  local q = body:particles()
  for i = 1, q.n do
    print(string.format("REF %d %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g",
      b, q.x[i], q.y[i], q.vx[i], q.vy[i], q.sxx[i], q.syy[i], q.sxy[i], q.rho[i], q.mass[i],
      q.p and q.p[i] or 0, q.nx and q.nx[i] or 0, q.ny and q.ny[i] or 0))
  end
end
