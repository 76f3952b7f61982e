-- contact_friction_hash.lua - state hashes of a friction pair on a pinned
-- plane with a third body in a release pair (tests/physics/contact_friction.lua's
-- set-up, t = 0.4), for each basis on one and two threads: a change to
-- contact meant to be bit-identical leaves them as they were
-- (docs/performance.md, "Contact's cost"; with contact_cost.lua's hashes).
--   lamina run --quiet scripts/measure/contact_friction_hash.lua
-- (not bspline2: its pins would hold the block, and the run stops saying so)
for _, basis in ipairs{"gimp", "linear"} do
for _, nt in ipairs{1, 2} do
  local sim = require("contact_scenes").incline{ theta = 30, mu = 0.3, basis = basis, threads = nt,
                                                 third = true }
  sim:run{ t_end = 0.4 }
  print("friction", basis, nt, sim:hash())
end end
