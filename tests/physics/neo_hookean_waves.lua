-- Issue 33 item 3: waves on a neo-Hookean strip (law = "neo_hookean"),
-- against the periods of its closed-form tangent and tension.
--
-- A strip of E = 3e4 (mu = E/3), rho 1, thickness t, stretched to lambda0
-- between two pins 1 apart (initial_strain = ln lambda0, so its unstrained
-- length is L0 = 1 / lambda0), segment forces on the default quadratic
-- B-spline, cell 1/32, points half a cell apart, dt = 0.3 h / sqrt(E/rho).
-- Started in mode 1, v = 1e-3 c sin(pi u) along or across it (strains of
-- 1e-3: linear), run 10 periods; the period from the upward zero
-- crossings of the middle point's displacement. Exact (the law's file
-- derives P = mu (lambda - 1/lambda^2), the nominal stress):
-- - along (longitudinal), the wave equation in the unstrained coordinate,
--   rho u_tt = P'(lambda0) u_XX with P' = mu (1 + 2/lambda0^3):
--   f = 1/(2 L0) sqrt(P'(lambda0)/rho). At lambda0 = 1, P' = 3 mu = E, so
--   f = wave_speed/(2 L0) with the material's wave_speed sqrt(E/rho): the
--   small-strain limit E = 3 mu and the Courant check's speed;
-- - across (transverse), a string of tension T = t P(lambda0) per unit
--   depth and mass rho t / lambda0 per length: f = 1/2 sqrt(T lambda0 /
--   (rho t)) = 1/2 sqrt(mu (lambda0^2 - 1/lambda0) / rho).
-- Checked within 1 %; and the total energy (the law's strain energy plus
-- the kinetic) within 1 % of the largest kinetic energy at cell 1/64.
-- Measured (2026-12-05), cell 1/32: along -0.244 / -0.244 / -0.242 % at
-- lambda0 = 1 / 1.5 / 2, across -0.246 / -0.244 % at 1.5 / 2 (the linear
-- law along at 1.5: -0.243 %: the discretisation's; 1/64: -0.059 %);
-- energy 1.6 % of the largest KE at 1/32 (the linear law 1.8 %), at 1/64
-- 0.81 % along, 0.54 % across at lambda0 = 1.5.
local E, rho, t = 3e4, 1, 0.01
local mu = E / 3

local function run(lam0, dir, n)
  local h = 1 / n
  local sim = lamina.sim{ cell = h, dt = 0.3 * h / math.sqrt(E / rho), domain = {0, 0, 1.4, 1},
                          boundary = "free" }
  local rubber = lamina.membrane{ rho = rho, E = E, thickness = t, law = "neo_hookean" }
  local L0 = 1 / lam0
  local f
  if dir == "along" then
    f = 1 / (2 * L0) * math.sqrt(mu * (1 + 2 * lam0 ^ -3) / rho)
    if lam0 == 1 then f = rubber.wave_speed / (2 * L0) end
  else
    f = 0.5 * math.sqrt(mu * (lam0 ^ 2 - 1 / lam0) / rho)
  end
  local amp = 1e-3 * math.sqrt(E / rho)
  local x0, y0 = 0.2, 0.5 + 0.3 * h    -- off the node lines
  local s = sim:membrane{ material = rubber, initial_strain = math.log(lam0), spacing = 0.5 * h,
    curve = lamina.segment{ from = {x0, y0}, to = {x0 + 1, y0} },
    velocity = function(u)
      local v = amp * math.sin(math.pi * u)
      if dir == "along" then return v, 0 end
      return 0, v
    end }
  s:pin{ points = {1} }
  s:pin{ points = {#s} }
  local P = s:particles()
  local mid = (#P.x + 1) // 2
  local function disp(Q) return dir == "along" and Q.x[mid] - P.x[mid] or Q.y[mid] - P.y[mid] end
  local per = 1 / f
  local ts, ds, ke, tot = {}, {}, {}, {}
  sim:every(per / 200, function()
    ts[#ts + 1], ds[#ds + 1] = sim.t, disp(s:particles())
    local e = sim:energy()
    ke[#ke + 1], tot[#tot + 1] = e.kinetic, e.total
  end)
  sim:run{ t_end = 10 * per }
  local up = {}
  for i = 2, #ts do
    if ds[i - 1] < 0 and ds[i] >= 0 then
      up[#up + 1] = ts[i - 1] + (ts[i] - ts[i - 1]) * (-ds[i - 1]) / (ds[i] - ds[i - 1])
    end
  end
  assert(#up >= 5, "the strip did not ring: " .. #up .. " upward crossings")
  local err = per / ((up[#up] - up[1]) / (#up - 1)) - 1
  local kmax, de = 0, 0
  for i = 1, #ts do
    kmax = math.max(kmax, ke[i])
    de = math.max(de, math.abs(tot[i] - tot[1]))
  end
  print(string.format("lambda0 %.2f %-6s cell 1/%d: f %.5g, measured %+.3f %%; energy within %.3f %% "
                      .. "of the largest KE", lam0, dir, n, f, 100 * err, 100 * de / kmax))
  return err, de / kmax
end

for _, c in ipairs{ {1, "along"}, {1.5, "along"}, {2, "along"}, {1.5, "across"}, {2, "across"} } do
  local err = run(c[1], c[2], 32)
  assert(math.abs(err) < 0.01, string.format("lambda0 %g %s: period off by %.3f %%", c[1], c[2],
                                             100 * err))
end
for _, dir in ipairs{ "along", "across" } do
  local _, de = run(1.5, dir, 64)
  assert(de < 0.01, string.format("lambda0 1.5 %s: energy changed by %.3f %% of the largest KE",
                                  dir, 100 * de))
end
