-- One pressure everywhere (issue 33 item 2): a gas block driven into the
-- wall with the artificial viscosity on (so q > 0 and the step's stress,
-- -(p^k + q) I plus its viscous part, is not the gas's pressure), beside an
-- elastic disk. The frame coloured by "pressure", sim:vtk, body:particles()
-- and a recorder's field column must all give the table's pressure (src/mpm/
-- fields.c): the gas's equation of state (gamma - 1) rho e, the solid's
-- -tr sigma / 3. Prints lines for tests/io/fields_agree.py.
local out = lamina.param("out", "out/fields_agree")
local sim = lamina.sim{domain = {0, 0, 1, 1}, cell = 0.1, dt = 1e-4}
local air = lamina.gas{rho = 1, p = 1000, av = true, mu = 0.5}
local gas = sim:body{material = air, name = "gas", velocity = {-20, 0},
                     region = lamina.rect{x0 = 0.15, y0 = 0.2, x1 = 0.55, y1 = 0.6}}
local el = lamina.elastic{rho = 1000, E = 1e5, nu = 0.3}
local disk = sim:body{material = el, region = lamina.disk{center = {0.75, 0.75}, radius = 0.12},
                      velocity = {0, -1}, name = "disk"}
local rec = sim:record{every = 1e-4, fields = {p_gas = {gas, 7, "pressure"}, szz_disk = {disk, 3, "szz"}}}
sim:run{t_end = 0.004}
sim:vtk{file = out .. "/run"}
sim:frame{file = out .. "/pressure.png", width = 320, height = 320, colour = "pressure"}
sim:frame{file = out .. "/disk_pressure.png", width = 320, height = 320, colour = "pressure",
          colour_bodies = {disk}}
local t = rec:column("t")
print(string.format("META t %.17g rec_t %.17g", sim.t, t[#t]))
print(string.format("REC %.17g %.17g", rec:column("p_gas")[#t], rec:column("szz_disk")[#t]))
for b, body in ipairs{gas, disk} do
  local q = body:particles()
  for i = 1, q.n do
    print(string.format("P %d %d %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g",
      b, i, q.pressure[i], q.p[i], q.sxx[i], q.syy[i], q.szz[i], q.rho[i],
      q.e and q.e[i] or 0, q.q and q.q[i] or 0, 1.4))
  end
end
