-- contact_friction_hash.lua - state hashes of a friction pair on a pinned
-- plane with a third body in a release pair (tests/physics/contact_friction.lua's
-- set-up, t = 0.4), for each basis on one and two threads: a change to
-- contact meant to be bit-identical leaves them as they were
-- (docs/performance.md, "Contact's cost"; with contact_cost.lua's hashes).
--   lamina run --quiet scripts/measure/contact_friction_hash.lua
for _, basis in ipairs{"gimp", "linear", "bspline2"} do
for _, nt in ipairs{1, 2} do
  local g, th = 10, math.rad(30)
  local sim = lamina.sim{ domain = {0, 0, 4, 1.5}, cell = 0.1, dt = 2e-4, basis = basis, threads = nt,
                          gravity = {g * math.sin(th), -g * math.cos(th)} }
  local mat = lamina.elastic{ rho = 1, E = 1e4, nu = 0.3, plane = "strain" }
  local plane = sim:body{ material = mat, ppc = 4, name = "plane",
                          region = lamina.rect{ min = {0.2, 0.2}, max = {3.8, 0.6} } }
  plane:pin{ points = "all" }
  local block = sim:body{ material = mat, ppc = 4, name = "block",
                          region = lamina.rect{ min = {0.5, 0.6}, max = {1.0, 0.9} } }
  local third = sim:body{ material = mat, ppc = 4, name = "third", velocity = {-1, 0},
                          region = lamina.rect{ min = {1.6, 0.6}, max = {2.0, 0.9} } }
  sim:contact{ block, plane, law = "friction", mu = 0.3 }
  sim:contact{ third, block, law = "release" }
  sim:run{ t_end = 0.4 }
  print("friction", basis, nt, sim:hash())
end end
