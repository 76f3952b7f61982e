-- Issue 30 item 7: a membrane point's mass is that of the material it
-- stands for. initial_strain e0 is a logarithmic strain (docs/physics.md
-- §2: l = ds0 exp(eps_t)), so a point placed ds apart with strain e0
-- stands for ds0 = ds exp(-e0) of unstrained membrane, and weighs
-- rho * thickness * ds * exp(-e0) per unit depth (rho the unstrained
-- density). Exact, for e0 = 0.05, -0.2 and 0 on a segment of length 0.9
-- with 37 points (ds = 0.025): each point's mass and its reported `ds`
-- (the unstrained length), the body's mass, and the point's
-- volume thickness * ds0 * exp(e0) = thickness * ds, the placed length.
local rho, t, L = 2, 0.01, 0.9
for _, e0 in ipairs{0.05, -0.2, 0} do
  local sim = lamina.sim{ domain = {0, 0, 1, 1}, cell = 0.05, dt = 1e-5 }
  local skin = lamina.membrane{ rho = rho, E = 1e4, thickness = t }
  local mem = sim:membrane{ material = skin, spacing = 0.025, initial_strain = e0,
                            curve = lamina.segment{ from = {0.05, 0.5}, to = {0.95, 0.5} } }
  local q = mem:particles()
  local ds = L / (q.n - 1)
  assert(q.n == 37 and math.abs(ds - 0.025) < 1e-15, "37 points 0.025 apart")
  for k = 1, q.n do
    local m = rho * t * ds * math.exp(-e0)
    assert(math.abs(q.mass[k] / m - 1) < 1e-12,
           string.format("e0 %g point %d: mass %.15g, rho t ds exp(-e0) = %.15g", e0, k, q.mass[k], m))
    assert(math.abs(q.ds[k] / (ds * math.exp(-e0)) - 1) < 1e-12, "ds is the unstrained length")
    -- volume thickness * ds0 * exp(e0) = thickness * ds: the placed length
    assert(math.abs(q.mass[k] / q.rho[k] / (t * ds) - 1) < 1e-12, "volume t ds")
  end
  -- every point stands for a whole ds, the two ends of an open curve
  -- included (as the papers' points): the body is rho t (L + ds) exp(-e0)
  local M = rho * t * (L + ds) * math.exp(-e0)
  print(string.format("e0 %5.2f: body mass %.10g = rho t (L + ds) exp(-e0) %.10g "
                      .. "(rho t (L + ds), the docs' old rule: %+.2f %%)",
                      e0, mem:mass(), M, 100 * (rho * t * (L + ds) / M - 1)))
  assert(math.abs(mem:mass() / M - 1) < 1e-12, "body mass")
end
