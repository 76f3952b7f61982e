-- the other half of the loop (tests/security/require_loop.lua)
return require("mods.loop_a")
