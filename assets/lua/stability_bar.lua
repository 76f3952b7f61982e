-- stability_bar.lua - the one-dimensional bar of [T] §8.5 (input deck:
-- App. A.4.11, Box 14), shared by scripts/paper/stability_bar.lua and
-- tests/physics/stability_bar.lua.
--
-- Box 14: nx = 6, ny = 2 grid lines on x in [0, 5], y in [0, 1] (cells
-- 1 x 1, one row), five material points one per cell at y = 0.5, density
-- 1, E = 1e6, nu = 0, zero stress, the middle point given vx = 1e-8, walls
-- wl = wr = 0, wb = wt = 1, tmax 0.03, dt 0.001 (= h/c, varied).
-- lamina: a string (lamina.membrane, law "uniaxial", thickness 1, so each
-- point has mass and volume 1) of five points 1 apart along y = 0.5 — a
-- bar carrying only its axial stress E eps_x, which is what the 1-D
-- analysis of [T] §8.3-8.4 assumes; the string's placement puts the points
-- exactly where the deck does (an elastic body's seeding would only give
-- cell centres). Walls: left/right "free" (wl = wr = 0: the bar's ends are
-- free), bottom/top "symmetry" (rollers): in a one-row grid every node is
-- on those walls, so v_y = 0 everywhere and the motion is one-dimensional
-- (fixed walls would hold every node).
local M = {}

M.E, M.rho, M.h = 1e6, 1, 1
M.dtc = M.h / math.sqrt(M.E / M.rho)   -- the CFL step h / c = 0.001
-- first point: the cell centre, or Box 14's x = 0.0001 (the cells' left sides)
M.start = { centres = 0.5, sides = 0.0001 }

-- One run: case "centres" | "sides", dt = factor * dtc, n points (default
-- Box 14's 5; a longer bar, one point a cell, on a grid n cells long, the
-- middle point perturbed). Returns the record (energy every step), whether
-- the run went to t_end, the sim and the bar (its membrane body).
function M.run(case, factor, scheme, t_end, n)
  n = n or 5
  local sim = lamina.sim{ domain = {0, 0, n * M.h, 1}, cell = M.h, dt = factor * M.dtc,
                          -- (courant: past every step tried, USL's factor 0.7 included)
                          scheme = scheme, courant = 5, basis = "linear",
                          boundary = { left = "free", right = "free",
                                       bottom = "symmetry", top = "symmetry" } }
  local bar = lamina.membrane{ rho = M.rho, E = M.E, nu = 0, thickness = 1, law = "uniaxial" }
  local x0 = M.start[case]
  local mid = (n + 1) // 2
  local body = sim:membrane{ material = bar, count = n, name = "bar", force = "point",
                curve = lamina.segment{ from = {x0, 0.5}, to = {x0 + (n - 1) * M.h, 0.5} },
                velocity = function(_, i) if i == mid then return 1e-8, 0 end return 0, 0 end }
  local rec = sim:record{ energy = true }
  local ok = pcall(sim.run, sim, { t_end = t_end })
  return rec, ok, sim, body
end

-- Unstable: the energy grows without bound — the run fails (a point
-- inverts or leaves: the amplitude reached a cell) or the total energy
-- exceeds GROWTH times its start within t_end. Stable runs were measured to
-- stay below 300x (a bounded exchange between the particles' energy and
-- the grid's at large dt) and unstable ones pass 1e5x within 0.03 s.
M.GROWTH = 1e4
function M.growth(rec)
  local e = rec:column("total")
  local mx = 0
  for i = 1, #e do mx = math.max(mx, e[i] / e[1]) end
  return mx
end

-- Runs every factor of the list; returns the table of rows {factor, growth,
-- ok, unstable, rec} and the first unstable factor (nil: none).
function M.scan(case, scheme, factors, t_end)
  local rows, first = {}, nil
  for _, f in ipairs(factors) do
    local rec, ok = M.run(case, f, scheme, t_end)
    local g = M.growth(rec)
    local unstable = not ok or g > M.GROWTH
    rows[#rows + 1] = { factor = f, growth = g, ok = ok, unstable = unstable, rec = rec }
    if unstable and not first then first = f end
  end
  return rows, first
end

-- The stability limit itself: bisects [lo, hi] (lo stable, hi not) k
-- times for a bar of n points; returns the last stable and first unstable
-- factors (an interval (hi - lo) / 2^k wide).
function M.limit(case, scheme, n, lo, hi, k, t_end)
  for _ = 1, k do
    local f = 0.5 * (lo + hi)
    local rec, ok = M.run(case, f, scheme, t_end, n)
    if ok and M.growth(rec) <= M.GROWTH then lo = f else hi = f end
  end
  return lo, hi
end

return M
