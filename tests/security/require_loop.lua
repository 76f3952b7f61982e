-- expect: 0
-- A loop of require calls (a copied example named like the module it
-- requires finds itself first) was "C stack overflow" after 200 nested
-- loads; now the second require of a module still loading says so, naming
-- it. A module that fails is not left marked: requiring it again fails the
-- same way, not as a loop.
local ok, err = pcall(require, "mods.loop_a")
assert(not ok and err:find("module 'mods.loop_a' requires itself while it loads", 1, true), err)
for _ = 1, 2 do
  ok, err = pcall(require, "mods.fails")
  assert(not ok and err:find("fails on purpose", 1, true) and not err:find("itself"), err)
end
-- and the loop's modules can be tried again with the same answer
ok, err = pcall(require, "mods.loop_b")
assert(not ok and err:find("requires itself", 1, true), err)
print("ok")
