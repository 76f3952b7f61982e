-- A 1D elastic bar vibrates at the analytic frequency (issue 2, item 7).
-- Bar of length L = 1 fixed at x = 0 (fixed left wall) and free at x = L,
-- one cell high between symmetry (roller) walls, plane stress with nu = 0,
-- so it is a 1D bar with c = sqrt(E/rho). It starts in its first mode,
-- v(x) = v0 sin(pi x / 2L), so the mean velocity follows cos(omega t) with
-- omega = pi c / (2L): period T = 4L/c = 0.4 for E = 100, rho = 1.
-- The period is measured from the zero crossings of the mean velocity over
-- three periods and must be within 1 % of T.
local L, E, rho, v0 = 1.0, 100, 1, 0.01
local cells = lamina.param("cells", 40)
local h = L / cells
local c = math.sqrt(E / rho)
local T = 4 * L / c
local sim = lamina.sim{ basis = "linear", domain = {0, 0, 1.25, h}, cell = h, dt = 0.2 * h / c,
                        boundary = { left = "fixed", right = "free",
                                     bottom = "symmetry", top = "symmetry" } }
local steel = lamina.elastic{ rho = rho, E = E, nu = 0, plane = "stress" }
local bar = sim:body{ material = steel, ppc = {2, 2},
                      region = lamina.rect{ x0 = 0, y0 = 0, x1 = L, y1 = h },
                      velocity = function(x, y) return v0 * math.sin(math.pi * x / (2 * L)), 0 end }

local crossings, prev_t, prev_v = {}, 0, select(1, bar:velocity())
sim:every(sim.dt, function(s)
  local v = bar:velocity()
  if prev_v > 0 and v <= 0 or prev_v < 0 and v >= 0 then
    -- linear interpolation of the crossing time
    crossings[#crossings + 1] = prev_t + (s.t - prev_t) * prev_v / (prev_v - v)
  end
  prev_t, prev_v = s.t, v
end)
sim:run{ t_end = 3 * T + 0.01 }

assert(#crossings >= 6, "expected at least 6 zero crossings, got " .. #crossings)
local measured = 2 * (crossings[#crossings] - crossings[1]) / (#crossings - 1)
print(string.format("bar: period %.6f, analytic %.6f, error %.3f %% (%d crossings, %d cells)",
                    measured, T, 100 * (measured - T) / T, #crossings, cells))
assert(math.abs(measured - T) / T < 0.01, "period off by more than 1 %")
