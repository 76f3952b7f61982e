-- title: Pendulum without the wrinkle (one-way) law, 40 points, cell 0.1
-- source: York's dissertation §5.7.3, Fig 38 (beside Fig 33, the same run
--   with the wrinkle law); Table 1 for the set-up
-- look: the string's points at t = 0, 0.3, ..., 1.5 (one colour per time)
--   without the wrinkle law (Fig 38) and with it (Fig 33), pure FLIP as the
--   papers ran: the swings are much alike, as [T] says ("the results are
--   similar"), and without the law the points are less well aligned ("the
--   oscillations 'up' may cause some material points to go into
--   compression ... a phenomenon similar to buckling"): the kink plot's
--   solid curves. Its dashed curves are the papers' point quadrature
--   ([M] eq 9), where the finding came out reversed and the run with the
--   law tore at t = 1.28: there each point's strain is the sum of its
--   t.de.t, the grid's velocity gradient at the point, which is noisy as
--   points cross cells; with the two-way law a wrong strain is pushed back
--   by its own stress, with the one-way law only a positive one is (a
--   slack point carries no stress), so the strains ratchet down: by
--   t = 1.2 their mean is 0.025 below the log strain of the string's
--   length (0.0064 above it without the law, 1e-4 with segments), the
--   points beside the end mass go slack (eps_t -0.4 to -1.0 at the tear),
--   nothing holds the mass and the string parts beside it. The segment form (sim:membrane{force = "segment"}, lamina's
--   default) takes each strain from the length between neighbouring
--   points, so it cannot drift; both runs use it. The theta plot sets the
--   two segment runs beside our bar-element FEM (dashed; ours,
--   assets/lua/barfem.lua)
-- checks: [T]'s statement as a number: the mean over the run of the kink
--   (the largest offset of a point from its two neighbours' midpoint, over
--   the spacing; the point beside the end mass left out) larger without the
--   law than with it (segment form; the point form's, over t <= 1.1 before
--   its tear, reported beside it); [T]'s "similar": theta(t) of the two runs
--   as an rms difference, and each against our FEM (no tolerance: [T] gives
--   none); the ratchet: the points' mean strain less the log strain of the
--   string's length, largest up to t = 1.2, for both forms
-- assumed: Table 1 (L = 0.73, m = 3.3, g = 20, theta0 = 19.8 deg, E = 1e6,
--   rho = 0.1, nu = 0, t = 0.1), 40 points on cells of 0.1 ([T] Figs 33
--   and 38; Box 7), dt = 0.63 h / c (Box 6's 2e-5); the pivot is the first
--   point, on the fixed top wall; uniaxial law, linear basis, MUSL; the
--   segment form where [T] used point quadrature (the ratchet above). The
--   FEM is ours: 20 bar elements, two-way
-- visual: t_end=0.3
-- thumb: fig38_positions.png
local out = lamina.param("out", "out/membrane_pendulum_no_wrinkle")
local t_end = lamina.param("t_end", 1.8)
local barfem = require("barfem")

local E, L, m, g, th0, rho, t = 1e6, 0.73, 3.3, 20, 19.8, 0.1, 0.1
local c = math.sqrt(E / rho)
local px, py = 0.6, 1.0
local mx, my = px + L * math.sin(math.rad(th0)), py - L * math.cos(math.rad(th0))
local h, n = 0.1, 40
local snap_times = {0, 0.3, 0.6, 0.9, 1.2, 1.5}

-- Kinks: the largest distance of a point from the midpoint of its two
-- neighbours, over the initial spacing (0 on a straight or gently bowed
-- string; the zig-zag of misaligned points). The point next to the end
-- mass is left out: the mass, 18000 times a string point's, bends the
-- string there with or without the law.
local function kink(q)
  local worst = 0
  for i = 2, q.n - 2 do
    local dx = q.x[i] - 0.5 * (q.x[i - 1] + q.x[i + 1])
    local dy = q.y[i] - 0.5 * (q.y[i - 1] + q.y[i + 1])
    worst = math.max(worst, math.sqrt(dx * dx + dy * dy))
  end
  return worst / (L / (n - 1))
end

-- The point form's kinks are compared up to t = 1.1: its run with the law
-- starts to tear at 1.17 (and does at 1.28).
local point_until = math.min(1.1, t_end)

local fem = barfem.run{ from = {px, py}, to = {mx, my}, elements = 20, rho = rho, A = t, E = E,
                        end_mass = m, g = {0, -g}, one_way = false, t_end = t_end,
                        every = 1e-3, safety = 0.9 }

local function run(one_way, force, kink_until)
  local sim = lamina.sim{ basis = "linear", domain = {0, 0, 1.2, 1.0}, cell = h, dt = 0.63 * h / c,
                          gravity = {0, -g}, mass = "lumped" }   -- [T]'s lumped mass
  local wire = lamina.membrane{ rho = rho, E = E, nu = 0, thickness = t, law = "uniaxial",
                                one_way = one_way }
  local s = sim:membrane{ force = force, material = wire, count = n, end_mass = m, name = "string",
                          curve = lamina.segment{ from = {px, py}, to = {mx, my} } }
  local rec = sim:record{ every = 2e-3, angle = { theta = s },
                          values = { kink = function() return kink(s:particles()) end,
                                     compressed = function()
                                       local q, k = s:particles(), 0
                                       for i = 1, q.n do if q.et[i] < 0 then k = k + 1 end end
                                       return k
                                     end,
                                     -- the ratchet's measure: the points' mean strain
                                     -- less the log strain of the string's length
                                     -- (0 for a uniformly strained string)
                                     drift = function()
                                       local q, se, len = s:particles(), 0, 0
                                       for i = 1, q.n do se = se + q.et[i] end
                                       for i = 2, q.n do
                                         len = len + math.sqrt((q.x[i] - q.x[i - 1])^2 + (q.y[i] - q.y[i - 1])^2)
                                       end
                                       return se / q.n - math.log(len / L)
                                     end } }
  local r = { snaps = {} }
  for _, tf in ipairs(snap_times) do
    if tf <= t_end then
      sim:at(tf, function()
        local q = s:particles()
        r.snaps[#r.snaps + 1] = { t = tf, x = q.x, y = q.y }
      end)
    end
  end
  local ok, err = pcall(sim.run, sim, { t_end = t_end })
  r.ok, r.t_end = ok, sim.t
  r.outcome = ok and string.format("ran to t = %.2f", sim.t)
    or string.format("tore at t = %.3f (%s)", sim.t, tostring(err):match("tore between its points %d+ and %d+") or "failed")
  r.t, r.theta, r.kink, r.comp = rec:column("t"), rec:column("theta"), rec:column("kink"), rec:column("compressed")
  -- the drift up to t = 1.2 (the tear's own motion after it left out)
  r.drift = 0
  for i, d in ipairs(rec:column("drift")) do
    if r.t[i] <= 1.2 and math.abs(d) > math.abs(r.drift) then r.drift = d end
  end
  local se, ks, nk, amp, amp_fem, cmax = 0, 0, 0, 0, 0, 0
  for i = 1, #r.t do
    local f = barfem.at(fem.t, fem.theta, r.t[i])
    se = se + (r.theta[i] - f)^2
    if r.t[i] <= kink_until then ks, nk = ks + r.kink[i], nk + 1 end
    if r.t[i] > 0.3 then amp, amp_fem = math.max(amp, math.abs(r.theta[i])), math.max(amp_fem, math.abs(f)) end
    cmax = math.max(cmax, r.comp[i])
  end
  r.rms, r.kmean, r.amp, r.amp_fem, r.cmax = math.sqrt(se / #r.t), ks / nk, amp, amp_fem, cmax
  r.hash = sim:hash()
  return r
end

local runs = { without = run(false, "segment", t_end), with = run(true, "segment", t_end),
               without_point = run(false, "point", point_until), with_point = run(true, "point", point_until) }

-- Positions at the snapshot times, as [T] Figs 33 and 38 draw them.
for _, k in ipairs{ {"without", "fig38_positions.png", "Fig 38: 40 points, cell 0.1, without the wrinkle law"},
                    {"with", "fig33_positions.png", "Fig 33: the same with the wrinkle law"} } do
  local r = runs[k[1]]
  local series = {}
  for i, sn in ipairs(r.snaps) do
    series[#series + 1] = { x = sn.x, y = sn.y, markers = true, color = i,
                            label = string.format("t = %.1f", sn.t) }
  end
  series[#series + 1] = { x = {px}, y = {py}, markers = true, color = 8, label = "pivot" }
  lamina.plot{ file = out .. "/" .. k[2], width = 560, height = 470,
               title = k[3] .. (r.ok and "" or string.format(" (torn at t = %.2f)", r.t_end)),
               xlabel = "x", ylabel = "y", xrange = {0, 1.2}, yrange = {0, 1.0}, legend = "bottom left",
               series = series }
end

local w, wi, wp, wip = runs.without, runs.with, runs.without_point, runs.with_point
lamina.plot{ file = out .. "/kinks.png", csv = true, width = 600, height = 340,
             title = "kinks: largest offset of a point from its neighbours' midpoint / spacing",
             xlabel = "t", ylabel = "kink", legend = "top left", yrange = {0, 0.4},
             series = { { x = w.t, y = w.kink, label = "without the law (segments)", color = 2 },
                        { x = wi.t, y = wi.kink, label = "with it (segments)", color = 1 },
                        { x = wp.t, y = wp.kink, label = "without, point form", color = 2, dashed = true },
                        { x = wip.t, y = wip.kink, color = 1, dashed = true,
                          label = "with, point form" .. (wip.ok and "" or string.format(" (tears at t = %.2f)", wip.t_end)) } } }
lamina.plot{ file = out .. "/theta.png", csv = true, width = 600, height = 340,
             title = "angle theta, 40 points, cell 0.1, FLIP, segments", xlabel = "t", ylabel = "theta (deg)",
             legend = "top", yrange = {-22, 34},
             series = { { x = w.t, y = w.theta, label = "MPM without the wrinkle law", color = 2 },
                        { x = wi.t, y = wi.theta, label = "MPM with it", color = 1 },
                        { x = fem.t, y = fem.theta, label = "bar FEM (ours)", dashed = true, color = 8 } } }

local sd, nd = 0, 0
for i = 1, math.min(#w.t, #wi.t) do sd, nd = sd + (w.theta[i] - wi.theta[i])^2, nd + 1 end
local function kv(a, b, upto)
  local ok = a.kmean > b.kmean
  return string.format("%s: mean kink over t <= %.1f %.4f without, %.4f with ([T]: alignment 'not as good' without)",
                       ok and "pass" or "FAIL", upto, a.kmean, b.kmean)
end
-- every run's state in the page's one hash (assets/lua/hashes.lua)
local fold = require("hashes").fold
lamina.report{
  run_without = w.outcome,
  run_with = wi.outcome,
  run_without_point_form = wp.outcome,
  run_with_point_form = wip.outcome,
  kink_mean_without = { w.kmean },
  kink_mean_with = { wi.kmean },
  alignment_worse_without = kv(w, wi, t_end),
  alignment_worse_without_point_form = kv(wp, wip, point_until),
  compressed_points_without = string.format("at most %d of %d points with negative strain at a sample (segments)", w.cmax, n),
  strain_drift_point_form = string.format("%.4f with the law, %.4f without: the points' mean eps_t less ln(l / L) of the string, largest up to t = 1.2",
                                          wip.drift, wp.drift),
  strain_drift_segments = string.format("%.2g with the law, %.2g without", wi.drift, w.drift),
  theta_rms_without_vs_with = { math.sqrt(sd / nd), unit = "deg" },
  theta_rms_without_vs_fem_ours = { w.rms, unit = "deg" },
  theta_rms_with_vs_fem_ours = { wi.rms, unit = "deg" },
  amplitude_without = string.format("%.2f deg; our bar FEM %.2f deg (after t = 0.3, segments)", w.amp, w.amp_fem),
  state_hash = fold{ w.hash, wi.hash, wp.hash, wip.hash },
}
