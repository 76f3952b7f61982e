-- expect: 2
-- stderr: lamina.gas: unknown key 'gama' \(known keys: rho, e, p, gamma
-- A gas key misspelt in a 3D script is refused by name (issue 34 item 1):
-- the 2D and 3D runs share lamina.gas{}, nothing is added.
local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, 1, 1, 1}, cell = 0.1, dt = 1e-3 }
sim:body{ material = lamina.gas{ rho = 1, p = 1, gama = 1.4 },
          region = lamina.box{ x0 = 0, y0 = 0, z0 = 0, x1 = 1, y1 = 1, z1 = 1 } }
