-- expect: 0
-- stderr: warning: membrane 'wire' \(body 1\) has force = "point": .*string_wall_\*
-- A membrane with the papers' point forces is warned of once (issue 30 item 2;
-- l_option_warn.c).
local sim = lamina.sim{ domain = {0, 0, 1, 0.5}, cell = 0.1, dt = 1e-4 }
sim:membrane{ material = lamina.membrane{ rho = 100, E = 5e4, nu = 0, thickness = 0.01, law = "uniaxial" },
              name = "wire", force = "point", spacing = 0.05,
              curve = lamina.segment{ from = {0, 0.25}, to = {1, 0.25} } }
sim:run{ t_end = 1e-3 }
