-- Issue 30 item 4, point by point: EXPECTED FAILURE (tests/CMakeLists.txt
-- WILL_FAIL). The sphere and circle of assets/lua/gas_spacing.lua at 0.2,
-- 0.4 and 0.8 cells: each point's time-averaged stress within 2 % of the
-- closed form (every point, the ends too). The means hold at every spacing
-- (spacing_sphere.lua, spacing_circle.lua); single points do not.
-- Measured (2026-12-03; meridional, the end points / the worst of the rest):
--   sphere 0.198 cells: poles -392 %, worst 282 % (hoop 392 %)
--   sphere 0.393: poles -304 %, worst 64 %;  0.785: poles -11 %, worst 6.6 % (hoop 15 %)
--   circle 0.196: ends -42 %, worst 33 %;  0.393: ends -29 %, worst 10 %;  0.785: 0.4 %
-- Why (docs/robustness.md "Point spacing"): with points under half a cell
-- apart a tension pattern one cell long sends no force to any node (the
-- basis' transform vanishes there), so the gas's particle noise drives it
-- with nothing to restore it: at 0.2 cells started in equilibrium the
-- worst point drifts 19 % by t = 0.01, 106 % by 0.05, 280 % by 0.2. A
-- point's stress under half a cell is not a result; the mean over the
-- surface is.
local run = require("gas_spacing").run

local worst = {}
for _, shape in ipairs{"sphere", "circle"} do
  for _, sp in ipairs{0.2, 0.4, 0.8} do
    local r = run{ shape = shape, spacing = sp }
    local w = 0
    for k = 1, r.n do
      w = math.max(w, math.abs(r.pm[k] / r.ref - 1))
      if shape == "sphere" then w = math.max(w, math.abs(r.ph[k] / r.ref - 1)) end
    end
    print(string.format("%s %.3f cells: ends %+.1f %%, worst point %.1f %%", shape, r.ds,
                        100 * (r.pm[1] / r.ref - 1), 100 * w))
    worst[#worst + 1] = { shape, sp, w }
  end
end
for _, c in ipairs(worst) do
  assert(c[3] < 0.02, string.format("%s at %.1f cells: a point's stress %.1f %% off (limit 2 %%)",
                                    c[1], c[2], 100 * c[3]))
end
