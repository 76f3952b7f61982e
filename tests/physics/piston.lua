-- V5 piston-container ([F] §4.2, Figs 7-9, Table I; docs/physics.md V5): a fluid
-- column of length L = 20 (p = -beta div U, rho = 1e-4, beta = 1.58e6,
-- c = sqrt(beta/rho)) closed by a piston of mass m, held by a spring of
-- constant K = 100; A = 1. The spring is a uniaxial membrane that also
-- resists compression (not one-way); its points weigh m/100 each, as in
-- [F]; it is 2 long (3 points at 1) so that its own mass (2 % of m) does
-- not shift the period much: the frequency equation is for a massless
-- spring. The piston starts with a small velocity.
-- Reference: the first root of [F] eq 27, omega^2 m = K + rho omega c A
-- cot(omega L / c), solved here by bisection: T = 0.00709 (m = 0.1),
-- 0.02234 (m = 1.0) ([F] Table I; the paper's MPM: 0.0071, 0.022).
-- Checks: the measured periods within 2 %.
local L, A, K, rho, beta = 20, 1, 100, 1e-4, 1.58e6
local c = math.sqrt(beta / rho)
local h = 1      -- one cell high, as [F] Fig 8: the piston point drives every node of x = L

local function theory(m)
  local function F(w) return w * w * m - K - rho * w * c * A / math.tan(w * L / c) end
  local a, b = 1e-6, math.pi * c / L * (1 - 1e-12)
  for _ = 1, 200 do
    local mid = 0.5 * (a + b)
    if F(a) * F(mid) <= 0 then b = mid else a = mid end
  end
  return 2 * math.pi / (0.5 * (a + b))
end

local function measure(m)
  local Ls = 2
  local sim = lamina.sim{ basis = "linear", domain = {0, 0, L + Ls, 1}, cell = h, dt = 0.5 * h / c,
                          boundary = { left = "fixed", right = "fixed",
                                       bottom = "symmetry", top = "symmetry" } }
  local fluid = lamina.linear_fluid{ rho = rho, beta = beta }
  sim:body{ material = fluid, region = lamina.rect{ x0 = 0, y0 = 0, x1 = L, y1 = 1 }, ppc = 4 }
  local n, ds = 3, Ls / 2
  local spring = lamina.membrane{ rho = m / (100 * A * ds), E = K * Ls / A, nu = 0,
                                  thickness = A, law = "uniaxial" }
  -- from the wall to the piston: the piston is the heavy last point
  local s = sim:membrane{ force = "point", material = spring, count = n, end_mass = m,
                          curve = lamina.segment{ from = {L + Ls, 0.5}, to = {L, 0.5} },
                          velocity = function(u, i) if i == n then return 0.1, 0 end return 0, 0 end }
  local T = theory(m)
  local rec = sim:record{ every = sim.dt, points = { piston = {s, -1} } }
  sim:run{ t_end = 4 * T }
  local t, x = rec:column("t"), rec:column("piston_x")
  local up = {}
  for i = 2, #t do
    if x[i - 1] < L and x[i] >= L then
      up[#up + 1] = t[i - 1] + (t[i] - t[i - 1]) * (L - x[i - 1]) / (x[i] - x[i - 1])
    end
  end
  assert(#up >= 3, "too few crossings: " .. #up)
  return (up[#up] - up[1]) / (#up - 1), T
end

for _, m in ipairs{0.1, 1.0} do
  local period, T = measure(m)
  print(string.format("V5 piston m = %.1f: period %.6f, frequency equation %.6f (%+.2f %%); "
    .. "paper: %s", m, period, T, 100 * (period - T) / T, m == 0.1 and "0.00709 / MPM 0.0071"
    or "0.02234 / MPM 0.022"))
  assert(math.abs(period - T) / T <= 0.02, "period off by more than 2 %")
end
