-- Used by tests/security/csv_does_not_execute.sh (issue 31 item 2): a record
-- whose column names try every character that would make its CSV header run
-- as shell or Python (each must be refused), then a record and a plot whose
-- CSVs are written with the most hostile names still accepted.
local out = "out/security/csv_exec"
local sim = lamina.sim{ dt = 1e-3, domain = {0, 0, 1, 1}, cell = 0.1 }
local hostile = { "$(touch pwned_sh)", "`touch pwned_sh`", "a;touch pwned_sh", "a|b", "a&b",
                  "a>pwned_sh", "a=1", "import os#", "x\"y", "x'y", "a,b", "a\\b", "a{b}",
                  "__import__('os').system('touch pwned_py')", "a\nb", "a*b", "~", "!a", "a<b" }
for _, name in ipairs(hostile) do
  local ok, err = pcall(sim.record, sim, { values = { [name] = function() return 1 end } })
  assert(not ok and err:find("may hold only letters", 1, true), name .. ": " .. tostring(err))
end
for _, label in ipairs{ "$(touch pwned_sh)", "`touch pwned_sh`", "a\\b", "\"\"\", 1)#" } do
  local ok, err = pcall(lamina.plot, { file = out .. "/p.png", csv = true,
                                       series = { { x = {0, 1}, y = {0, 1}, label = label } } })
  assert(not ok and err:find("may not hold", 1, true), label .. ": " .. tostring(err))
end
-- accepted: the safe set for columns, free text but " $ ` \ for plot labels
local rec = sim:record{ file = out .. "/rec.csv", values = {
  ["rm -rf (x) [y] / z"] = function() return 1 end, ["import os"] = function() return 2 end,
  ["print(1)"] = function() return 3 end } }
sim:run{ t_end = 2e-3 }
rec:write()
lamina.plot{ file = out .. "/p.png", csv = true, series = {
  { x = {0, 1}, y = {0, 1}, label = "x; touch pwned_sh; print(1); '" },
  { x = {0, 1}, y = {0, 1}, label = "__import__('os').system('touch pwned_py'); print(2)#" },
  { x = {0, 1}, y = {0, 1}, label = "a, b = 1 > pwned_sh & (x) | {y} # ~ !" } } }
