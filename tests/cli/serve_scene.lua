-- lamina serve's test scene (tests/cli/serve_*.py): two small elastic disks
-- on a coarse grid, run for t_end (long: the tests stop it with SIGTERM or
-- let a short one end). Every `every` seconds of simulated time a callback
-- reads lamina.param("amp") again - the value the page changes live - and
-- draws a frame whose title shows it; a recorder keeps it as a column, so a
-- test reads the value the script saw after each change.
local t_end = lamina.param("t_end", 0.2)
local every = lamina.param("every", 0.01)
local out = lamina.param("out", "out")
local amp = lamina.param("amp", 1.0)
lamina.param("label", "disks")           -- a string parameter, shown on the page
lamina.param("fast", true)               -- a boolean one
lamina.param("tag<b>\"&'", 0)             -- a name the page must escape

local sim = lamina.sim{ basis = "linear", domain = {0, 0, 1, 1}, cell = 0.1, dt = 1e-3 }
local rubber = lamina.elastic{ rho = 1000, E = 1000, nu = 0.3 }
sim:body{ material = rubber, ppc = 4, velocity = { 0.1,  0.1},
          region = lamina.disk{ center = {0.3, 0.3}, radius = 0.15 } }
sim:body{ material = rubber, ppc = 4, velocity = {-0.1, -0.1},
          region = lamina.disk{ center = {0.7, 0.7}, radius = 0.15 } }
sim:record{ file = out .. "/amp.csv", every = every, energy = true,
            values = { amp = function() return amp end } }
sim:every(every, function(s)
  amp = lamina.param("amp", 1.0)
  s:frame{ file = string.format("%s/f%06d.png", out, s.nstep), width = 96, height = 96,
           title = string.format("amp = %g", amp) }
end)
sim:run{ t_end = t_end }
