-- expect: 2
-- stderr: record_header_injection\.lua:12: sim:record: column name '\\10echo INJECTED > pwned\\10#' may hold only letters, digits, spaces and _ \. - \( \) \[ \] / \(it heads a CSV column; '\\10' is not allowed\)
-- Issue 18: sim:record wrote column names unescaped, so a name with
-- newlines planted shell lines in the CSV. Issue 31: column names hold only
-- letters, digits, space and _ . - ( ) [ ] /; plot labels no control character.
local sim = lamina.sim{ dt = 1e-3 }
local ok, err = pcall(sim.record, sim, { values = { ["a,b"] = function() return 1 end } })
assert(not ok and err:find("may hold only letters", 1, true), tostring(err))
ok, err = pcall(lamina.plot, { file = "out/security/h.png", csv = true,
                               series = { { x = {0, 1}, y = {0, 1}, label = "a\rb" } } })
assert(not ok and err:find("series label 'a\\13b' contains a control character"), tostring(err))
sim:record{ file = "out/security/h.csv",
            values = { ["\necho INJECTED > pwned\n#"] = function() return 1 end } }
