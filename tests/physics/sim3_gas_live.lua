-- A live change to a gas material reaches a 3D run's copy (issue 34 item 1;
-- l_material.c set_everywhere -> la_sim3_set_material): a gas made with mu
-- = 0 and av off, then given mu = 0.5 and av = true before the run, runs
-- bit for bit as the gas made with them (the same state hash), and not as
-- the unchanged one; a change mid-run is deterministic and takes effect.
-- The scene: a gas block driven into the wall (compression: q > 0) with a
-- shear (vy varies with x: the viscous stress 2 mu D > 0).
local function run(mu, av, change, at)
  local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, 1, 1, 0.2}, cell = 0.1, dt = 1e-4 }
  local air = lamina.gas{ rho = 1, p = 1000, av = av, mu = mu }
  sim:body{ material = air, region = lamina.box{ x0 = 0.15, y0 = 0.2, z0 = 0, x1 = 0.55,
                                                 y1 = 0.6, z1 = 0.2 },
            velocity = function(x, y, z) return -20, 10 * x, 0 end }
  local function apply() air.mu, air.av = change.mu, change.av end
  if change and at then sim:at(at, apply) elseif change then apply() end
  sim:run{ t_end = 0.004 }
  return sim:hash(), sim:energy().internal
end
local h_made, e_made = run(0.5, true)
local h_set, e_set = run(0, false, { mu = 0.5, av = true })
local h_none, e_none = run(0, false)
local h_mid1 = run(0, false, { mu = 0.5, av = true }, 0.002)
local h_mid2 = run(0, false, { mu = 0.5, av = true }, 0.002)
print(string.format("made with mu, av: %s (internal %.17g); set before the run: %s (%.17g); "
  .. "unchanged: %s (%.17g); changed at t = 0.002 twice: %s %s", h_made, e_made, h_set, e_set,
  h_none, e_none, h_mid1, h_mid2))
assert(h_set == h_made, "the 3D copy did not take mu and av")
assert(h_none ~= h_made, "mu and av made no difference to this scene")
assert(h_mid1 == h_mid2 and h_mid1 ~= h_made and h_mid1 ~= h_none,
       "a mid-run change is not deterministic or had no effect")
