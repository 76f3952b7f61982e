-- expect: 0
-- stderr: warning: body 'block' \(body 2\) slides with law = "friction" under scheme = "musl" .*case incline\); scheme = "usl" gives -0\.07 / -2\.44 / -0\.16 %
-- stderr-once: lamina: warning:
-- Friction under the default scheme is warned of once (issue 30 item 2;
-- l_option_warn.c): the verification case incline's block, two sims, one
-- warning.
local g, th = 10, math.rad(30)
for k = 1, 2 do
  local sim = lamina.sim{ domain = {0, 0, 4, 1.5}, cell = 0.1, dt = 2e-4, basis = "gimp",
                          gravity = {g * math.sin(th), -g * math.cos(th)} }
  local mat = lamina.elastic{ rho = 1, E = 1e4, nu = 0.3, plane = "strain" }
  local plane = sim:body{ material = mat, ppc = 4, name = "plane",
                          region = lamina.rect{ min = {0.2, 0.2}, max = {3.8, 0.6} } }
  plane:pin{ points = "all" }
  local block = sim:body{ material = mat, ppc = 4, name = "block",
                          region = lamina.rect{ min = {0.5, 0.6}, max = {1.0, 0.9} } }
  sim:contact{ block, plane, law = "friction", mu = 0.3 }
  sim:run{ t_end = 0.002 }
end
