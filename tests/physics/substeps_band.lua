-- Issue 36 item 1: the sub-steps sweep only the nodes near the membranes
-- (src/mpm/subcycle_band.c). Every other node takes, once a step, the same
-- k-fold sums the whole-grid sweep gave it, so the state must be the same
-- bits: the hashes below were computed with the whole-grid sub-steps (main
-- c467cff, before subcycle_band.c) and are asserted here, one thread and
-- two. The cases cover what the band must get right:
-- 1. the gas-filled quarter circle (tests/physics/substeps.lua's, cell 0.1,
--    symmetry walls left and bottom, fixed right and top: the membrane's
--    stencils reach the ghost nodes), MUSL with 4 sub-steps (the slow
--    group's consistent re-map reads A two nodes beyond the membranes'
--    stencils) and USL with 10;
-- 2. the same circle on a finer grid (cell 0.04, MUSL, 6 sub-steps), where
--    the band is a small part of the grid;
-- 3. a segment membrane (the walled string of assets/lua/string_modes.lua,
--    4 sub-steps) alone, no gas: the nodes beyond it carry no mass;
-- 4. Box 9's dog-bone at cell 0.05 as docs/performance.md runs it (USL,
--    the gas at 16 x 3.5e-5, "auto" sub-steps) to t = 0.05, one thread and
--    two;
-- 5. a membrane arc falling freely in strong gravity with 6 sub-steps (USL)
--    of a long step, alone: it crosses more than a cell a step, so the band made
--    at the step's start no longer holds its stencils within the step and
--    must grow (the nodes it takes in brought to the sub-step by the same
--    sums).
local want = {
  circle_musl4 = "83d66ee7d8a61913",
  circle_usl10 = "51daccb4f7f49182",
  fine_musl6 = "2f300df5f4c98ff2",
  string4 = "4c9f9e6f0965fac5",
  dogbone1 = "0af29b143d6a8355",
  dogbone2 = "bf3f82ec4da1935b",
  falling2 = "12d1cd72add95ac9",
}
local got = {}

local p0, r, t, E, nu = 1000, 0.5, 0.1, 1e6, 0.3
local function circle(k, scheme, cell, t_end)
  local sim = lamina.sim{ domain = {0, 0, 1, 1}, cell = cell, dt = 0.5e-4 * k * (scheme == "usl" and 0.6 or 1)
                            * cell / 0.1, scheme = scheme, substeps = k, mass = "lumped",
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
got.circle_musl4 = circle(4, "musl", 0.1, 0.05)
got.circle_usl10 = circle(10, "usl", 0.1, 0.05)
got.fine_musl6 = circle(6, "musl", 0.04, 0.01)

do   -- 3. the walled string, segment forces
  local h = 1 / 32
  local sim = lamina.sim{ basis = "bspline2", dt = 4 * 0.4 * h / 100, cell = h, substeps = 4,
                          domain = {0, 0, 1, 1},
                          boundary = { left = "fixed", right = "fixed", top = "free", bottom = "free" } }
  local mat = lamina.membrane{ rho = 1, E = 1e4, nu = 0, thickness = 0.01, law = "uniaxial" }
  sim:membrane{ material = mat, initial_strain = 0.05, spacing = 0.5 * h,
                curve = lamina.segment{ from = {0, 0.5 + 0.3 * h}, to = {1, 0.5 + 0.3 * h} },
                velocity = function(u) return 0, 0.01 * math.sin(math.pi * u) end }
  sim:run{ t_end = 0.05 }
  got.string4 = sim:hash()
end

local b = require("dogbone_box9")
local function dogbone(threads)
  local h, d = 0.05, b.deck
  local sim = lamina.sim{ domain = {0, 0, d.width, d.width}, cell = h, dt = b.dt(h) * 16, courant = 1.05,
                          boundary = { left = "symmetry", bottom = "symmetry", right = "symmetry", top = "symmetry" },
                          pic = 0, threads = threads, basis = "bspline2", scheme = "usl", substeps = "auto" }
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

do   -- 5. falling faster than a cell a step: the band grows within the step
  local sim = lamina.sim{ domain = {0, 0, 1, 1}, cell = 0.05, dt = 4e-3, substeps = 6, scheme = "usl",
                          gravity = {0, -5000}, boundary = "free" }
  local skin = lamina.membrane{ rho = 1, E = 1e3, nu = 0, thickness = 0.01, law = "uniaxial" }
  local mem = sim:membrane{ material = skin, count = 20, name = "arc",
                            curve = lamina.arc{ center = {0.5, 0.6}, radius = 0.2, from = 20, to = 160 } }
  local y0 = mem:particles().y[1]
  sim:run{ t_end = 0.012 }
  local fell = (y0 - mem:particles().y[1]) / 0.05
  print(string.format("falling arc: %.2f cells in %d steps", fell, sim.nstep))
  assert(fell > sim.nstep, "the arc did not fall more than a cell a step")
  got.falling2 = sim:hash()
end

local bad = {}
for _, name in ipairs{"circle_musl4", "circle_usl10", "fine_musl6", "string4", "dogbone1", "dogbone2",
                      "falling2"} do
  print(string.format("%-13s %s (pinned %s)", name, got[name], want[name]))
  if got[name] ~= want[name] then bad[#bad + 1] = name end
end
assert(#bad == 0, "state hash changed: " .. table.concat(bad, ", "))
