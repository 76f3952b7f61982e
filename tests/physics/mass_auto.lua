-- lamina.sim{mass = "auto"}, the default (issue 30 item 2, l_sim.c
-- mass_resolve): "membrane" when a membrane has segment forces, else
-- "lumped". Checked against explicit runs of the same scene (sim:hash()
-- after 100 steps equal to the bit) and by sim.mass:
--  1. a string with segment forces (the default force): as mass = "membrane",
--     and unlike "lumped";
--  2. the same string with point forces (the papers' scheme): as "lumped";
--  3. no membrane: "lumped" (and "membrane" would step the same);
--  4. segment forces with substeps (multi-rate stepping is lumped only) and
--     with transfer = "apic" (l_sim.c says why): "lumped";
--  5. a segment membrane added after a first run: the next run resolves
--     again, to "membrane";
--  6. mass = "auto" may be named.
local function string_sim(o)
  local h = 1 / 16
  local sim = lamina.sim{ domain = {0, 0, 1, 0.5}, cell = h, boundary = "fixed", mass = o.mass,
                          dt = 0.4 * h / (math.sqrt(5e4 / 100) / 0.75) * (o.substeps or 1),
                          substeps = o.substeps, transfer = o.transfer }
  local wire = lamina.membrane{ rho = 100, E = 5e4, nu = 0, thickness = 0.01, law = "uniaxial" }
  if not o.later then
    sim:membrane{ material = wire, count = 33, initial_strain = 0.01, name = "string", force = o.force,
                  curve = function(u) return u, 0.25 + 2e-4 * math.sin(math.pi * u) end }
  end
  return sim, wire
end
local function run(o)
  local sim = string_sim(o)
  sim:step(100)
  return sim:hash(), sim.mass
end

local auto, m_auto = run{}
local memb = run{ mass = "membrane" }
local lump = run{ mass = "lumped" }
print("1. segment: auto " .. auto .. " (" .. m_auto .. "), membrane " .. memb .. ", lumped " .. lump)
assert(m_auto == "membrane" and auto == memb and auto ~= lump, "segment string: auto is not \"membrane\"")

local pauto, pm = run{ force = "point" }
local plump = run{ force = "point", mass = "lumped" }
print("2. point: auto " .. pauto .. " (" .. pm .. "), lumped " .. plump)
assert(pm == "lumped" and pauto == plump, "point-force string: auto is not \"lumped\"")

local sim = lamina.sim{ domain = {0, 0, 1, 1}, cell = 0.05, dt = 5e-5 }
sim:body{ material = lamina.elastic{ rho = 500, E = 1e5, nu = 0.3 }, ppc = 4, velocity = {0, -1},
          region = lamina.disk{ center = {0.5, 0.75}, radius = 0.1 } }
assert(sim.mass == "lumped", "no membrane: sim.mass " .. sim.mass)
print("3. no membrane: " .. sim.mass)

local _, ms = run{ substeps = 2 }
local _, ma = run{ transfer = "apic" }
print("4. substeps: " .. ms .. ", apic: " .. ma)
assert(ms == "lumped" and ma == "lumped", "substeps / apic: auto is not \"lumped\"")

local later, wire = string_sim{ later = true }
later:step(10)
assert(later.mass == "lumped", "before the membrane: " .. later.mass)
later:membrane{ material = wire, count = 33, initial_strain = 0.01, name = "string",
                curve = lamina.segment{ from = {0, 0.25}, to = {1, 0.25} } }
assert(later.mass == "membrane", "after adding it, sim.mass reads " .. later.mass)
later:step(10)
assert(later.mass == "membrane", "after the next run: " .. later.mass)
print("5. added later: lumped, then membrane")

local named = run{ mass = "auto" }
assert(named == auto, "mass = \"auto\" named is not the default")
print("6. named auto: " .. named)
