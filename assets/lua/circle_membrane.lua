-- circle_membrane.lua - the gas-filled circular membrane of the normals
-- paper §8 (Figs 12-13; docs/physics.md V6), shared by its scenarios and tests:
-- quarter symmetry, radius 0.5, 91 membrane points, E = 1e6, nu = 0.3,
-- rho = 0.5, t = 0.1 (plane stress), initially unstressed; gas gamma = 1.4,
-- p0 = 1000, rho = 1, mu = 0.2, 16 ppc; 10 x 10 cells of 0.1; dt = 0.7e-4
-- (Courant 1.04 on the membrane's plane-stress wave speed: the paper's dt,
-- so courant is raised to 1.05); the gas seeded with fill = "clipped" (o.fill
-- overrides; docs/normals.md "Centred elements" says why).
local M = {}

-- o: normals (default "connectivity"), oriented away from the centre.
-- Returns sim, gas, membrane.
function M.setup(o)
  o = o or {}
  local sim = lamina.sim{ domain = {0, 0, 1, 1}, cell = 0.1, dt = 0.7e-4, courant = 1.05,
                          basis = "linear",
                          boundary = { left = "symmetry", bottom = "symmetry",
                                       right = "fixed", top = "fixed" } }
  local air = lamina.gas{ rho = 1, p = 1000, gamma = 1.4, mu = 0.2 }
  local skin = lamina.membrane{ rho = 0.5, E = 1e6, nu = 0.3, thickness = 0.1,
                                law = "plane_stress" }
  local gas = sim:body{ material = air, ppc = 16, name = "gas", fill = o.fill or "clipped",
                        region = lamina.disk{ center = {0, 0}, radius = 0.5 } }
  local mem = sim:membrane{ material = skin, count = 91, name = "membrane", force = "point",
                            normals = o.normals or "connectivity", orient = {0, 0},
                            curve = lamina.arc{ center = {0, 0}, radius = 0.5, from = 0, to = 90 } }
  return sim, gas, mem
end

-- The largest angle (degrees, sign ignored) between a membrane normal and
-- the radial direction, over the points away from the two ends.
function M.worst_normal_error(mem)
  local q = mem:particles()
  local w = 0
  for i = 3, q.n - 2 do
    local c = (q.nx[i] * q.x[i] + q.ny[i] * q.y[i]) / math.sqrt(q.x[i]^2 + q.y[i]^2)
    w = math.max(w, math.deg(math.acos(math.min(1, math.abs(c)))))
  end
  return w
end

-- The same against the connectivity normal of each point (x_{p+1} - x_{p-1}
-- turned 90 degrees, [N] §8): a reference that follows the membrane's own
-- shape, wrinkles included, where the radial one assumes a perfect circle.
function M.worst_connectivity_error(mem)
  local q = mem:particles()
  local w = 0
  for i = 3, q.n - 2 do
    local tx, ty = q.x[i + 1] - q.x[i - 1], q.y[i + 1] - q.y[i - 1]
    local c = (q.ny[i] * tx - q.nx[i] * ty) / math.sqrt(tx * tx + ty * ty)
    w = math.max(w, math.deg(math.acos(math.min(1, math.abs(c)))))
  end
  return w
end

-- The quarter circle's drift from its start, sampled every millisecond of
-- the run that follows: the largest |r / r0 - 1| at 0, 45 and 90 degrees and
-- the largest |hoop / hoop at the start - 1|. Returns a function giving both.
function M.watch_drift(sim, mem, r0)
  local s_start, wr, ws = mem:hoop_stress(), 0, 0
  sim:every(1e-3, function()
    for _, deg in ipairs{0, 45, 90} do wr = math.max(wr, math.abs(mem:radius_at(deg) / r0 - 1)) end
    ws = math.max(ws, math.abs(mem:hoop_stress() / s_start - 1))
  end)
  return function() return wr, ws end
end

-- An energy record's least-squares slope over the run times its length (its
-- trend) and its largest |value|: ts the times, es the relative changes.
function M.energy_trend(ts, es)
  local n, mt, me = #ts, 0, 0
  for i = 1, n do mt, me = mt + ts[i] / n, me + es[i] / n end
  local sxy, sxx, worst = 0, 0, 0
  for i = 1, n do
    sxy = sxy + (ts[i] - mt) * (es[i] - me)
    sxx = sxx + (ts[i] - mt) ^ 2
    worst = math.max(worst, math.abs(es[i]))
  end
  return sxy / sxx * (ts[n] - ts[1]), worst
end

-- sigma t / (p r) at the present state: the hoop stress against Laplace's
-- law, r the mean of the radii at 0 and 90 degrees, p the enclosed gas's.
function M.laplace_ratio(mem, gas, t)
  return mem:hoop_stress() * t / (gas:pressure(mem) * (mem:radius_at(0) + mem:radius_at(90)) / 2)
end

return M
