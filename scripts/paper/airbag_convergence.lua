-- title: Airbag struck by a probe: the convergence row over three meshes
-- source: York, Sulsky & Schreyer 2000 §4.4, Figs 16-17; dissertation §6.3
-- look: the probe's displacement into the bag against time on three meshes
--   (17 x 26 cells of 18.8 mm as Box 10's ~19 mm, then 26 x 39 of 12.5 mm
--   and 34 x 52 of 9.4 mm), each
--   after its own tethered pre-run, the tether removed at the probe's
--   start; the curves should draw together as the mesh is refined, and the
--   shapes at 40 ms agree
-- checks: the deepest displacement, its time and the rebound velocity per
--   mesh, and their changes between meshes (ours: the papers ran one mesh
--   and their Fig 17 curves are not in the text); the impact's energy
--   change per mesh (kinetic + strain + gas internal, from the probe's
--   start)
-- assumed: as airbag_impact (assets/lua/airbag.lua), the same inputs on
--   every mesh: gas 16 points per cell, bag points a quarter cell apart, the
--   tethered pre-run damped to rest (grid damping 150 /s and a PIC blend of
--   1.25 % a deck step, both per unit time) at 4 x the deck's dt 3.5e-6 s
--   divided by the refinement and the impact at 8 x it (m = 8, m_pre = 4;
--   `--set m=1` runs the deck's dt throughout): the step is set by the
--   deck, 15 x below every body's Courant limit (docs/performance.md
--   "Multi-rate on the airbags", "The airbag's pre-run"). Ours, on the
--   deck's dt throughout: deepest 139.98 / 145.94 / 150.54 mm at 59.8 /
--   61.8 / 63.2 ms, final velocity -3.087 / -2.956 / -2.875 m/s, energy
--   change -0.27 / -0.30 / -0.45 %, 4 / 3 / 1 gas points outside (302 CPU
--   s); the longer steps move the deepest by at most 0.03 mm, a
--   hundred-and-fiftieth of the mesh-to-mesh change, the final velocity by
--   at most 0.13 %, and the energy change to -0.42 / -0.63 / -1.22 % (the MUSL
--   step's loss grows with the step), 6 / 6 / 5 gas points outside
--   (skin-grazers: the pre-run's larger blend a step), 47.8 CPU s. The two
--   finer meshes run on two threads (the state is bit-identical for a
--   given thread count)
-- heavy: three meshes to 100 ms, the finest 34 x 52 cells with 12 779 gas points: about 30 s here
-- visual: t_end=0.002 t_pre=0.001 meshes=1
-- thumb: displacement.png
local out = lamina.param("out", "out/airbag_convergence")
local t_end = lamina.param("t_end", 0.1)
local t_pre = lamina.param("t_pre", 0.03)
local meshes = lamina.param("meshes", "1,1.5,2")
local dt_m = lamina.param("m", 8)   -- the impact's step m x the deck's dt / refine (1: the deck's)
local dt_pre = lamina.param("m_pre", math.min(4, dt_m))   -- the pre-run's likewise
local airbag = require("airbag")

local runs, list = {}, {}
for m in meshes:gmatch("[^,]+") do
  local refine = tonumber(m)
  local r = airbag.impact{ variant = "removed", t_pre = t_pre, t_end = t_end, refine = refine, dt_factor = dt_pre, impact_dt_factor = dt_m,
                           threads = refine > 1 and 2 or 1,
                           frame_times = {0.04},
                           on_frame = function(s, tf)
                             s:frame{ file = string.format("%s/shape_%s_t%.3f.png", out, m, tf),
                                      width = 480, height = 390, mirror = "x",
                                      window = {-0.32, -0.001, 0.32, 0.499}, scalebar = true, units = "m",
                                      discs = "spacing",
                                      title = string.format("cells %.1f mm, t = %.0f ms",
                                                            320 / (17 * refine), 1e3 * tf) }
                           end }
  r.refine = refine
  runs[#runs + 1] = r
  -- the domain is rounded up to whole cells: 1.5 x 17 = 25.5 makes 26
  list[#list + 1] = string.format("%d x %d (%.1f mm)", math.ceil(17 * refine - 1e-9),
                                  math.ceil(26 * refine - 1e-9), 320 / (17 * refine))
end
local series = {}
for i, r in ipairs(runs) do
  series[i] = { x = r.t, y = r.u, label = list[i] .. " cells" }
end
lamina.plot{ file = out .. "/displacement.png", csv = true, width = 640, height = 360,
             title = "probe displacement into the bag, three meshes (tether removed)",
             xlabel = "t (ms)", ylabel = "u (mm)", series = series }
-- every mesh's state, not the finest's alone (assets/lua/hashes.lua; issue 32)
local hashes = {}
for i, r in ipairs(runs) do hashes[i] = r.hash end
local rep = { state_hash = require("hashes").fold(hashes) }
for i, r in ipairs(runs) do
  local key = string.format("mesh%d", i)
  rep[key .. "_cells"] = list[i]
  rep[key .. "_deepest"] = { r.umax, unit = "mm" }
  rep[key .. "_time_of_deepest"] = { r.tmax, unit = "ms" }
  rep[key .. "_final_velocity"] = { r.vend, unit = "m/s (into the bag)" }
  rep[key .. "_energy_change"] = { 100 * r.drift, unit = "% of the probe's kinetic energy" }
  rep[key .. "_gas_outside"] = r.escaped
  if i > 1 then
    rep[key .. "_deepest_change"] = { r.umax - runs[i - 1].umax, unit = "mm, from the coarser mesh" }
  end
end
lamina.report(rep)
