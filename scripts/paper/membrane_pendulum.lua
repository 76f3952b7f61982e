-- title: Pendulum: a string swinging through the grid, four refinements
-- source: York, Sulsky & Schreyer 1999 (membranes), §3.1.2, Figs 8-12;
--   York's dissertation §5.7, Figs 31-37, Table 1, Boxes 6-7
-- look: the string swings laterally through the Cartesian grid and stays
--   straight; theta(t) approaches the dashed bar-element FEM curve as the
--   grid is refined, with a little amplitude loss that shrinks; Fig 11: the
--   FEM's nodes at the same times, joined as bars, the string straight
-- checks: rms error of theta(t) against the FEM falls with every refinement;
--   swing amplitude at the finest grid against the FEM's, within the
--   finest's own error estimate (first order: its difference from the run
--   at twice the cell, Richardson; it was 10 %, not derived); the FEM's
--   theta with 40 elements against 20 ([M]: the FEM solution "does not
--   change if a larger number of elements is used")
-- assumed: the papers disagree on rho and thickness (same mass per length,
--   EA 10x apart): we use the dissertation's rho = 0.1, t = 0.1 with its
--   point counts 20/40/80/320 and dt = 0.63 dt_c. With [M] Table I's
--   rho = 1, t = 0.01 the light string's cell-crossing noise grows under
--   pure FLIP; even here it does at cells <= 0.05 (the run fails near
--   t = 1.2), so every refinement uses a 0.1 % PIC blend (pic = 0.001).
--   The cause (membrane_pendulum_no_wrinkle's page): under the one-way law
--   the point form's strains, sums of the grid's noisy t.de.t, ratchet
--   down, since only a positive error is pushed back by its stress; the
--   points by the end mass go slack and it pulls the string apart. The
--   segment form (strain from the points' spacing) has no drift, but also
--   none of the papers' amplitude loss (0.17-0.31 deg rms at every cell
--   without PIC): the papers' convergence is shown on their point form.
--   The pivot is the first point, on the fixed top wall.
-- visual: finest=0.1
-- thumb: fig12_theta.png
local out = lamina.param("out", "out/membrane_pendulum")
local finest = lamina.param("finest", 0.025)
local barfem = require("barfem")

local E, L, m, g, th0, rho, t = 1e6, 0.73, 3.3, 20, 19.8, 0.1, 0.1
local c = math.sqrt(E / rho)
local px, py = 0.6, 1.0
local mx, my = px + L * math.sin(math.rad(th0)), py - L * math.cos(math.rad(th0))
local T_end = 1.8

local fem = barfem.run{ from = {px, py}, to = {mx, my}, elements = 20, rho = rho, A = t, E = E,
                        end_mass = m, g = {0, -g}, one_way = true, t_end = T_end,
                        every = 1e-3, safety = 0.9, snapshots = {0, 0.3, 0.6, 0.9, 1.2, 1.5} }
-- [M] §3.1.2: "The finite element solution does not change if a larger
-- number of elements is used": the same with twice the elements
local fem40 = barfem.run{ from = {px, py}, to = {mx, my}, elements = 40, rho = rho, A = t, E = E,
                          end_mass = m, g = {0, -g}, one_way = true, t_end = T_end,
                          every = 1e-3, safety = 0.9 }
local fem_change = 0
for i = 1, #fem.t do
  fem_change = math.max(fem_change, math.abs(fem.theta[i] - barfem.at(fem40.t, fem40.theta, fem.t[i])))
end
print(string.format("bar FEM, 20 against 40 elements: theta differs by at most %.3f deg", fem_change))

-- Fig 11: the FEM's nodes at the frames' times, joined as the bars they are
local fseries = {}
for i, sn in ipairs(fem.snaps) do
  fseries[#fseries + 1] = { x = sn.x, y = sn.y, color = i }
  fseries[#fseries + 1] = { x = sn.x, y = sn.y, markers = true, color = i,
                            label = string.format("t = %.1f", sn.t) }
end
lamina.plot{ file = out .. "/fig11_fem.png", width = 480, height = 400,
             title = "Fig 11: bar-element FEM (ours), 20 elements", xlabel = "x", ylabel = "y",
             xrange = {0, 1.2}, yrange = {0, 1.0}, legend = "bottom left", series = fseries }

local series, report, hashes = {}, {}, {}
local prev_err, prev_amp
for _, r in ipairs{ {0.2, 20}, {0.1, 40}, {0.05, 80}, {0.025, 320} } do
  local h, n = r[1], r[2]
  if h < finest - 1e-12 then break end
  local sim = lamina.sim{ basis = "linear", domain = {0, 0, 1.2, 1.0}, cell = h, dt = 0.63 * h / c,
                          gravity = {0, -g}, pic = 0.001 }
  local wire = lamina.membrane{ rho = rho, E = E, nu = 0, thickness = t, one_way = true }
  local s = sim:membrane{ force = "point", material = wire, count = n, end_mass = m, name = "string",
                          curve = lamina.segment{ from = {px, py}, to = {mx, my} } }
  local rec = sim:record{ every = 1e-3, angle = { theta = s },
                          file = string.format("%s/theta_cell%.3f.csv", out, h) }
  for _, tf in ipairs{0, 0.3, 0.6, 0.9, 1.2, 1.5} do
    sim:at(tf, function(sm)
      -- the window reaches 0.1 above the domain, whose top edge the pivot
      -- is on, so that its disc stays clear of the title (issue 32)
      sm:frame{ file = string.format("%s/cell%.3f_t%.1f.png", out, h, tf), width = 480, height = 400,
                discs = "spacing", window = {0, 0, 1.2, 1.1},
                title = string.format("cell %.3f, %d points", h, n) }
    end)
  end
  sim:run{ t_end = T_end }
  local ts, th = rec:column("t"), rec:column("theta")
  local se, amp, amp_fem = 0, 0, 0
  for i = 1, #ts do
    local f = barfem.at(fem.t, fem.theta, ts[i])
    se = se + (th[i] - f)^2
    if ts[i] > 0.3 then amp, amp_fem = math.max(amp, math.abs(th[i])), math.max(amp_fem, math.abs(f)) end
  end
  local err = math.sqrt(se / #ts)
  print(string.format("cell %.3f, %d points: rms theta error %.3f deg, amplitude %.2f (FEM %.2f)",
                      h, n, err, amp, amp_fem))
  series[#series + 1] = { x = ts, y = th, label = string.format("MPM cell %.3f", h) }
  report[string.format("rms_err_cell_%.3f", h)] = { err, unit = "deg" }
  report[string.format("amplitude_cell_%.3f", h)] = { amp, unit = "deg (FEM " .. string.format("%.2f", amp_fem) .. ")" }
  -- tol (issue 32 item 3; it was 10 %, not derived: [M] and [T] print no
  -- number for the amplitude loss): the scheme is first order, so the
  -- finest run's error is about its difference from the run at twice its
  -- cell (Richardson, p = 1); within it, the MPM converges to the FEM at
  -- least as fast as first order. Measured: 19.53 at 0.025, 19.00 at 0.05,
  -- tol 0.53 deg against a miss of 0.27 (the loss 2.79 / 0.65 / 0.80 / 0.27
  -- deg at cells 0.2 / 0.1 / 0.05 / 0.025 does not fall at 0.05)
  if prev_amp then
    report.amplitude_finest = { amp, ref = amp_fem, unit = "deg (tol: Richardson, |A(h) - A(2h)|)",
                                tol = math.abs(amp - prev_amp) }
  end
  prev_amp = amp
  report.error_falls = (prev_err == nil) and true or (report.error_falls and err < prev_err)
  prev_err = err
  hashes[#hashes + 1] = sim:hash()
end
series[#series + 1] = { x = fem.t, y = fem.theta, label = "bar-element FEM", dashed = true, color = 8 }
lamina.plot{ file = out .. "/fig12_theta.png", csv = true, title = "Fig 12: angle theta",
             xlabel = "t", ylabel = "theta (deg)", legend = "bottom left", series = series }
report.fem_20_vs_40_elements = { fem_change, unit = "deg, largest theta difference ([M]: 'does not change')" }
-- every refinement's state (assets/lua/hashes.lua)
report.state_hash = require("hashes").fold(hashes)
lamina.report(report)
