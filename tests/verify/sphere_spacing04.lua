-- Verification case (issue 30 item 1): the gas-filled axisymmetric sphere (sigma t = p r / 2), membrane
-- points 0.4 cells apart. Exact answer derived in lib/gas_balloon.lua.
-- verify: membrane
require("lib.gas_balloon").run{ sphere = true, spacing = 0.4 }
