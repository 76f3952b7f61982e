-- expect: 2
-- stderr: sim3_courant\.lua:8: dt = 0\.01: the Courant number dt c / h = 3\.669 \(c = 36\.69, h = 0\.1\) is above the limit 1; take dt <= 0\.00272554 or raise courant
-- The Courant check of a 3D run, before the first step: c the dilatational
-- speed sqrt((lambda + 2 G) / rho) = 36.69 m/s for E = 1e6, nu = 0.3, rho = 1000.
local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, 1, 1, 1}, cell = 0.1, dt = 1e-2 }
sim:body{ material = lamina.elastic{ rho = 1000, E = 1e6, nu = 0.3 },
          region = lamina.box{ x0 = 0.3, y0 = 0.3, z0 = 0.3, x1 = 0.6, y1 = 0.6, z1 = 0.6 } }
sim:run{ t_end = 0.1 }
