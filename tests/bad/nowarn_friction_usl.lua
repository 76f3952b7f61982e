-- expect: 0
-- stderr-not: warning
-- The same block under scheme = "usl", and a release pair under "musl",
-- are not warned of (issue 30 item 2; l_option_warn.c: only friction under
-- MUSL misses the incline case).
local g, th = 10, math.rad(30)
for _, c in ipairs{ { scheme = "usl", law = "friction" }, { scheme = "musl", law = "release" } } do
  local sim = lamina.sim{ domain = {0, 0, 4, 1.5}, cell = 0.1, dt = 2e-4, basis = "gimp",
                          scheme = c.scheme, gravity = {g * math.sin(th), -g * math.cos(th)} }
  local mat = lamina.elastic{ rho = 1, E = 1e4, nu = 0.3, plane = "strain" }
  local plane = sim:body{ material = mat, ppc = 4, name = "plane",
                          region = lamina.rect{ min = {0.2, 0.2}, max = {3.8, 0.6} } }
  plane:pin{ points = "all" }
  local block = sim:body{ material = mat, ppc = 4, name = "block",
                          region = lamina.rect{ min = {0.5, 0.6}, max = {1.0, 0.9} } }
  if c.law == "friction" then
    sim:contact{ block, plane, law = "friction", mu = 0.3 }
  else
    sim:contact{ block, plane, law = "release" }
  end
  sim:run{ t_end = 0.002 }
end
