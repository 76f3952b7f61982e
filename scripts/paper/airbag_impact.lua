-- title: Airbag struck by a probe, axisymmetric (WORK IN PROGRESS: coarse mesh, no pre-run yet)
-- source: York, Sulsky & Schreyer 2000 §4.4, Figs 14-18, Tables V-VI; dissertation §6.3 and
--   its input deck, Box 10 (A.4.8)
-- look: a cross-section mirrored about the axis (dashed), and at 40 ms the
--   same revolved in 3D (bag3d_t0.040.png: the bag's far half as meridians
--   and rings, the gas and probe in the cut plane): the bag (membrane
--   points) sits on the support, the cylindrical probe above it moves down at
--   3.9 m/s, depresses the top of the bag, which bulges out at the sides; the
--   probe slows, stops and rebounds. The gas should stay inside the bag:
--   3 of 3243 gas points get through it in the first 8 ms (counted). Known
--   defects of this first step: those 3 points, and below the probe the gas
--   points near the axis thin out and clump (see t = 40 ms)
-- checks: the probe rebounds (its velocity turns upward before 100 ms), the
--   gas stays inside, the energy balance. The papers' curves (Fig 17:
--   displacement against time, MPM, PISCES and the experiment) are not in
--   the text we have (only the caption): no digitised values are compared,
--   they are unavailable. Work in progress (issue 15 item 3, first step):
--   the initial shape is Box 10's gas polygon with an unstrained bag, not
--   the tethered pre-run of Fig 15; no tether variants, no convergence row yet
-- assumed: the geometry of Box 10 (x is r, y is z): gas polygon (0, 0.002)
--   ... (0.28, 0.139) ... (0, 0.299) plus the triangle up to (0, 0.318) at
--   the top centre; the bag is the membrane along that outline from pole
--   to pole (both ends on the axis); probe r <= 0.1, 0.329 <= z <= 0.409,
--   E = 5e7 (the papers': "arbitrary"), nu 0.3, its density set so that the
--   whole probe weighs 6.03 kg (2399 kg/m3; Box 10 has 2375), gas and probe
--   seeded with fill = "clipped" so that their masses are exact; grid 17 x 26
--   cells over 0.32 x 0.5 m (18.8 x 19.2 mm), dt 3.5e-6 s, 100 ms; gas
--   16 ppc, probe 4 ppc (Box 10's nprg), gas e0 = 8226.39 J/kg (p0 =
--   4000 Pa with rho 1.2156), no viscosity (mu = 0 in Box 10), no artificial
--   viscosity. The bag: t 0.5 mm, rho 662, E 6e7, nu 0.4, plane stress
--   (biaxial in the axisymmetric form), its density raised so that the bag
--   weighs the papers' 367.2 g (printed), spacing a quarter cell, unstrained at
--   the start, tension along segments. Basis bspline2, not the papers'
--   bilinear hats: in lamina's axisymmetric form FLIP gas at rest is
--   unstable on the hats (tests/physics/axisym_lame.lua), with an e-folding
--   time of about 0.35 ms at this pressure and cell. The support is the
--   fixed bottom of the grid, the probe and bag meet through the grid (no
--   contact law, as the papers)
-- visual: t_end=0.004
-- thumb: shape_t0.040.png
local out = lamina.param("out", "out/airbag_impact")
local revolve = require("revolve")
local t_end = lamina.param("t_end", 0.1)
local basis = lamina.param("basis", "bspline2")

local hr, hz = 0.32 / 17, 0.5 / 26
local sim = lamina.sim{ domain = {0, -0.001, 0.32, 0.499}, cell = {hr, hz}, dt = 3.5e-6,
                        axisymmetric = true, basis = basis,
                        boundary = { left = "symmetry", bottom = "fixed", right = "fixed",
                                     top = "fixed" } }
-- Box 10's gas regions: the bag's outline and the small triangle at the top centre
local outline = { {0, 0.002}, {0.14, 0.01}, {0.22, 0.037}, {0.26, 0.077}, {0.28, 0.139},
                  {0.26, 0.219}, {0.22, 0.261}, {0.18, 0.289}, {0.14, 0.299}, {0, 0.299} }
local body = lamina.polygon(outline)
local top = lamina.polygon{ {0.08, 0.299}, {0, 0.318}, {0, 0.299} }
local air = lamina.gas{ rho = 1.2156, e = 8226.39, gamma = 1.4 }
local gas = sim:body{ material = air, ppc = 16, name = "air", fill = "clipped",
                      region = function(x, y) return body:contains(x, y) or top:contains(x, y) end }
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
local fabric = lamina.membrane{ rho = rho_bag, E = 6e7, nu = 0.4, thickness = 5e-4,
                                law = "plane_stress" }
local bag = sim:membrane{ material = fabric, curve = lamina.polyline(bag_curve), name = "bag",
                          spacing = 0.25 * math.min(hr, hz), force = "segment" }
local R, H = 0.1, 0.08
local probe_mat = lamina.elastic{ rho = 6.03 / (math.pi * R * R * H), E = 5e7, nu = 0.3 }
local probe = sim:body{ material = probe_mat, ppc = 4, name = "probe", velocity = {0, -3.90},
                        fill = "clipped",
                        region = lamina.rect{ x0 = 0, y0 = 0.329, x1 = R, y1 = 0.329 + H } }
-- per radian: 2 pi times these are the whole bodies
local two_pi = 2 * math.pi
print(string.format("probe %.3f kg, bag %.1f g, air %.2f g, %d gas points, %d bag points",
                    two_pi * probe:mass(), 1e3 * two_pi * bag:mass(), 1e3 * two_pi * gas:mass(),
                    #gas, #bag))
local _, z0 = probe:com()
local escaped = 0
local rec = sim:record{ every = 2e-4, energy = true, file = out .. "/history.csv", values = {
  u = function() local _, z = probe:com(); return 1e3 * (z0 - z) end,    -- mm, into the bag
  v = function() local _, v = probe:velocity(); return -v end,            -- m/s, into the bag
  p = function() return gas:pressure() end,
  escaped = function() escaped = math.max(escaped, bag:escaped(gas)); return escaped end } }
for _, tf in ipairs{0, 0.02, 0.04, 0.06, 0.1} do
  sim:at(tf, function(s)
    s:frame{ file = string.format("%s/shape_t%.3f.png", out, tf), width = 640, height = 520,
             mirror = "x", window = {-0.4, -0.01, 0.4, 0.5}, scalebar = true, units = "m",
             title = string.format("t = %.0f ms (gas, bag, probe)", 1e3 * tf) }
    if tf == 0.04 then   -- the same moment revolved about the axis (assets/lua/revolve.lua)
      revolve.frame(s, { file = out .. "/bag3d_t0.040.png", bodies = {gas, bag, probe},
                         width = 640, height = 560, meridians = 32,
                         title = "t = 40 ms revolved: the bag's far half, the cut plane's gas and probe" })
    end
  end)
end
sim:run{ t_end = t_end }

local t, u, v, p = rec:column("t"), rec:column("u"), rec:column("v"), rec:column("p")
local ms = {}
for i = 1, #t do ms[i] = 1e3 * t[i] end
lamina.plot{ file = out .. "/probe_displacement.png", csv = true, width = 640, height = 360,
             title = "probe displacement into the bag (Fig 17's quantity; its curves unavailable)",
             xlabel = "t (ms)", ylabel = "u (mm)",
             series = { { x = ms, y = u, label = "lamina, 17 x 26 cells, " .. basis } } }
lamina.plot{ file = out .. "/probe_velocity.png", csv = true, width = 640, height = 360,
             title = "probe velocity (positive: into the bag)", xlabel = "t (ms)",
             ylabel = "v (m/s)", series = { { x = ms, y = v, label = "lamina" } } }
lamina.plot{ file = out .. "/bag_pressure.png", csv = true, width = 640, height = 360,
             title = "mean bag pressure", xlabel = "t (ms)", ylabel = "p (Pa)",
             series = { { x = ms, y = p, label = "lamina" } } }
local E = { rec:column("kinetic"), rec:column("strain"), rec:column("internal"),
            rec:column("total") }
lamina.plot{ file = out .. "/energy.png", csv = true, width = 640, height = 360,
             title = "energy per radian", xlabel = "t (ms)", ylabel = "J / rad",
             series = { { x = ms, y = E[1], label = "kinetic" }, { x = ms, y = E[2], label = "strain" },
                        { x = ms, y = E[3], label = "gas internal" },
                        { x = ms, y = E[4], label = "total" } } }
local umax, tmax, vend = -1e9, 0, v[#v]
for i = 1, #t do if u[i] > umax then umax, tmax = u[i], t[i] end end
local drift = (E[4][#E[4]] - E[4][1]) / E[1][1]
print(string.format("probe: deepest %.1f mm at %.1f ms, final velocity %.2f m/s (into the bag); " ..
                    "energy change %.2f %% of the probe's kinetic energy; gas outside %d",
                    umax, 1e3 * tmax, vend, 100 * drift, escaped))
lamina.report{
  probe_max_displacement = { umax, unit = "mm" },
  time_of_max = { 1e3 * tmax, unit = "ms" },
  final_velocity = { vend, unit = "m/s (into the bag)" },
  rebounds = t_end >= 0.1 and (vend < 0) or nil,
  energy_change = { 100 * drift, unit = "% of the probe's kinetic energy" },
  gas_outside = escaped,
  paper_curves = "unavailable (Fig 17's curves are not in the text)",
  state_hash = sim:hash(),
}
