-- a module that requires one that requires it back (tests/security/require_loop.lua)
return require("mods.loop_b")
