-- The engine owns its materials (issue 33 item 1): each sim a material is
-- given to keeps a copy, and a live change (m.E = ...) reaches every one
-- of them through the engine's setter. Three two-disk runs: a and b share
-- the material m, whose E is doubled after their first 50 steps; c has
-- its own material, doubled at the same step. All three must reach the
-- same state to the bit, and differ from d, which never changes (so the
-- change did reach the engines). A material given to two bodies of one
-- sim is one material there: changing it changes both bodies.
local steps = 100

local function build(m)
  local sim = lamina.sim{ basis = "linear", domain = {0, 0, 1, 1}, cell = 0.05, dt = 1e-3 }
  sim:body{ material = m, ppc = 4, velocity = {0.1, 0.1},
            region = lamina.disk{ center = {0.25, 0.25}, radius = 0.2 } }
  sim:body{ material = m, ppc = 4, velocity = {-0.1, -0.1},
            region = lamina.disk{ center = {0.75, 0.75}, radius = 0.2 } }
  return sim
end

local m = lamina.elastic{ rho = 1000, E = 1000, nu = 0.3 }
local own = lamina.elastic{ rho = 1000, E = 1000, nu = 0.3 }
local still = lamina.elastic{ rho = 1000, E = 1000, nu = 0.3 }
local a, b, c, d = build(m), build(m), build(own), build(still)
for _, s in ipairs{a, b, c, d} do s:step(steps // 2) end
m.E = 2000
own.E = 2000
assert(m.E == 2000 and own.E == 2000 and still.E == 1000)
for _, s in ipairs{a, b, c, d} do s:step(steps // 2) end
print("hash a", a:hash(), "b", b:hash(), "c", c:hash(), "d", d:hash())
assert(a:hash() == c:hash(), "sim a did not take the shared material's change")
assert(b:hash() == c:hash(), "sim b did not take the shared material's change")
assert(a:hash() ~= d:hash(), "doubling E did not change the run")

-- a refused change leaves every copy as it was
local ok, err = pcall(function() m.nu = 0.7 end)
assert(not ok and err:find("nu must lie in %(%-1, 0.5%)"), tostring(err))
assert(m.nu == 0.3)
