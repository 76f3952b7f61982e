-- expect: 0
-- stderr: warning: body 'block' \(body 2\) slides with law = "friction" under scheme = "musl" .*case incline\); scheme = "usl" gives -0\.07 / -2\.44 / -0\.16 %
-- stderr-once: lamina: warning:
-- Friction under the default scheme is warned of once (issue 30 item 2;
-- l_option_warn.c): the verification case incline's block
-- (assets/lua/contact_scenes.lua), two sims, one warning.
local scenes = require("contact_scenes")
for _ = 1, 2 do
  local sim = scenes.incline{ theta = 30, mu = 0.3, basis = "gimp" }
  sim:run{ t_end = 0.002 }
end
