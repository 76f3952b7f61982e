-- expect: 0
-- Issue 31, item 4: lamina.report with ~30 names in one call crashed the
-- release build (the entries were pushed without luaL_checkstack, past the
-- 20 slots a C function gets). 2000 names, plain and as tables, must be
-- stored; read back through lamina.report's table is not possible in the
-- sandbox, so the run finishing with status 0 is the check.
local t = {}
for i = 1, 2000 do
  t[string.format("value_%04d", i)] = (i % 2 == 0) and i or { i, paper = i + 1, unit = "m" }
end
lamina.report(t)
lamina.report(t)   -- again: every name replaced in place
print("reported 2000 names")
