-- title: Piston and container: fluid-structure interaction in one dimension
-- source: York, Sulsky & Schreyer 2000 (fluid-membrane), §4.2, Figs 7-9, Table I
-- look: the piston oscillates about its start; the dashed vertical lines
--   mark the periods of the frequency equation and the crossings fall on them
-- checks: the periods against the paper's MPM 0.0071 and 0.022 ([F] Table
--   I), each to half its last printed digit; beside them the theory, 0.00709
--   (m = 0.1) and 0.02234 (m = 1.0) from [F] eq 27 (ours recomputed)
-- assumed: one cell of 1 high (A = 1), cells of 1 along the 20-long fluid
--   (4 points per cell), the spring a 2-long uniaxial membrane of 3 points
--   that also resists compression, its points m/100 each as in [F]; the
--   piston starts at 0.1; dt = 0.5 dt_c (not given)
-- visual: periods=1
-- thumb: fig9_m0.1.png
local out = lamina.param("out", "out/gas_piston_container")
local periods = lamina.param("periods", 4)
local L, A, K, rho, beta, h = 20, 1, 100, 1e-4, 1.58e6, 1
local c = math.sqrt(beta / rho)

local function theory(m)
  local function F(w) return w * w * m - K - rho * w * c * A / math.tan(w * L / c) end
  local a, b = 1e-6, math.pi * c / L * (1 - 1e-12)
  for _ = 1, 200 do
    local mid = 0.5 * (a + b)
    if F(a) * F(mid) <= 0 then b = mid else a = mid end
  end
  return 2 * math.pi / (0.5 * (a + b))
end

local report, hashes = {}, {}
for _, m in ipairs{0.1, 1.0} do
  local Ls, n = 2, 3
  local sim = lamina.sim{ basis = "linear", domain = {0, 0, L + Ls, 1}, cell = h, dt = 0.5 * h / c,
                          boundary = { left = "fixed", right = "fixed",
                                       bottom = "symmetry", top = "symmetry" } }
  local fluid = lamina.linear_fluid{ rho = rho, beta = beta }
  sim:body{ material = fluid, region = lamina.rect{ x0 = 0, y0 = 0, x1 = L, y1 = 1 }, ppc = 4 }
  local spring = lamina.membrane{ rho = m / (100 * A * Ls / (n - 1)), E = K * Ls / A, nu = 0,
                                  thickness = A }
  local s = sim:membrane{ force = "point", material = spring, count = n, end_mass = m, name = "spring",
                          curve = lamina.segment{ from = {L + Ls, 0.5}, to = {L, 0.5} },
                          velocity = function(u, i) if i == n then return 0.1, 0 end return 0, 0 end }
  local T = theory(m)
  local rec = sim:record{ every = T / 200, points = { piston = {s, -1} },
                          file = string.format("%s/piston_m%.1f.csv", out, m) }
  sim:run{ t_end = periods * T }
  local t, x = rec:column("t"), rec:column("piston_x")
  local d, up, lo, hi = {}, {}, 0, 0
  for i = 1, #t do
    d[i] = x[i] - L
    lo, hi = math.min(lo, d[i]), math.max(hi, d[i])
    if i > 1 and x[i - 1] < L and x[i] >= L then
      up[#up + 1] = t[i - 1] + (t[i] - t[i - 1]) * (L - x[i - 1]) / (x[i] - x[i - 1])
    end
  end
  local series = { { x = t, y = d, label = string.format("piston, m = %.1f", m) } }
  for k = 1, periods do
    series[#series + 1] = { x = {k * T, k * T}, y = {lo, hi}, dashed = true, color = 8,
                            label = k == 1 and "theoretical periods" or nil }
  end
  lamina.plot{ file = string.format("%s/fig9_m%.1f.png", out, m), csv = true, width = 640, height = 360,
               title = string.format("Fig 9: piston deflection, m = %.1f", m), xlabel = "t",
               ylabel = "deflection", legend = "top right", series = series,
               yrange = { lo - 0.05 * (hi - lo), hi + 0.45 * (hi - lo) } }
  local period = #up >= 2 and (up[#up] - up[1]) / (#up - 1) or -1
  print(string.format("m = %.1f: period %.6f, theory %.6f", m, period, T))
  -- [F] Table I: its MPM periods (0.0071, 0.022 s), to half their last
  -- printed digit (issue 32 item 3; it was 2 % of T, ours); its theory
  -- (0.00709, 0.02234 s) is ours too, T from the same frequency
  -- equation (eq 27), printed beside as the reference
  local table_I_mpm = { [0.1] = { 0.0071, 0.00005 }, [1.0] = { 0.022, 0.0005 } }
  local table_I = { [0.1] = 0.00709, [1.0] = 0.02234 }
  report[string.format("period_m%.1f", m)] = { period, paper = table_I_mpm[m][1], ref = T,
    tol = table_I_mpm[m][2],
    unit = string.format("s ([F] Table I's MPM period; tol: half its last digit; its theory %.5f)", table_I[m]) }
  hashes[#hashes + 1] = sim:hash()
end
-- both masses' runs (assets/lua/hashes.lua)
report.state_hash = require("hashes").fold(hashes)
lamina.report(report)
