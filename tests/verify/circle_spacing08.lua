-- Verification case (issue 30 item 1): the gas-filled circle (sigma t = p r), membrane
-- points 0.8 cells apart. Exact answer derived in lib/gas_balloon.lua.
-- verify: membrane
require("lib.gas_balloon").run{ sphere = false, spacing = 0.8 }
