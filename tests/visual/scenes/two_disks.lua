-- title: Two elastic disks (scripts/examples/two_disks.lua, unchanged)
-- source: Sulsky, Chen & Schreyer 1994; lamina's first example (issue 2)
-- look: the example itself, stopped while the disks are in contact
-- checks: the state hash after the run, so that a failing comparison says
--   whether the simulation or only the drawing changed
-- visual: t_end=1.3
--
-- Runs the example through dofile, catching the simulation it makes, so the
-- visual test follows the example as it is, with no copy of its set-up.
local here = SCRIPT:match("^(.*)/") or "."
local example = here .. "/../../../scripts/examples/two_disks.lua"

local made
local make_sim = lamina.sim
lamina.sim = function(args)
  made = make_sim(args)
  return made
end
dofile(example)
lamina.sim = make_sim

lamina.report{ state_hash = made:hash(), steps = made.nstep }
