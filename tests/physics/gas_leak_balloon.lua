-- Issue 30 item 5: membrane:escaped tells a leak from a skin-grazer, and
-- the soft balloon keeps its gas. The balloon of assets/lua/balloon.lua made
-- soft (p 3, E t 20: it flattens by a third on landing) dropped 0.25 onto
-- the fixed floor, 4 particles a cell, cell 0.05, default basis and force,
-- run 2 s (it lands at 0.3 s, bounces and settles).
-- (a) Points half a cell apart: no gas particle more than a quarter cell
--     outside at any sample (every 0.05 s), the deepest outside below a
--     quarter cell.
-- (b) Points a cell apart (what docs/api.md suggested for a taut sheet):
--     gas crosses the skin from t = 0.84 (the run warns once,
--     tests/bad/gas_leak_warning.lua); membrane:escaped's count and deepest
--     distance are checked against an independent count here: the
--     particles outside the points' polygon (even-odd rule) and their
--     distance to its nearest chord (35 samples agree exactly). Measured:
--     at worst 4 beyond a quarter cell, the deepest 1.01 cells, 10 grazers
--     (half a cell apart: none beyond, the deepest 0.006 cells, 2 grazers;
--     the area dips by 36 % on landing either way).
local balloon = require("balloon")
local h = 0.05

-- outside the polygon, and the distance to its nearest chord
local function reference(mem, gas)
  local m, g = mem:particles(), gas:particles()
  local beyond, within, deepest = 0, 0, 0
  for k = 1, g.n do
    local px, py, inside = g.x[k], g.y[k], false
    local d = math.huge
    for i = 1, m.n do
      local j = i == 1 and m.n or i - 1
      local xa, ya, xb, yb = m.x[j], m.y[j], m.x[i], m.y[i]
      if (ya > py) ~= (yb > py) and px < xa + (py - ya) * (xb - xa) / (yb - ya) then
        inside = not inside
      end
      local ex, ey = xb - xa, yb - ya
      local u = math.max(0, math.min(1, ((px - xa) * ex + (py - ya) * ey) / (ex * ex + ey * ey)))
      d = math.min(d, math.sqrt((px - xa - u * ex)^2 + (py - ya - u * ey)^2))
    end
    if not inside then
      deepest = math.max(deepest, d)
      if d > h / 4 then beyond = beyond + 1 else within = within + 1 end
    end
  end
  return beyond, deepest, within
end

for _, spacing in ipairs{0.5, 1} do
  local sim, gas, mem = balloon.setup{ p = 3, E = 2e3, spacing = spacing }
  local A0 = mem:enclosed_area()
  local worst, deepest, grazers, amin, checked = 0, 0, 0, 0, 0
  sim:every(0.05, function()
    local n, d, g = mem:escaped(gas)
    worst, deepest, grazers = math.max(worst, n), math.max(deepest, d), math.max(grazers, g)
    amin = math.min(amin, mem:enclosed_area() / A0 - 1)
    if spacing == 1 and (n > 0 or g > 0) then   -- against the reference
      local rn, rd, rg = reference(mem, gas)
      assert(rn == n and rg == g and math.abs(rd - d) <= 1e-12 * (1 + d),
             string.format("escaped %d %.6g %d, reference %d %.6g %d", n, d, g, rn, rd, rg))
      checked = checked + 1
    end
  end)
  sim:run{ t_end = 2 }
  print(string.format("points %.1f cells apart: at worst %d gas particles beyond a quarter cell, "
    .. "the deepest outside %.3f cells, %d grazers; area at least %+.1f %%; %d samples checked "
    .. "against the reference", spacing, worst, deepest / h, grazers, 100 * amin, checked))
  if spacing == 0.5 then
    assert(worst == 0 and deepest <= h / 4, "the soft balloon's gas crossed its skin")
  else
    assert(worst > 0 and deepest > h / 4 and checked > 5, "the leak was not seen")
  end
end
