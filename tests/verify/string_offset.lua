-- Verification case (issue 30 item 1): the walled string's mode 1 laid a
-- third of a cell off the node line (lib/string_modes.lua derives the period
-- 2 L / sqrt(T / mu); the exact answer does not depend on where the grid is).
-- verify: membrane
require("lib.string_modes").run{ ends = "wall", mode = 1, offset = 1 / 3 }
