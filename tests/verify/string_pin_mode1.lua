-- Verification case (issue 30 item 1): a taut string's mode 1, ends held by
-- body:pin at both end points, away from any wall. The exact period
-- 2 L / (n sqrt(T / mu)) is derived in lib/string_modes.lua.
-- verify: membrane
require("lib.string_modes").run{ ends = "pin", mode = 1 }
