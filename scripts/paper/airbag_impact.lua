-- title: Airbag struck by a probe, axisymmetric, after a tethered pre-run (coarse mesh)
-- source: York, Sulsky & Schreyer 2000 §4.4, Figs 14-18, Tables V-VI; dissertation §6.3 and
--   its input deck, Box 10 (A.4.8)
-- look: a cross-section mirrored about the axis (dashed), and at 40 ms the
--   same revolved in 3D (bag3d_t0.040.png: the bag's far half as meridians
--   and rings, the gas and probe in the cut plane). First the pre-run (Fig
--   15): the bag inflates with a tether between its poles and comes to rest,
--   the tether pulling the top centre in (the papers' arrow in Fig 16's
--   first plot; frames show the clock with the 30-ms pre-run in it, titles
--   the time from the probe's start). Then the probe, 11 mm above the bag,
--   moves down at 3.9 m/s, depresses the top, the bag bulges out at the
--   sides, the probe slows, stops and rebounds. Two runs: the tether removed
--   at the probe's start (the paper's run) and kept (its variant); their
--   displacements lie on each other (below)
-- checks: the probe rebounds (its velocity turns upward before 100 ms), the
--   gas stays inside (a few points get through: counted), the impact's
--   energy balance (kinetic + strain of bag, probe and tether + gas
--   internal, from the probe's start). With the tether kept [F] §4.4 says
--   the probe went "about 20 mm farther" and blames "the interference of
--   the tether with the gas flow": its tether was material points, a cone
--   in the axisymmetric form. Here the tether is the link its last
--   paragraph suggests, which the gas does not see, and the probe goes
--   0.2 mm farther: the cable is slack while the probe presses the top pole
--   down, so without the interference the tether changes nothing, as the
--   paper suspected (shown beside its 20 mm, with this reason).
--   The papers' curves (Fig 17: displacement against time, MPM, PISCES and
--   the experiment) are not in the text we have (only the caption): no
--   digitised values are compared, they are unavailable. Not yet: a
--   convergence row over meshes (one mesh here)
-- assumed: the geometry of Box 10 (x is r, y is z): gas polygon (0, 0.002)
--   ... (0.28, 0.139) ... (0, 0.299) plus the triangle up to (0, 0.318) at
--   the top centre; the bag is the membrane along that outline from pole
--   to pole (both ends on the axis), unstrained at the start of the
--   pre-run. The tether (no data in the papers): a cable between the poles
--   at their distance, 0.316 m, of stiffness E t w / L = 1.9e4 N/m (a strap
--   of the bag's fabric 200 mm wide); the lower pole held on the support
--   (pinned), where an airbag is mounted. Pre-run 30 ms with a PIC blend of
--   0.05 to bring the bag to rest (kinetic energy left 0.1 % of the probe's),
--   then no blend. Probe r <= 0.1, height 0.08, its bottom 11 mm above the
--   bag's highest point under it (Box 10: 0.329 over the pole's 0.318), E =
--   5e7 (the papers': "arbitrary"), nu 0.3, its density set so that the
--   whole probe weighs 6.03 kg (2399 kg/m3; Box 10 has 2375), gas and probe
--   seeded with fill = "clipped" so that their masses are exact; grid 17 x 26
--   cells over 0.32 x 0.5 m (18.8 x 19.2 mm), dt 3.5e-6 s, 100 ms; gas 16
--   ppc, probe 4 ppc (Box 10's nprg), gas e0 = 8226.39 J/kg (p0 = 4000 Pa
--   with rho 1.2156; 3685 Pa after the pre-run's inflation), no viscosity
--   (mu = 0 in Box 10), no artificial viscosity. The bag: t 0.5 mm, rho 662,
--   E 6e7, nu 0.4, plane stress (biaxial in the axisymmetric form), its
--   density raised so that the bag weighs the papers' 367.2 g (printed),
--   spacing a quarter cell, tension along segments. Basis bspline2, not the
--   papers' bilinear hats: in lamina's axisymmetric form FLIP gas at rest is
--   unstable on the hats (tests/physics/axisym_lame.lua), with an e-folding
--   time of about 0.35 ms at this pressure and cell. The support is the
--   fixed bottom of the grid, the probe and bag meet through the grid (no
--   contact law, as the papers)
-- visual: t_end=0.004 t_pre=0.002 variants=removed
-- thumb: shape_t0.040.png
local out = lamina.param("out", "out/airbag_impact")
local revolve = require("revolve")
local t_end = lamina.param("t_end", 0.1)            -- of the impact, from the probe's start
local t_pre = lamina.param("t_pre", 0.03)           -- the tethered pre-run (Fig 15)
local basis = lamina.param("basis", "bspline2")
local k_tether = lamina.param("tether_k", 1.9e4)    -- N/m: E t w / L of a 200 mm strap
local variants = lamina.param("variants", "removed,kept")

local hr, hz = 0.32 / 17, 0.5 / 26
-- Box 10's gas regions: the bag's outline and the small triangle at the top centre
local outline = { {0, 0.002}, {0.14, 0.01}, {0.22, 0.037}, {0.26, 0.077}, {0.28, 0.139},
                  {0.26, 0.219}, {0.22, 0.261}, {0.18, 0.289}, {0.14, 0.299}, {0, 0.299} }
local gas_body = lamina.polygon(outline)
local gas_top = lamina.polygon{ {0.08, 0.299}, {0, 0.318}, {0, 0.299} }
-- the bag: along the outline to (0.14, 0.299), then over the triangle's top
-- edge to the upper pole
local bag_curve = {}
for k = 1, 9 do bag_curve[k] = outline[k] end
bag_curve[10] = {0.08, 0.299}
bag_curve[11] = {0, 0.318}
-- The papers: "the total airbag mass was derived to be 367.2 g ... material
-- point volumes were prescribed such that the total airbag mass was
-- correct". This outline's surface, 2 pi int r ds, at t = 0.5 mm and rho =
-- 662 weighs less (printed); as they did, the mass is made 367.2 g (here by
-- the density; the stiffness E t is Table VI's).
local area = 0
for k = 1, #bag_curve - 1 do
  local a, b = bag_curve[k], bag_curve[k + 1]
  area = area + 2 * math.pi * 0.5 * (a[1] + b[1]) * math.sqrt((b[1] - a[1]) ^ 2 + (b[2] - a[2]) ^ 2)
end
local rho_bag = 0.3672 / (5e-4 * area)
print(string.format("bag surface %.4f m2: %.1f g at rho 662; rho %.0f for 367.2 g", area,
                    1e3 * 662 * 5e-4 * area, rho_bag))
local two_pi = 2 * math.pi   -- per radian: 2 pi times the engine's masses are the whole bodies

-- One run: the tethered pre-run to rest, then the probe; the tether
-- removed at the probe's start ("removed", the paper's run) or kept
-- ("kept", the paper's variant, here as the link of its closing remark).
local function impact(variant, frames)
  local sim = lamina.sim{ domain = {0, -0.001, 0.32, 0.499}, cell = {hr, hz}, dt = 3.5e-6,
                          axisymmetric = true, basis = basis,
                          boundary = { left = "symmetry", bottom = "fixed", right = "fixed",
                                       top = "fixed" } }
  local air = lamina.gas{ rho = 1.2156, e = 8226.39, gamma = 1.4 }
  local gas = sim:body{ material = air, ppc = 16, name = "air", fill = "clipped",
                        region = function(x, y) return gas_body:contains(x, y) or gas_top:contains(x, y) end }
  local fabric = lamina.membrane{ rho = rho_bag, E = 6e7, nu = 0.4, thickness = 5e-4,
                                  law = "plane_stress" }
  local bag = sim:membrane{ material = fabric, curve = lamina.polyline(bag_curve), name = "bag",
                            spacing = 0.25 * math.min(hr, hz), force = "segment" }
  -- The tether: from the bag's lower pole, held on the support where an
  -- airbag is mounted, to its upper pole, at the poles' distance; the
  -- pre-run's PIC blend brings the inflated bag to rest ([F] §4.4: "allowed
  -- to come to approximate equilibrium").
  bag:pin{ points = {1} }
  local tether = sim:link{ a = {bag, 1}, b = {bag, #bag}, stiffness = k_tether }
  sim.pic = 0.05
  sim:run{ t_end = t_pre }
  local pre = sim:energy()
  local P = bag:particles()
  local ztop = -1
  for i = 1, #P.x do if P.x[i] <= 0.1 then ztop = math.max(ztop, P.y[i]) end end
  local tension = tether:tension()
  sim.pic = 0
  if variant == "removed" then tether:remove() end
  -- the probe, 11 mm above the bag as in Box 10 (0.329 over the pole's 0.318)
  local R, H = 0.1, 0.08
  local probe_mat = lamina.elastic{ rho = 6.03 / (math.pi * R * R * H), E = 5e7, nu = 0.3 }
  local probe = sim:body{ material = probe_mat, ppc = 4, name = "probe", velocity = {0, -3.90},
                          fill = "clipped",
                          region = lamina.rect{ x0 = 0, y0 = ztop + 0.011, x1 = R, y1 = ztop + 0.011 + H } }
  print(string.format("%s: pre-run %.0f ms, kinetic energy left %.2e J/rad, tether %.1f N, bag top %.4f m, " ..
                      "gas %.1f Pa; probe %.3f kg, bag %.1f g, air %.2f g, %d gas points, %d bag points",
                      variant, 1e3 * t_pre, pre.kinetic, tension, ztop, gas:pressure(),
                      two_pi * probe:mass(), 1e3 * two_pi * bag:mass(), 1e3 * two_pi * gas:mass(), #gas, #bag))
  local _, z0 = probe:com()
  local escaped = 0
  local rec = sim:record{ every = 2e-4, energy = true, values = {
    u = function() local _, z = probe:com(); return 1e3 * (z0 - z) end,    -- mm, into the bag
    v = function() local _, v = probe:velocity(); return -v end,            -- m/s, into the bag
    p = function() return gas:pressure() end,
    T = function() return tether:tension() end,
    escaped = function() escaped = math.max(escaped, bag:escaped(gas)); return escaped end } }
  for _, tf in ipairs(frames and {0, 0.02, 0.04, 0.06, 0.1} or {}) do
    sim:at(t_pre + tf, function(s)
      s:frame{ file = string.format("%s/shape_t%.3f.png", out, tf), width = 640, height = 520,
               mirror = "x", window = {-0.4, -0.01, 0.4, 0.5}, scalebar = true, units = "m",
               title = string.format("t = %.0f ms from the probe's start (tether %s)", 1e3 * tf, variant) }
      if tf == 0.04 then   -- the same moment revolved about the axis (assets/lua/revolve.lua)
        revolve.frame(s, { file = out .. "/bag3d_t0.040.png", bodies = {gas, bag, probe},
                           width = 640, height = 560, meridians = 32,
                           title = "t = 40 ms revolved: the bag's far half, the cut plane's gas and probe" })
      end
    end)
  end
  sim:run{ t_end = t_pre + t_end }
  local r = { t = {}, u = rec:column("u"), v = rec:column("v"), p = rec:column("p"),
              T = rec:column("T"), kin = rec:column("kinetic"), strain = rec:column("strain"),
              internal = rec:column("internal"), total = rec:column("total"), escaped = escaped,
              hash = sim:hash(), tension = tension, ztop = ztop }
  for i, t in ipairs(rec:column("t")) do r.t[i] = 1e3 * (t - t_pre) end
  r.umax, r.tmax = -1e9, 0
  for i = 1, #r.t do if r.u[i] > r.umax then r.umax, r.tmax = r.u[i], r.t[i] end end
  r.vend = r.v[#r.v]
  -- the impact's energy balance: from the probe's start on, no PIC blend,
  -- so kinetic + strain (bag, probe, tether) + gas internal is conserved
  r.drift = (r.total[#r.total] - r.total[1]) / r.kin[1]
  print(string.format("%s: deepest %.1f mm at %.1f ms, final velocity %.2f m/s (into the bag); " ..
                      "energy change %.2f %% of the probe's kinetic energy; gas outside %d",
                      variant, r.umax, r.tmax, r.vend, 100 * r.drift, escaped))
  return r
end

local runs, names = {}, {}
for v in variants:gmatch("[^,]+") do
  names[#names + 1] = v
  runs[v] = impact(v, #names == 1)
end
local main = runs[names[1]]
local label = { removed = "tether removed at the start (the paper's run)",
                kept = "tether kept, as a link (the paper's variant)" }
local function series(field)
  local s = {}
  for _, v in ipairs(names) do s[#s + 1] = { x = runs[v].t, y = runs[v][field], label = label[v] or v } end
  return s
end
lamina.plot{ file = out .. "/probe_displacement.png", csv = true, width = 640, height = 360,
             title = "probe displacement into the bag (Fig 17's quantity; its curves unavailable)",
             xlabel = "t (ms)", ylabel = "u (mm)", series = series("u") }
lamina.plot{ file = out .. "/probe_velocity.png", csv = true, width = 640, height = 360,
             title = "probe velocity (positive: into the bag)", xlabel = "t (ms)",
             ylabel = "v (m/s)", series = series("v") }
lamina.plot{ file = out .. "/bag_pressure.png", csv = true, width = 640, height = 360,
             title = "mean bag pressure", xlabel = "t (ms)", ylabel = "p (Pa)", series = series("p") }
lamina.plot{ file = out .. "/energy.png", csv = true, width = 640, height = 360,
             title = "energy per radian (" .. (label[names[1]] or names[1]) .. ")", xlabel = "t (ms)",
             ylabel = "J / rad",
             series = { { x = main.t, y = main.kin, label = "kinetic" },
                        { x = main.t, y = main.strain, label = "strain (bag, probe, tether)" },
                        { x = main.t, y = main.internal, label = "gas internal" },
                        { x = main.t, y = main.total, label = "total" } } }
local rep = {
  probe_max_displacement = { main.umax, unit = "mm" },
  time_of_max = { main.tmax, unit = "ms" },
  final_velocity = { main.vend, unit = "m/s (into the bag)" },
  rebounds = t_end >= 0.1 and (main.vend < 0) or nil,
  energy_change = { 100 * main.drift, unit = "% of the probe's kinetic energy" },
  gas_outside = main.escaped,
  pre_run_tether = { main.tension, unit = "N" },
  paper_curves = "unavailable (Fig 17's curves are not in the text)",
  state_hash = main.hash,
}
if runs.removed and runs.kept then
  -- [F] §4.4 in words: with the tether kept the probe went "about 20 mm
  -- farther into the airbag" and the slope past the peak matched the
  -- experiment's (no numbers for the slope: not compared)
  rep.kept_deeper = { runs.kept.umax - runs.removed.umax, paper = 20, unit = "mm" }
  rep.kept_energy_change = { 100 * runs.kept.drift, unit = "% of the probe's kinetic energy" }
end
lamina.report(rep)
