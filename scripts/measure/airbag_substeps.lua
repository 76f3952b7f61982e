-- airbag_substeps.lua - multi-rate stepping on the airbag pages (issue 36
-- item 1; docs/performance.md "Multi-rate on the airbags"): one run of
-- assets/lua/airbag.lua's impact as a page runs it, with the gas and the
-- probe at m x the deck's dt and the bag in sub-steps, printing the page's
-- numbers (the probe's deepest displacement, its time, the final velocity,
-- the energy change, the gas outside, the pre-run tether) and the CPU time.
--   lamina run scripts/measure/airbag_substeps.lua --set page=cyl500 \
--     --set m=8 --set substeps=auto --set scheme=usl --set t_end=0.1
-- page: impact (Cyl-200, Box 10) or cyl500 (Box 11); substeps: a number,
-- "auto" or "none" (the plain step at m x dt); scheme: the page's (musl)
-- or usl; t_pre, t_end as the pages'; refine as airbag_convergence's.
local airbag = require("airbag")
local page = lamina.param("page", "impact")
local m = lamina.param("m", 1)
local sub = lamina.param("substeps", "none")
local scheme = lamina.param("scheme", "musl")
local t_pre = lamina.param("t_pre", 0.03)
local t_end = lamina.param("t_end", 0.1)
local refine = lamina.param("refine", 1)
local o = { variant = "removed", t_pre = t_pre, t_end = t_end, refine = refine, quiet = true,
            dt_factor = m, scheme = scheme, substeps = sub ~= "none" and (tonumber(sub) or sub) or nil,
            -- the pre-run these measurements were made with (the blend alone:
            -- the multi-rate step refuses the grid damping)
            pre_damping = 0, pre_pic = 0.05 }
if page == "cyl500" then
  o.width, o.cells_r = 0.34, 18
  o.probe = { radius = 0.25, mass = 8.05, speed = 4.70, gap = 0.005, exact_mass = true }
end
local clock = os.clock()
local r = airbag.impact(o)
local cpu = os.clock() - clock
print(string.format("%s m %g substeps %s (k %d) %s t_end %g: deepest %.2f mm at %.2f ms, final "
  .. "velocity %.3f m/s, energy change %.3f %%, gas outside %d, pre-run tether %.2f N, probe "
  .. "%.4f kg at %.4f m/s, %d steps, cpu %.1f s", page, m, tostring(sub), r.substeps, scheme, t_end,
  r.umax, r.tmax, r.vend, 100 * r.drift, r.escaped, r.tension, r.probe_mass, r.v[1], r.steps, cpu))
