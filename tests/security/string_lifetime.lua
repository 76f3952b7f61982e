-- expect: 0
-- Issue 18, item 1: every string taken from a Lua table stays valid while
-- used. sim:frame(setmetatable({}, {__index = function() return "x".."y" end}))
-- read strings after they were popped (ASan: heap-use-after-free in
-- lr_format_of). Argument tables are now read raw: the metatable is not
-- consulted, so `file` is missing (the sanitizer pass runs this test).
local sim = lamina.sim{ dt = 1e-3 }
local el = lamina.elastic{ rho = 1000, E = 1000, nu = 0.3 }
sim:body{ material = el, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 } }
local calls = 0
local tricky = setmetatable({}, { __index = function(_, k)
  calls = calls + 1
  collectgarbage()
  return "out/security/" .. "x" .. k .. ".png"
end })
local ok, err = pcall(sim.frame, sim, tricky)
assert(not ok and err:find("'file' is required"), tostring(err))
ok, err = pcall(lamina.plot, tricky)
assert(not ok and err:find("'file' is required"), tostring(err))
ok, err = pcall(sim.record, sim, setmetatable({}, { __index = function() return 1e-300 end }))
assert(ok, tostring(err))
-- a panel table and a series table with such a metatable: ignored too
ok, err = pcall(sim.frame, sim, { file = "out/security/lifetime.png", width = 32, height = 32,
                                  panels = { tricky } })
assert(ok, tostring(err))
assert(calls == 0, "an __index function ran inside a binding")
print("strings held")
