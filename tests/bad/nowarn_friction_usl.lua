-- expect: 0
-- stderr-not: warning
-- The same block under scheme = "usl", and a release pair under "musl",
-- are not warned of (issue 30 item 2; l_option_warn.c: only friction under
-- MUSL misses the incline case).
local scenes = require("contact_scenes")
for _, c in ipairs{ { scheme = "usl", law = "friction" }, { scheme = "musl", law = "release" } } do
  local sim = scenes.incline{ theta = 30, mu = 0.3, basis = "gimp", scheme = c.scheme, law = c.law }
  sim:run{ t_end = 0.002 }
end
