-- expect: 0
-- Issue 31, item 4: sim:record{average = 1e-18} overflowed the heap in the
-- running mean (t - 1e-18 == t, so the window's start ran past the row and
-- off the end of the rows) and the CSV was lost. The window now always
-- holds the row itself: with a window shorter than a step the running mean
-- is the value itself, checked here against the column.
local sim = lamina.sim{ dt = 1e-3, domain = {0, 0, 1, 1}, cell = 0.1 }
local n = 0
local rec = sim:record{ file = "out/security/average_tiny.csv", average = 1e-18,
                        values = { count = function() n = n + 1; return n * n end } }
sim:run{ t_end = 0.05 }
rec:write()
local v, m = rec:column("count"), rec:column("count_avg")
assert(#v > 40 and #m == #v, #v .. " rows, " .. #m .. " means")
for i = 1, #v do assert(m[i] == v[i], string.format("row %d: mean %g, value %g", i, m[i], v[i])) end
-- NaN and infinite windows are refused by name
for _, bad in ipairs{ 0 / 0, math.huge, -1 } do
  local ok, err = pcall(sim.record, sim, { average = bad, energy = true })
  assert(not ok and err:find("average must be a finite time >= 0", 1, true), tostring(err))
end
print(#v .. " rows, every running mean equal to its value")
