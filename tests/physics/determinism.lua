-- Determinism: the same script and build give a bit-identical particle state
-- (docs/design.md, "Engine"). Two identical two-disk simulations are stepped side by
-- side and their state hashes compared; a third with one particle velocity
-- different must hash differently (the hash does see the state).
local steps = lamina.param("steps", 300)
-- full = false: the two-disk part only (the leak test runs it under
-- valgrind, where the threaded and per-basis runs below take minutes)
local full = lamina.param("full", true)

local function build(v)
  local sim = lamina.sim{ basis = "linear", domain = {0, 0, 1, 1}, cell = 0.05, dt = 1e-3 }
  local m = lamina.elastic{ rho = 1000, E = 1000, nu = 0.3 }
  sim:body{ material = m, ppc = 4, velocity = {v, v},
            region = lamina.disk{ center = {0.25, 0.25}, radius = 0.2 } }
  sim:body{ material = m, ppc = 4, velocity = {-0.1, -0.1},
            region = lamina.disk{ center = {0.75, 0.75}, radius = 0.2 } }
  return sim
end

local a, b, c = build(0.1), build(0.1), build(0.1 + 1e-12)
a:step(steps); b:step(steps); c:step(steps)
print("hash a", a:hash(), "hash b", b:hash(), "hash c", c:hash())
assert(a:hash() == b:hash(), "two identical runs differ: " .. a:hash() .. " vs " .. b:hash())
assert(a:hash() ~= c:hash(), "a changed initial velocity did not change the hash")
a:frame{ file = "out/determinism/a.png", width = 128, height = 128 }

-- The fused pass (src/mpm/step_fused.c) makes the next step's grid sums in
-- this step's pass when sim:run says another step follows at once, and not
-- before a callback (which may change the run; bodies cannot be added
-- during a run). Callbacks that change dt, gravity and the PIC blend at
-- t = 0.1, and one every step after, must give the same bits as the run
-- stopped at t = 0.1, changed, and run on.
local function change(sim)
  sim.dt = 5e-4
  sim.gravity = {0, -2}
  sim.pic = 0.05
end
local d, e = build(0.1), build(0.1)
local calls = 0
d:at(0.1, change)
d:every(5e-4, function() calls = calls + 1 end)
d:run{ t_end = 0.2 }
e:run{ t_end = 0.1 }
change(e)
e:run{ t_end = 0.2 }
print("callbacks", d:hash(), "split run", e:hash(), "steps", d.nstep, e.nstep, "calls", calls)
assert(d.nstep == e.nstep and calls > 150, "the runs did not step alike")
assert(d:hash() == e:hash(), "callbacks: " .. d:hash() .. " vs the split run " .. e:hash())

if full then
-- Threads (threads.h): the gas-filled dog-bone at cell 0.4 on two threads,
-- twice, must hash the same; and agree with the one-thread run to rounding
-- (only the order of the grid sums differs).
local dog = require("dogbone")
local function dogbone(threads)
  local sim, gas, mem = dog.setup(0.4, { threads = threads })
  sim:run{ t_end = 0.05 }
  return sim, gas
end
local s1, g1 = dogbone(1)
local s2, g2 = dogbone(2)
local s3 = dogbone(2)
print("dog-bone hash, 1 thread", s1:hash(), "2 threads", s2:hash(), s3:hash(), "threads", s2.threads)
assert(s2:hash() == s3:hash(), "two identical two-thread runs differ")
local e1, e2 = s1:energy().total, s2:energy().total
local rel = math.abs(e1 - e2) / e1
print(string.format("1 vs 2 threads: energy %.15g vs %.15g (%.1e), pressure %.12g vs %.12g",
                    e1, e2, rel, g1:pressure(), g2:pressure()))
assert(rel < 1e-9 and math.abs(g1:pressure() - g2:pressure()) < 1e-7 * g1:pressure(),
       "two threads do not reproduce the one-thread run to rounding")

-- Segment forces and pins (membrane_force.c, pin.c): the trampoline on one
-- and on two threads, each twice, hashes the same.
local tramp = require("trampoline")
local function trampoline(threads)
  local sim = tramp.setup{ threads = threads }
  sim:run{ t_end = 0.02 }
  return sim:hash()
end
local t1, t1b, t2, t2b = trampoline(1), trampoline(1), trampoline(2), trampoline(2)
print("trampoline hash, 1 thread", t1, t1b, "2 threads", t2, t2b)
assert(t1 == t1b and t2 == t2b, "trampoline runs differ for the same thread count")

-- Every basis (lamina.sim{basis}): the dog-bone again with the 3 x 3
-- stencils, whose walls fold ghost nodes (grid_walls.c) and whose threads
-- zero wider bands (threads.c): bit-identical for the same thread count,
-- and one thread against two to rounding.
for _, basis in ipairs{ "gimp", "bspline2" } do
  local runs = {}
  for _, threads in ipairs{ 1, 1, 2, 2 } do
    local sim, gas = dog.setup(0.4, { threads = threads, basis = basis })
    sim:run{ t_end = 0.05 }
    runs[#runs + 1] = { sim = sim, gas = gas }
  end
  local h = {}
  for i, r in ipairs(runs) do h[i] = r.sim:hash() end
  print(string.format("dog-bone, basis %s: 1 thread %s %s, 2 threads %s %s", basis,
                      h[1], h[2], h[3], h[4]))
  assert(runs[1].sim.basis == basis, "the basis was not taken")
  assert(h[1] == h[2], basis .. ": two identical one-thread runs differ")
  assert(h[3] == h[4], basis .. ": two identical two-thread runs differ")
  local b1, b2 = runs[1].sim:energy().total, runs[3].sim:energy().total
  local p1, p2 = runs[1].gas:pressure(), runs[3].gas:pressure()
  local r = math.abs(b1 - b2) / b1
  print(string.format("  1 vs 2 threads: energy %.15g vs %.15g (%.1e), pressure %.12g vs %.12g",
                      b1, b2, r, p1, p2))
  assert(r < 1e-9 and math.abs(p1 - p2) < 1e-7 * p1,
         basis .. ": two threads do not reproduce the one-thread run to rounding")
end
end
