-- lamina.read_csv (issue 20 item 5): what sim:record wrote reads back equal
-- to the recorder's own columns (to 1e-12 relative: the CSV's digits), in
-- file order, with the row count, so a sweep's histories can be overlaid
-- in one plot; a path outside the output root and a missing file are
-- refused.
local out = "out/read_csv"
local sim = lamina.sim{basis = "linear", dt = 1e-3, domain = {0, 0, 1, 1}, cell = 0.1}
local el = lamina.elastic{rho = 1000, E = 1000, nu = 0.3}
local b = sim:body{material = el, region = lamina.disk{center = {0.5, 0.5}, radius = 0.2},
                   velocity = {0.1, 0.05}}
local rec = sim:record{file = out .. "/h.csv", every = 0.01,
                       values = {x = function() local x = b:com(); return x end,
                                 n = function() return #b end}}
sim:run{t_end = 0.1}
local h, names, n = lamina.read_csv(out .. "/h.csv")
assert(n == #rec:column("t") and n == 11, "rows: " .. tostring(n))
assert(names[1] == "t" and names[2] == "step", "names: " .. table.concat(names, ","))
for _, col in ipairs{"t", "step", "x", "n"} do
  local mine = rec:column(col)
  for i = 1, n do
    assert(math.abs(h[col][i] - mine[i]) <= 1e-12 * math.max(1, math.abs(mine[i])),
           string.format("%s[%d]: read %.17g, recorded %.17g", col, i, h[col][i], mine[i]))
  end
end
print(string.format("read_csv: %d rows of %s read back as recorded", n, table.concat(names, ", ")))
lamina.plot{file = out .. "/overlay.png", width = 320, height = 200, title = "read back",
            xlabel = "t", ylabel = "x", series = {{x = h.t, y = h.x, label = "x"}}}
local ok, err = pcall(lamina.read_csv, "../outside.csv")
assert(not ok and err:find("outside the output root"), err)
ok, err = pcall(lamina.read_csv, out .. "/missing.csv")
assert(not ok and err:find("cannot read"), err)
