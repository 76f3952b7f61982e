-- expect: 2
-- stderr: sim:body: 'material': lamina.gas\{density = \.\.\.\}: 3D has density = "continuity" only
-- A 2D-only gas key in a 3D body is refused by name (issue 34 item 1): the
-- 3D engine finds a gas point's density by continuity only.
local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, 1, 1, 1}, cell = 0.1, dt = 1e-3 }
sim:body{ material = lamina.gas{ rho = 1, p = 1, density = "cell" },
          region = lamina.box{ x0 = 0, y0 = 0, z0 = 0, x1 = 1, y1 = 1, z1 = 1 } }
