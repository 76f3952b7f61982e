-- Verification case (issue 30 item 1): a taut string's mode 2, ends held by
-- fixed walls (the domain's sides). The exact period
-- 2 L / (n sqrt(T / mu)) is derived in lib/string_modes.lua.
-- verify: membrane
require("lib.string_modes").run{ ends = "wall", mode = 2 }
