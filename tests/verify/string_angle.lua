-- Verification case (issue 30 item 1): the pinned string's mode 1 laid at 30
-- degrees to the grid's lines (lib/string_modes.lua derives the period
-- 2 L / sqrt(T / mu); the exact answer does not depend on the angle).
-- verify: membrane
require("lib.string_modes").run{ ends = "pin", mode = 1, angle = 30 }
