-- contact_cost.lua - issue 14 item 7: what contact costs beside the same run
-- without it (README "Contact", docs/performance.md). Two problems:
--  * two_bar: the two-bar impact of tests/physics/contact_two_bar.lua
--    refined to cell 0.0625 (dt 1.75e-4, 11 520 particles), to t = 0.5;
--  * disks_wire: scripts/paper/contact_disks_wire.lua's set-up (three
--    release pairs, 299 points), to t = 5;
-- each with law = "release" and with the single field, alternating `rounds`
-- times so that the machine's load falls on both alike. Processor time
-- (os.clock: one thread, so the step's own time) after a first step; the
-- ratio per round, and the state hashes so that a change meant to be
-- bit-identical can be checked. `only` = "contact" or "plain" runs that one
-- once (for valgrind), `case` picks the problem, `t_end` shortens it;
-- `basis` and `threads` (1: processor time is then the step's) as lamina.sim's.
--   nice -n 5 lamina run scripts/measure/contact_cost.lua --set case=two_bar
local case = lamina.param("case", "two_bar")
local rounds = lamina.param("rounds", 3)
local only = lamina.param("only", "")
local t_end_p = lamina.param("t_end", 0)
local basis = lamina.param("basis", "linear")
local threads = lamina.param("threads", 1)

local scenes = require("contact_scenes")

local function two_bar(contact)
  return (scenes.two_bar{ cell = 0.0625, basis = basis, threads = threads, release = contact }), 0.5
end

local function disks_wire(contact)
  return (scenes.disks_wire{ centres = { {3.9, 5}, {7.6, 5} }, velocities = { {1.0, 0}, {-1.1, 0} },
                             basis = basis, threads = threads, release = contact }), 5
end

local make = ({ two_bar = two_bar, disks_wire = disks_wire })[case]
assert(make, "case must be two_bar or disks_wire")

local function timed(contact)
  local sim, t_end = make(contact)
  if t_end_p > 0 then t_end = t_end_p end
  sim:step(1)
  local s0 = sim.nstep
  local c0 = os.clock()
  sim:run{ t_end = t_end }
  local t = os.clock() - c0
  return t, sim:hash(), sim.n, sim.nstep - s0
end

local function line(what, t, hash, n, steps)
  print(string.format("%-8s %6d particles %6d steps %8.3f s  %6.2f M particle-steps/s  hash %s",
                      what, n, steps, t, n * steps / t / 1e6, hash))
end

if only ~= "" then
  line(only, timed(only == "contact"))
  return
end
for k = 1, rounds do
  local tc, hc, n, steps = timed(true)
  line("contact", tc, hc, n, steps)
  local tp, hp = timed(false)
  line("plain", tp, hp, n, steps)
  print(string.format("round %d: ratio %.2f", k, tc / tp))
end
