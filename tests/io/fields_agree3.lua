-- One pressure in 3D (issue 34 item 1, as issue 33 item 2 in 2D): a gas
-- block driven into the wall with the artificial viscosity on (q > 0, so
-- the step's stress -(p^k + q) I plus its viscous part is not the gas's
-- pressure) beside an elastic ball. The frame coloured by "pressure",
-- sim:vtk and body:particles() must all give the one definition
-- (src/lua/l_pressure3.h): the gas's (gamma - 1) rho e, the solid's
-- -tr sigma / 3. Prints lines for tests/io/fields_agree3.py.
local out = lamina.param("out", "out/fields_agree3")
local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, 1, 1, 0.2}, cell = 0.1, dt = 1e-4 }
local air = lamina.gas{ rho = 1, p = 1000, av = true, mu = 0.5 }
local gas = sim:body{ material = air, name = "gas", velocity = {-20, 0, 0},
                      region = lamina.box{ x0 = 0.15, y0 = 0.2, z0 = 0, x1 = 0.55, y1 = 0.6,
                                           z1 = 0.2 } }
local el = lamina.elastic{ rho = 1000, E = 1e5, nu = 0.3 }
local ball = sim:body{ material = el, name = "ball", velocity = {0, -1, 0},
                       region = lamina.ball{ center = {0.75, 0.75, 0.1}, radius = 0.1 } }
sim:run{ t_end = 0.004 }
sim:vtk{ file = out .. "/run" }
sim:frame{ file = out .. "/pressure.png", width = 320, height = 320, colour = "pressure",
           backend = "cairo" }
local g = air.gamma
for b, body in ipairs{gas, ball} do
  local q = body:particles()
  for i = 1, q.n do
    print(string.format("P %d %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g", b,
      q.pressure and q.pressure[i] or 0, q.p and q.p[i] or 0, q.sxx[i], q.syy[i], q.szz[i],
      q.rho[i], q.e and q.e[i] or 0, g))
  end
end
