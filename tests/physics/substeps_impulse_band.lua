-- Issue 36 item 1: the impulse sub-steps' cost (docs/performance.md "The
-- impulse sub-steps' cost"). The impulse forms (lamina.sim{multirate}) swept
-- every node in every sub-step and carried the gas's momentum through its
-- consistent mass matrix C on every node; the cheaper step must give the same
-- bits. The hashes below were computed on main d9a2067, before the change,
-- and are asserted here. The cases:
-- 1. the gas-filled quarter circle of tests/physics/substeps.lua started
--    slack, ringing (cell 0.1, symmetry walls left and bottom, fixed right
--    and top: the membrane's stencils reach the ghost nodes), MUSL, 10
--    sub-steps, with every consistent form (impulse, half, held_consistent,
--    split, hybrid) and the lumped impulse, and USL impulse with 10;
-- 2. the same circle on a finer grid (cell 0.04, MUSL impulse, 6 sub-steps),
--    where the membranes' band is a small part of the grid;
-- 3. Box 9's dog-bone at cell 0.05 with the page's scheme (MUSL, point
--    forces, pure FLIP), the gas at 16 x 3.5e-5, "auto" sub-steps, impulse,
--    viscous_limit = 0.25, to t = 0.05, one thread and two;
-- 4. a membrane arc falling freely in strong gravity onto nothing (MUSL
--    impulse, 6 sub-steps): more than a cell a step, so a band made at the
--    step's start would have to grow within the step.
local want = {
  circle_impulse = "d04bab610e0b1bea",
  circle_half = "ff31227a357554e2",
  circle_held_consistent = "e7fe7cd297a9c63b",
  circle_split = "9bafdd0d55fef562",
  circle_hybrid = "e8ecd45ef26f1092",
  circle_impulse_lumped = "8c3b15e0e712e5cb",
  circle_usl_impulse = "b0b5ce5d3e3094c2",
  fine_impulse = "60619f55fd68367f",
  dogbone1 = "d19aa1cbc5d51bd3",
  dogbone2 = "1a83472bb0134ee5",
  falling = "a299b12ab02129c4",
}
local got = {}

local p0, r, t, E, nu = 1000, 0.5, 0.1, 1e6, 0.3
local function circle(k, scheme, cell, t_end, multirate)
  local sim = lamina.sim{ domain = {0, 0, 1, 1}, cell = cell, dt = 0.5e-4 * k * (scheme == "usl" and 0.6 or 1)
                            * cell / 0.1, scheme = scheme, substeps = k, mass = "lumped",
                          multirate = multirate, viscous_limit = 0.25,
                          boundary = { left = "symmetry", bottom = "symmetry", right = "fixed", top = "fixed" } }
  local air = lamina.gas{ rho = 1, p = p0, gamma = 1.4, mu = 0.2 }
  local skin = lamina.membrane{ rho = 0.5, E = E, nu = nu, thickness = t, law = "plane_stress" }
  sim:body{ material = air, ppc = 16, name = "gas", fill = "clipped",
            region = lamina.disk{ center = {0, 0}, radius = r } }
  -- started slack: it rings, so the nodes' values change every sub-step
  sim:membrane{ material = skin, count = math.floor(9.1 / cell), name = "membrane", orient = {0, 0},
                curve = lamina.arc{ center = {0, 0}, radius = r, from = 0, to = 90 } }
  sim:run{ t_end = t_end }
  return sim:hash()
end
for _, form in ipairs{"impulse", "half", "held_consistent", "split", "hybrid", "impulse_lumped"} do
  got["circle_" .. form] = circle(10, "musl", 0.1, 0.05, form)
end
got.circle_usl_impulse = circle(10, "usl", 0.1, 0.05, "impulse")
got.fine_impulse = circle(6, "musl", 0.04, 0.01, "impulse")

local b = require("dogbone_box9")
local function dogbone(threads)
  local h, d = 0.05, b.deck
  local sim = lamina.sim{ domain = {0, 0, d.width, d.width}, cell = h, dt = b.dt(h) * 16, courant = 1.05,
                          boundary = { left = "symmetry", bottom = "symmetry", right = "symmetry", top = "symmetry" },
                          pic = 0, threads = threads, basis = "bspline2", scheme = "musl", substeps = "auto",
                          multirate = "impulse", viscous_limit = 0.25 }
  local air = lamina.gas{ rho = d.rho_gas, e = d.e, gamma = d.gamma, mu = d.mu }
  local skin = lamina.membrane{ rho = d.rho_membrane, E = d.E, nu = d.nu, thickness = d.thickness,
                                law = "plane_stress", one_way = true }
  sim:body{ material = air, ppc = d.nprg, region = b.contains, name = "gas" }
  sim:membrane{ material = skin, name = "membrane", count = d.points, normals = "connectivity",
                orient = {0, 0}, force = "point", curve = lamina.polyline(b.polyline()) }
  sim:run{ t_end = 0.05 }
  return sim:hash()
end
got.dogbone1 = dogbone(1)
got.dogbone2 = dogbone(2)

do   -- 4. falling faster than a cell a step
  local sim = lamina.sim{ domain = {0, 0, 1, 1}, cell = 0.05, dt = 4e-3, substeps = 6, scheme = "musl",
                          multirate = "impulse", gravity = {0, -5000}, boundary = "free" }
  local skin = lamina.membrane{ rho = 1, E = 1e3, nu = 0, thickness = 0.01, law = "uniaxial" }
  local mem = sim:membrane{ material = skin, count = 20, name = "arc",
                            curve = lamina.arc{ center = {0.5, 0.6}, radius = 0.2, from = 20, to = 160 } }
  local y0 = mem:particles().y[1]
  sim:run{ t_end = 0.012 }
  local fell = (y0 - mem:particles().y[1]) / 0.05
  print(string.format("falling arc: %.2f cells in %d steps", fell, sim.nstep))
  assert(fell > sim.nstep, "the arc did not fall more than a cell a step")
  got.falling = sim:hash()
end

local bad = {}
for _, name in ipairs{"circle_impulse", "circle_half", "circle_held_consistent", "circle_split", "circle_hybrid",
                      "circle_impulse_lumped", "circle_usl_impulse", "fine_impulse", "dogbone1", "dogbone2",
                      "falling"} do
  print(string.format("%-23s %s (pinned %s)", name, got[name], want[name]))
  if got[name] ~= want[name] then bad[#bad + 1] = name end
end
assert(#bad == 0, "state hash changed: " .. table.concat(bad, ", "))
