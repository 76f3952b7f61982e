-- a module that fails as it loads (tests/security/require_loop.lua)
error("fails on purpose")
