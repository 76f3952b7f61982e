-- title: Dog-bone membrane expansion as the dissertation ran it (input deck Box 9)
-- source: York's dissertation §6.2, Fig 47, Tables 4-6, Figs 48-55
--   (App. A.4.7, Box 9: the input deck of simulation 4); York, Sulsky &
--   Schreyer 2000 (fluid-membrane), §4.3, Figs 10-13, Tables II-IV
-- look: the deck's gas (two quadrilaterals, blue) inside its membrane line
--   (vermilion points, a dog-bone with a neck at x = 0.5 and a knob out to
--   x = 0.95) pushes the membrane out; it overshoots, rings and settles to a
--   quarter circle at the three finer cells; at cell 0.4 it stays
--   non-circular (r(0) < r(90)), as [T] Table 5's simulation 1 does; no gas
--   gets out; the radii at 0 and 90 degrees converge to the same value
-- checks: radius at 0 and 90 degrees and the pressure averaged over the
--   enclosed space beside [T] Table 5 and [F] Table III; the hoop stress
--   and p r / t beside [T] Table 6 and [F] Table IV, and the hoop stress
--   against p r / t of the same run; the energy loss beside [T] §6.2.1-6.2.4
--   and [F] §4.3; gas outside the membrane; the total mass beside Table 5
-- assumed: the deck read as assets/lua/dogbone_box9.lua's header says
--   (every reading and choice there). In short: 33 x 33 nodes on 1.6 x 1.6
--   (cell 0.05); gas the deck's two quadrilaterals (area 0.47463), 64
--   points per cell (nprg), rho 1, mu = 0.1 (the deck and [T] Table 4; [F]
--   Table II says 0.2), e = 250, gamma = 1.4, AV off; membrane rho 0.5,
--   E 1e6, nu 0.3, plane stress, wrinkle (one-way) law on, thickness 0.1
--   ([T] Table 6; not in the deck); 600 points (the deck; Table 5 says 400)
--   each weighing rho h^2 / np2 with np2 = 6.8207 (the spring-mass deck's
--   rule), i.e. standing for ds = 3.665e-3 of membrane: 2.199 in all, the
--   quarter circle of radius 1.400; total mass 0.584 at cell 0.05 and 0.600
--   at 0.4 (Table 5's). The deck prints only the first point, (0.49999,
--   0.00111); the line is lamina's reading: the gas outline stood off
--   outward (neck x = 0.49999, top through Fig 47's (0, 1), the knob's
--   edges d = 0.0463 out so that the points lie ds apart), stress-free as
--   placed (the deck gives no initial stress). Walls: symmetry at x = 0 and
--   y = 0 (codes 4), rollers at x = y = 1.6 (codes 1). The same 600-point
--   membrane at every cell (the decks of simulations 1-3 are not printed);
--   dt = 0.35e-4 h / 0.05 (the deck's Courant number, 1.04 for the
--   plane-stress membrane wave, at every cell; lamina's courant limit
--   raised to 1.05 for it). Run to the deck's t = 8.5; means over the last
--   time unit [7.5, 8.5] ([F]'s runs ended at t = 4, [F] §4.3.2: its
--   Table III stands beside our means over [3, 4] too); pure FLIP; two
--   threads. Basis: the papers'
--   bilinear one at cells 0.4-0.1; at cell 0.05 it fails: without help
--   the run stops at t = 0.38 (a gas point beside the membrane compressed
--   to zero volume), and with gas splitting (lamina.gas{split = 16}, the
--   variant page's remedy) about 100 gas points leave the membrane from
--   t = 0.05 on, where its first fold (the neck's top corner) swings out.
--   So cell 0.05 alone runs the quadratic B-spline (lamina.sim{basis =
--   "bspline2"}, docs/robustness.md): no gas leaves, no splitting, the
--   papers' continuity density; a change of basis between the last two
--   cells, to be kept in mind when reading the 0.1 -> 0.05 step.
--   Radii: the deck's end points lie 0.00111 off the axes, so r(0) and
--   r(90) are the end points' distances from the centre (under 0.1 degree
--   off the axis; [T] §6.2's radii are "based on material point
--   locations"). Gas outside: the points outside the membrane's polygon
--   closed through (-1, -1), i.e. along the axes (closed through the
--   centre, the chord to the end point 0.00111 off the x axis leaves a thin
--   sliver along the axis outside; counted that way, cell 0.05 had one gas
--   point outside from t = 8.38 on). Pressure: the mean over the space the membrane encloses,
--   gas:pressure(mem) = sum V_p p_p / A (the sum the internal forces use),
--   as [T] Table 5 note c averaged over interior grid points; the mean
--   over the particles is shown too (docs/decisions.md "Gas pressure over
--   the space"). At t = 0 it is 80-83, not 100: the gas fills 0.47-0.49 of
--   the 0.59 the membrane encloses (the deck's standoff). Energy: the loss
--   is measured on what the grid sees (sim:energy().grid_kinetic in place
--   of the particles' kinetic energy, which also holds FLIP's hidden
--   velocity); the particles' sum is shown too. Tolerances: radius and
--   pressure within the two papers' own difference at the cell ([T] Table 5
--   against [F] Table III, the same simulations reported twice), but not
--   where that is over half the value (cell 0.4's pressure, 33.4 against
--   50.3: both printed, no check); hoop
--   against p r / t within [F] Table IV's 2-5 % for simulations 2-4;
--   total mass to Table 5's three digits; no gas outside ([T] §6.2). The
--   earlier construction of the shape is the page gas_dogbone_superellipse.
--   Misses, and why. At cells 0.2 and 0.1 the radius ends 0.08 and 0.075
--   short of [T]'s: as the dog-bone balloons in the first 0.05 time units
--   its polyline shortens from 2.198 to 2.03, and the one-way law stores
--   the difference as compressive strain in ~490 of the 600 points, all
--   round the quarter; a cell's points move affinely, so slack points
--   beside taut ones are never stretched out again (cell 0.1: 436 points
--   slack at t = 4, 0.087 of membrane; docs/robustness.md "The dog-bone as
--   [T] Box 9 reads it"). The smaller circle holds about the same energy
--   in less area, so the pressure is higher (p = 0.4 E_int / A: 34.1
--   against [T]'s 27.0 at cell 0.1), and the hoop stress, a mean over
--   points many of which are slack, falls 6-12 % below p r / t. With
--   [T]'s 200 points at cell 0.1 the membrane tears at t = 3.64. Remedies
--   tried at cell 0.1 (accuracy30, the same deck run to t = 4, means of
--   r(0) / r(90) and p over [3, 4]; [T] Table 5: 1.388 / 1.387, 27.0; [F]
--   Table III: 1.35, 31.2): the page's bilinear basis and point forces
--   1.3066 / 1.3120, p 34.16 (462 points slack at t = 4); the quadratic
--   B-spline with point forces 1.3542 / 1.3555, p 31.82 (439 slack); the
--   B-spline with segment forces (dt x 0.7 for the segment form's Courant
--   factor) 1.3752 / 1.3732, p 30.67 (459 slack): the radius within the
--   papers' difference (0.038) of [T]'s, the pressure 3.7 above it (tol
--   4.2). The slack points stay as many: the smoother basis lets the taut
--   ones stretch, it does not take up the slack. The page keeps the papers'
--   bilinear basis at cells 0.4-0.1 (their scheme); the B-spline with
--   segment forces is the remedy for a user's run. At cell
--   0.05 the radius is within the papers' difference and the pressure,
--   31.8, is [F]'s 31.7 but 2.8 above [T]'s 29.0 (tolerance 2.7, the two
--   papers' own difference). At cell 0.4 r(0) is 0.024 below [T]'s 1.08
--   (tolerance 0.01); the mean radius over [3, 4], 1.084, is beside [F]'s
--   1.07. The total mass at cells 0.2 and 0.1 differs from Table 5 in the
--   third digit (their decks are not printed). The energy lost as the grid
--   sees it is about twice [T]'s at the bilinear cells.
-- heavy: four meshes to t = 8.5, the finest cell 0.05 with the quadratic B-spline on two threads (the time is in the page's record)
-- visual: finest=0.4 t_end=0.5 threads=1
-- thumb: cell0.050_t8.50.png

-- every gas particle outside the membrane: membrane:escaped's count beyond a
-- quarter cell plus its skin-grazers (issue 30: the count this file used)
local function outside(beyond, _, grazing) return beyond + grazing end
local out = lamina.param("out", "out/gas_dogbone")
local finest = lamina.param("finest", 0.05)
local t_end = lamina.param("t_end", 8.5)   -- [T] Box 9: tmax = 8.500014
local threads = lamina.param("threads", 2)   -- fixed here, so the state does not depend on the machine
local b = require("dogbone_box9")

-- [T] Table 5: r(0), r(90), pressure, total mass; [T] Table 6: p r / t from
-- Table 5, the simulation's hoop stress, % difference; [T] §6.2.1-6.2.4:
-- energy lost. [F] Table III: radius, pressure; Table IV: p r / t, hoop,
-- % difference.
local T5 = { [0.4] = {1.08, 1.13, 33.4, 0.600}, [0.2] = {1.335, 1.334, 24.9, 0.584},
             [0.1] = {1.388, 1.387, 27.0, 0.583}, [0.05] = {1.394, 1.396, 29.0, 0.584} }
local T6 = { [0.4] = {369, 394, 6.75}, [0.2] = {332, 372, 11.95}, [0.1] = {375, 417, 11.31},
             [0.05] = {405, 447, 10.49} }
local T_loss = { [0.4] = 3.6, [0.2] = 3.4, [0.1] = 1.2, [0.05] = "< 1" }
local F3 = { [0.4] = {1.07, 50.3}, [0.2] = {1.33, 28.8}, [0.1] = {1.35, 31.2}, [0.05] = {1.36, 31.7} }
local F4 = { [0.4] = {539, 101, -81.3}, [0.2] = {385, 399, 3.6}, [0.1] = {420, 400, -4.8},
             [0.05] = {443, 433, -2.3} }
local sim_no = { [0.4] = 1, [0.2] = 2, [0.1] = 3, [0.05] = 4 }

-- Fig 47 / Box 9: the deck's geometry
do
  local series = {}
  for i, poly in ipairs(b.gas_polygons) do
    local x, y = {}, {}
    for k = 1, #poly + 1 do local p = poly[(k - 1) % #poly + 1]; x[k], y[k] = p[1], p[2] end
    series[#series + 1] = { x = x, y = y, color = 1, label = i == 1 and "gas quadrilaterals (Box 9)" or nil }
  end
  local o = b.outline(b.standoff())
  local ox, oy = {}, {}
  for k, p in ipairs(o) do ox[k], oy[k] = p[1], p[2] end
  series[#series + 1] = { x = ox, y = oy, color = 2, dashed = true, label = "membrane line (our reading)" }
  series[#series + 1] = { x = { b.deck.first[1] }, y = { b.deck.first[2] }, markers = true, color = 3,
                          label = "the deck's first point (0.49999, 0.00111)" }
  lamina.plot{ file = out .. "/fig47_box9_geometry.png", width = 560, height = 520,
               title = "Fig 47 / Box 9: gas regions and membrane line at t = 0",
               xlabel = "x", ylabel = "y", xrange = {0, 1.2}, yrange = {0, 1.25},
               legend = "top right", series = series }
end

local report, radius_series, energy_series, hashes = {}, {}, {}, {}
for _, h in ipairs{0.4, 0.2, 0.1, 0.05} do
  if h < finest - 1e-12 then break end
  local basis = h < 0.075 and "bspline2" or "linear"
  local sim, gas, mem = b.setup(h, { basis = basis, threads = threads })
  local ngas, nmem = #gas, #mem
  local mass = 0
  for _, body in ipairs{gas, mem} do
    local m = body:particles().mass
    for i = 1, #body do mass = mass + m[i] end
  end
  local escaped = 0
  local rec = sim:record{ every = 0.01, energy = true,
                          file = string.format("%s/history_cell%.3f.csv", out, h), values = {
    p = function() return gas:pressure(mem) end,
    pp = function() return gas:pressure("particles") end,
    hoop = function() return mem:hoop_stress() end,
    r0 = function() return b.radius(mem, 0) end,
    r90 = function() return b.radius(mem, 90) end,
    gk = function() return sim:energy().grid_kinetic end,
    escaped = function() escaped = math.max(escaped, outside(mem:escaped(gas, {-1, -1}))); return escaped end } }
  for _, tf in ipairs{0, 0.05, 0.1, 0.2, 0.5, t_end} do
    sim:at(tf, function(s)
      -- the whole quarter, and a close-up around the membrane's end on the
      -- 0-degree axis where its 600 points (1 px apart in the whole view)
      -- read as separate discs (membrane points only: the gas's discs would
      -- cross the close-up's edge, which the renderer clips to the panel's
      -- cell, not to its window)
      local r0 = b.radius(mem, 0)
      s:frame{ file = string.format("%s/cell%.3f_t%.2f.png", out, h, tf), width = 840, height = 470,
               discs = "spacing",   -- the membrane as points (docs/gallery.md checklist)
               title = string.format("Box 9, cell %.2f (%s), t = %.2f", h,
                                     basis == "linear" and "bilinear" or "B-spline", tf),
               layout = {1, 2},
               panels = { { title = "quarter" },
                          { title = "membrane points at 0 degrees", particles = "membranes",
                            window = {r0 - 0.08, 0, r0 + 0.08, 0.16} } } }
    end)
  end
  local clock = lamina.clock()
  sim:run{ t_end = t_end }
  local secs = lamina.clock() - clock
  local t0 = math.max(0, t_end - 1)
  local p, hoop = rec:mean("p", t0, t_end), rec:mean("hoop", t0, t_end)
  local pp = rec:mean("pp", t0, t_end)
  local r0, r90 = rec:mean("r0", t0, t_end), rec:mean("r90", t0, t_end)
  local prt, pprt = p * 0.5 * (r0 + r90) / 0.1, pp * 0.5 * (r0 + r90) / 0.1
  local tot, ke, gk = rec:column("total"), rec:column("kinetic"), rec:column("gk")
  local n = #tot
  local dE = (tot[n] - tot[1]) / tot[1]
  local vis = {}
  for i = 1, n do vis[i] = tot[i] - ke[i] + gk[i] end
  local loss, hidden = (vis[1] - vis[n]) / vis[1], ke[n] - gk[n]
  local dev = 100 * (hoop - prt) / prt
  print(string.format("cell %.3f (%s): %d gas + %d membrane points, mass %.5f, %d steps in %.1f s; "
    .. "r(0) %.4f r(90) %.4f p %.2f (particles %.2f) hoop %.1f p r/t %.1f (%+.1f %%); gas outside %d; "
    .. "visible energy loss %.2f %%, hidden kinetic energy %.2f, particle energy %+.2f %%",
    h, basis, ngas, nmem, mass, sim.nstep, secs, r0, r90, p, pp, hoop, prt, dev, escaped,
    100 * loss, hidden, 100 * dE))
  local tag = string.format("cell_%.3f", h)
  local s = sim_no[h]
  report["radius_0deg_" .. tag] = { r0, paper = T5[h][1], tol = math.abs(T5[h][1] - F3[h][1]),
    unit = string.format("([T] Table 5 sim %d; tol: [F] Table III's %.2f)", s, F3[h][1]) }
  report["radius_90deg_" .. tag] = { r90, paper = T5[h][2], tol = math.abs(T5[h][2] - F3[h][1]),
    unit = string.format("([T] Table 5 sim %d; tol: [F] Table III's %.2f)", s, F3[h][1]) }
  -- the tolerance is the two papers' own difference for the same run, but
  -- never above half [T]'s value (issue 32 item 3): at cell 0.4 they differ
  -- by 51 % (33.4 against 50.3), so there both are printed and none checked
  local dp = math.abs(T5[h][3] - F3[h][2])
  report["pressure_" .. tag] = dp <= 0.5 * T5[h][3]
    and { p, paper = T5[h][3], tol = dp,
          unit = string.format("(mean over the enclosed space; [T] Table 5; tol: [F] Table III's %.1f)", F3[h][2]) }
    or { p, paper = T5[h][3],
         unit = string.format("(mean over the enclosed space; [T] Table 5; [F] Table III: %.1f for the same run, "
                              .. "%.0f %% apart: no check)", F3[h][2], 100 * dp / T5[h][3]) }
  if t_end >= 4 then   -- [F] §4.3.2 shows its final state at t = 4: its Table III beside our means over [3, 4]
    report["radius_t3to4_" .. tag] = { 0.5 * (rec:mean("r0", 3, 4) + rec:mean("r90", 3, 4)), paper = F3[h][1],
      unit = "(mean of r(0), r(90) over t in [3, 4]; [F] Table III, its runs ended at t = 4)" }
    report["pressure_t3to4_" .. tag] = { rec:mean("p", 3, 4), paper = F3[h][2],
      unit = "(over t in [3, 4]; [F] Table III)" }
  end
  report["pressure_particles_" .. tag] = { pp, unit = "(mean over the particles)" }
  report["hoop_" .. tag] = { hoop, paper = T6[h][2],
    unit = string.format("(mean membrane stress; [T] Table 6; [F] Table IV: %d)", F4[h][2]) }
  report["p_r_over_t_" .. tag] = { prt, paper = T6[h][1],
    unit = string.format("(this run's p and r, t = 0.1; [T] Table 6 from Table 5; [F] Table IV: %d)", F4[h][1]) }
  report["hoop_vs_prt_" .. tag] = { dev, ref = h < 0.3 and 0 or nil, tol = h < 0.3 and 5 or nil,
    unit = string.format("%% from p r / t of this run (ours); [T] Table 6: %+.2f %%, [F] Table IV: %+.1f %%%s",
                         T6[h][3], F4[h][3], h < 0.3 and "; tol: [F]'s 2-5 % for sims 2-4" or "") }
  report["r0_r90_" .. tag] = { 100 * math.abs(r0 - r90) / r0, unit = "% apart" }
  report["energy_loss_" .. tag] = { 100 * loss, paper = T_loss[h],
    unit = string.format("%% (as the grid sees it; [T] §6.2.%d; [F] §4.3: %s)", s,
                         h == 0.4 and "1.5 %" or h == 0.05 and "-0.03 % (a gain)" or "-") }
  report["energy_change_" .. tag] = { 100 * dE, unit = "% (particles' sum)" }
  report["hidden_kinetic_" .. tag] = { hidden, unit = string.format("(of %.0f)", tot[1]) }
  report["gas_outside_" .. tag] = { escaped, ref = 0, tol = 0, unit = "points ([T] §6.2: none should escape)" }
  report["total_mass_" .. tag] = { mass, paper = T5[h][4], tol = 0.0005, unit = "([T] Table 5, to its three digits)" }
  report["run_" .. tag] = string.format("%s basis, %d + %d points, dt %.3g, %d steps, %.0f s",
                                        basis == "linear" and "bilinear" or "quadratic B-spline",
                                        ngas, nmem, sim.dt, sim.nstep, secs)
  local t = rec:column("t")
  radius_series[#radius_series + 1] = { x = t, y = rec:column("r0"), label = string.format("0 deg, cell %.2f", h) }
  radius_series[#radius_series + 1] = { x = t, y = rec:column("r90"), label = string.format("90 deg, cell %.2f", h),
                                        dashed = true, color = #radius_series }
  local rel, vrel = {}, {}
  for i = 1, n do rel[i], vrel[i] = tot[i] / tot[1], vis[i] / vis[1] end
  energy_series[#energy_series + 1] = { x = t, y = rel, label = string.format("particles, cell %.2f", h) }
  energy_series[#energy_series + 1] = { x = t, y = vrel, label = string.format("grid's view, cell %.2f", h),
                                        dashed = true, color = #energy_series }
  hashes[#hashes + 1] = sim:hash()
end
lamina.plot{ file = out .. "/fig55_radii.png", csv = true, width = 720, height = 420,
             title = "Figs 49/51/53/55: membrane radius at 0 and 90 degrees (Box 9)", xlabel = "t",
             ylabel = "radius", legend = "bottom right", series = radius_series }
lamina.plot{ file = out .. "/fig55_energy.png", csv = true, width = 720, height = 420,
             title = "Figs 49/51/53/55: total energy / initial (dashed: as the grid sees it)", xlabel = "t",
             ylabel = "E / E0", yrange = {0.75, 1.03}, legend = "bottom right",   -- the legend below the curves
             series = energy_series }
-- every mesh's state (assets/lua/hashes.lua)
report.state_hash = require("hashes").fold(hashes)
lamina.report(report)
