-- Issue 30 item 4: results do not depend on the membrane's point spacing.
-- The axisymmetric gas-filled sphere of assets/lua/gas_spacing.lua (radius
-- 0.3, p 200, cell 0.05, unstressed start; the closed form sigma t = p r / 2
-- derived in its head) on the defaults (quadratic B-spline, segment
-- forces) with points 0.2, 0.4 and 0.8 cells apart: the time-averaged mean
-- meridional stress (mem:hoop_stress(), over the surface) and mean hoop
-- stress (by ring area) each within 2 % of p r / 2 t with p and r of the
-- same run, within 2 % of each other, and each within 2 % of its value at
-- the other spacings.
-- Measured (2026-12-03, meridional / hoop): 0.198 cells -0.83 % / -0.64 %,
-- 0.393: -1.17 % / -0.79 %, 0.785: -0.91 % / -0.51 %. Before, hoop_stress()
-- counted the points alike, and the points within a cell of the axis (a
-- few per cent of the surface; the poles -390 %, see
-- tests/physics/spacing_points.lua) made the meridional mean -12.1 % at 0.2
-- cells, -14.6 % at 0.4 and -2.3 % at 0.8 (a count of the hoop stresses
-- -15.8 %, -17.4 %, -1.4 %): the issue's "-15 %" (docs/robustness.md
-- "Point spacing").
local run = require("gas_spacing").run

local res = {}
for _, sp in ipairs{0.2, 0.4, 0.8} do
  local r = run{ shape = "sphere", spacing = sp }
  local em, eh = r.mer / r.ref - 1, r.hoop / r.ref - 1
  print(string.format("spacing %.3f cells (%d points): meridional %+.2f %%, hoop %+.2f %% of p r / 2 " ..
                      "(p r / 2 = %.4f); gas out %d", r.ds, r.n, 100 * em, 100 * eh, r.ref, r.escaped))
  assert(math.abs(em) < 0.02, string.format("%.1f cells: meridional %+.2f %% (limit 2 %%)", sp, 100 * em))
  assert(math.abs(eh) < 0.02, string.format("%.1f cells: hoop %+.2f %% (limit 2 %%)", sp, 100 * eh))
  assert(math.abs(em - eh) < 0.02, string.format("%.1f cells: meridional and hoop %.2f %% apart", sp,
                                                 100 * (em - eh)))
  assert(r.escaped == 0, "gas escaped")
  res[#res + 1] = { em, eh }
end
for i = 1, #res do
  for j = i + 1, #res do
    for c = 1, 2 do
      assert(math.abs(res[i][c] - res[j][c]) < 0.02, "the stresses depend on the spacing")
    end
  end
end
