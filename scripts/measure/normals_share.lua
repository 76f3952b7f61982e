-- normals_share.lua - issue 17 item 3: the isosurface normals' share of a
-- dog-bone step (docs/performance.md). The dog-bone of gas_dogbone_superellipse at cell
-- 0.1, one thread, `steps` steps after a first one (preparation and the
-- workspace's allocation kept apart) with normals "connectivity" (no
-- construction) and "isosurface", alternating `rounds` times so that the
-- machine's load falls on both alike; the share is 1 - connectivity /
-- isosurface per round, on processor time (os.clock: one thread, so it is
-- the step's own time, and other work on the machine disturbs it less than
-- the wall clock). The state hashes after the run are printed so a change
-- that should be bit-identical can be checked. `only` = "isosurface" or
-- "connectivity" runs that one once, for valgrind (instruction counts,
-- allocations), as docs/performance.md does.
--   nice -n 5 lamina run scripts/measure/normals_share.lua --set rounds=5
local h = lamina.param("cell", 0.1)
local steps = lamina.param("steps", 400)
local rounds = lamina.param("rounds", 3)
local only = lamina.param("only", "")
local dog = require("dogbone")

local function timed(method)
  local sim = dog.setup(h, { normals = method, threads = 1 })
  sim:step(1)
  local c0 = os.clock()
  sim:step(steps)
  return os.clock() - c0, sim:hash()
end

if only ~= "" then
  local t, hash = timed(only)
  print(string.format("%s: %d steps %.3f s (hash %s)", only, steps, t, hash))
  return
end
for r = 1, rounds do
  local tc, hc = timed("connectivity")
  local ti, hi = timed("isosurface")
  print(string.format("round %d: connectivity %.3f s, isosurface %.3f s, share %.1f %% " ..
                      "(hashes %s %s)", r, tc, ti, 100 * (1 - tc / ti), hc, hi))
end
