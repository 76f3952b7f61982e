-- title: Offset disks pinching a wire: rotation from no-slip contact
-- source: York, Sulsky & Schreyer 1999 (membranes), §4.4, Fig 23
-- look: the disks, offset vertically, meet the wire from both sides at the
--   same speed and pinch it; while pressed they stick to it (the release
--   law's contact is no-slip) and turn clockwise, as [M] Fig 23 shows.
--   [M] sees them turn counter-clockwise after release, "due to the torque
--   induced by the no-slip contact"; here they leave the wire turning
--   clockwise in 44 of the 46 set-ups tried, the other two within +0.03 of
--   zero (see "checks"). The second run, offset 2.0 (the disks' rims pass
--   0.5, two cells, apart, so the wire alone stops them, at t =
--   0.8, and pushes them back, as [M]'s text tells it), shows why. The
--   no-slip torque on a disk is the difference of the wire's tension just
--   above and just below the stuck patch: the torque plot's dL/dt of disk I
--   and R (T_above - T_below) follow each other. It is clockwise while the
--   disks press in (the span between them, pulled both ways, is the more
--   stretched), then swings with the disk's turning against the two wire
--   spans (period about 0.2) about a mean near zero: omega touches +0.02
--   and +0.04 at t = 0.85 and 1.03, on those swings and still on the wire,
--   but nothing turns the clockwise spin round before the wire lets go
--   (disk II's curves lie on disk I's: the set-up is point-symmetric)
-- checks: each disk's angular velocity (its particles' angular momentum
--   about its centre over their moment of inertia) while pinching (paper:
--   clockwise, < 0) and at the end (paper: counter-clockwise, > 0); for
--   offset 2.0 also disk I's angle turned by the time it stops and by the
--   time it leaves the wire (a contact that gave back what it took would
--   bring it back to 0). Measured beside this page (32 runs: offsets 1.0,
--   1.5, 2.0, 2.5; wire E 1e4 and 1e5; cells 0.25 and 0.125; bases linear
--   and gimp): clockwise while pinching in all (-0.07 to -0.67); at t = 4
--   clockwise in 30, the other two +0.004 and +0.028 (offsets 2.5 and 2.0,
--   where the pinch gives only -0.14 and -0.25); at offset 2.0 with speeds
--   0.5 and 2, wire density 0.1 and 10 or thickness 0.2 (Table II lost its
--   exponents), disk E 1e5 with wire E 1e4 and 1e5, cells 0.25 and 0.125,
--   14 runs: all clockwise at the end (-0.013 to -0.31). Refining does not
--   turn it: at cell 0.0625 (linear, offsets 1.0 / 2.0 / 2.5) -0.63 / -0.20 /
--   -0.07 at the end. Over the way back (disk I's velocity < 0, still on
--   the wire) the torque's integral at offset 2.0 is +0.15 / +0.016 /
--   -0.036 against -0.20 / -0.087 / -0.066 over the way in (cells 0.25 /
--   0.125 / 0.0625): small and of either sign. The runs keep 31-81 % of
--   the energy (merging the fields where they stick is inelastic), and a
--   free disk's spin decays (-0.5 to -0.39 over 3 time units at cell 0.25,
--   to -0.47 at 0.125: the grid transfer); neither turns the sign.
--   The papers' contact-release as printed (sim:contact{test = "eq26",
--   update = "eq21"}: [M] eq 26 once at time level k, and a disk that
--   sticks takes the centre-of-mass acceleration only, its points keeping
--   their own velocity, [M] eqs 20-21) is run at offset 2.0 on the paper's
--   mesh (cell 0.25) and at 0.125, and checked for the turn's sense (the
--   sign of omega, paper: -1 while pinching, +1 after release, [M] §4.4).
--   On the paper's mesh it gives the paper's picture: clockwise while
--   pinching (-0.247), counter-clockwise after release (+0.086 at t = 4;
--   offset 2.5 too, +0.084, measured beside); at cell 0.125 the disks leave
--   clockwise again (-0.105), and with uGIMP at 0.25 at -0.006, and offset
--   1.0 (the first run's) ends at -0.20 on the paper's mesh: the paper's
--   counter-clockwise turn is the printed algorithm on that mesh, not a
--   turn that survives refinement
-- assumed: as contact_disks_wire.lua (the figure gives no dimensions), the
--   disks at (3.9, 5.5) and (6.1, 4.5), both at speed 1 toward the wire;
--   an offset of 1.0 is less than the diameter 1.5, so the disks also meet
--   each other through the wire, which is what turns them back so soon.
--   The second run: the disks at (3.9, 6) and (6.1, 4), offset 2.0
-- visual: t_end=1
-- thumb: omega.png
local out = lamina.param("out", "out/contact_offset_disks")
local t_end = lamina.param("t_end", 4)
local sim, wire, d1, d2 = require("contact_scenes").disks_wire{
  centres = { {3.9, 5.5}, {6.1, 4.5} }, velocities = { {1, 0}, {-1, 0} }, release = true }

-- angular velocity of a body about its centre of mass
local function omega(b)
  local P = b:particles()
  local cx, cy = b:com()
  local vx, vy = b:velocity()
  local L, I = 0, 0
  for i = 1, #P.x do
    local rx, ry = P.x[i] - cx, P.y[i] - cy
    L = L + P.mass[i] * (rx * (P.vy[i] - vy) - ry * (P.vx[i] - vx))
    I = I + P.mass[i] * (rx * rx + ry * ry)
  end
  return L / I
end

local t, w1, w2 = {}, {}, {}
local w_pinch1, w_pinch2 = 0, 0
sim:every(0.01, function(s)
  t[#t + 1], w1[#w1 + 1], w2[#w2 + 1] = s.t, omega(d1), omega(d2)
  if s.t <= 0.5 + 1e-9 then   -- the pinch: the largest turn reached in it
    if math.abs(w1[#w1]) > math.abs(w_pinch1) then w_pinch1 = w1[#w1] end
    if math.abs(w2[#w2]) > math.abs(w_pinch2) then w_pinch2 = w2[#w2] end
  end
end)
for _, ft in ipairs{0, 0.3, 0.5, 1, 2, 4} do
  if ft <= t_end then
    sim:at(ft, function(s)
      s:frame{ file = string.format("%s/frame_t%.1f.png", out, ft), width = 360, height = 300,
               window = {0.5, 2, 9.5, 8}, title = string.format("Fig 23: t = %.1f", ft) }
    end)
  end
end
sim:run{ t_end = t_end }

-- The second run, offset 2.0: disk I's angular momentum L about its centre,
-- its rate dL/dt (the torque of the contact, the only force on it), and
-- the torque the no-slip contact would pass on if the wire's tension were
-- all that acts along it: R (T_above - T_below), T = E thickness et of the
-- wire points in the half-length beyond each end of the stuck patch (the
-- points within 0.75 cell of the disk's rim). A frictionless contact
-- would take no difference of tension across the patch.
local simB, wireB, b1 = require("contact_scenes").disks_wire{
  centres = { {3.9, 6}, {6.1, 4} }, velocities = { {1, 0}, {-1, 0} }, release = true }
local R, reach, EA = 0.75, 0.75 * 0.25, 1e4 * 0.05
local function ang_mom(b)
  local P = b:particles()
  local cx, cy = b:com()
  local vx, vy = b:velocity()
  local L = 0
  for i = 1, #P.x do
    L = L + P.mass[i] * ((P.x[i] - cx) * (P.vy[i] - vy) - (P.y[i] - cy) * (P.vx[i] - vx))
  end
  return L, cx, cy
end
local function tension_torque(cx, cy)
  local W = wireB:particles()
  local lo, hi = math.huge, -math.huge
  for j = 1, #W.x do
    if math.sqrt((W.x[j] - cx) ^ 2 + (W.y[j] - cy) ^ 2) < R + reach then
      lo, hi = math.min(lo, W.y[j]), math.max(hi, W.y[j])
    end
  end
  if lo > hi then return nil end
  local sa, na, sb, nb = 0, 0, 0, 0
  for j = 1, #W.x do
    if W.y[j] > hi and W.y[j] < hi + 0.5 then sa, na = sa + W.et[j], na + 1 end
    if W.y[j] < lo and W.y[j] > lo - 0.5 then sb, nb = sb + W.et[j], nb + 1 end
  end
  return R * EA * (sa / math.max(na, 1) - sb / math.max(nb, 1))
end
local tB, wB, tq, tqT, tT = {}, {}, {}, {}, {}
local L_prev, t_prev = 0, 0
local theta, theta_stop, theta_leave, w_leave, w_pinchB = 0, nil, nil, nil, 0
simB:every(0.01, function(s)
  local L, cx, cy = ang_mom(b1)
  local w = omega(b1)
  tB[#tB + 1], wB[#wB + 1] = s.t, w
  tq[#tq + 1] = (L - L_prev) / (s.t - t_prev)
  L_prev, t_prev = L, s.t
  theta = theta + w * 0.01
  local T = tension_torque(cx, cy)
  if T then
    tT[#tT + 1], tqT[#tqT + 1] = s.t, T
    theta_leave, w_leave = theta, w
  end
  if not theta_stop and b1:velocity() <= 0 then theta_stop = theta end
  if not theta_stop and math.abs(w) > math.abs(w_pinchB) then w_pinchB = w end
end)
simB:at(0.8, function(s)
  s:frame{ file = out .. "/offset2_t0.8.png", width = 360, height = 300, window = {0.5, 2, 9.5, 8},
           title = "offset 2.0: t = 0.8, the disks stopped" }
end)
simB:run{ t_end = t_end }

-- The papers' form as printed, offset 2.0, at the paper's cell and half
-- of it (header): disk I's omega; the largest turn to t = 0.5 (the pinch)
local function printed_run(cell)
  local simP, _, p1, p2 = require("contact_scenes").disks_wire{
    centres = { {3.9, 6}, {6.1, 4} }, velocities = { {1, 0}, {-1, 0} }, release = true,
    test = "eq26", update = "eq21", cell = cell }
  local r = { t = {}, w = {}, pinch = 0, sim = simP }
  simP:every(0.01, function(s)
    local w = omega(p1)
    r.t[#r.t + 1], r.w[#r.w + 1] = s.t, w
    if s.t <= 0.5 + 1e-9 and math.abs(w) > math.abs(r.pinch) then r.pinch = w end
  end)
  simP:run{ t_end = t_end }
  r.w_end, r.w2_end = r.w[#r.w], omega(p2)
  return r
end
local P1, P2 = printed_run(0.25), printed_run(0.125)
local function sign(x) return x > 0 and 1 or (x < 0 and -1 or 0) end

lamina.plot{ file = out .. "/omega.png", csv = true,
             title = "Angular velocity of the disks (> 0: counter-clockwise)", xlabel = "t",
             legend = "bottom right", yrange = { -0.95, 0.3 },   -- room below the curves for the legend
             ylabel = "omega", series = { { x = t, y = w1, label = "disk I (upper, left)" },
                                          { x = t, y = w2, label = "disk II (lower, right)" },
                                          { x = tB, y = wB, label = "disk I, offset 2.0" },
                                          { x = P1.t, y = P1.w, dashed = true,
                                            label = "disk I, offset 2.0, eqs 26/21 as printed" },
                                          { x = P2.t, y = P2.w, dashed = true,
                                            label = "the same, cell 0.125" } } }
lamina.plot{ file = out .. "/torque.png", csv = true, legend = "best",
             title = "Offset 2.0: torque on disk I (> 0: counter-clockwise)", xlabel = "t",
             ylabel = "torque", xrange = { 0.2, 2 },
             series = { { x = tB, y = tq, label = "dL/dt" },
                        { x = tT, y = tqT, label = "R (T_above - T_below)", dashed = true } } }
print(string.format("omega while pinching %.3f / %.3f, at t = %g %.3f / %.3f", w_pinch1,
                    w_pinch2, t_end, w1[#w1], w2[#w2]))
print(string.format("offset 2.0: omega while pinching %.3f, leaving the wire %.3f, at t = %g %.3f; "
  .. "angle turned when stopped %.3f, when leaving %.3f", w_pinchB, w_leave or 0, t_end, wB[#wB],
  theta_stop or 0, theta_leave or 0))
print(string.format("offset 2.0, eqs 26/21 as printed: omega while pinching %.3f, at t = %g %.3f / %.3f "
  .. "(cell 0.25); %.3f, %.3f / %.3f (cell 0.125)", P1.pinch, t_end, P1.w_end, P1.w2_end, P2.pinch,
  P2.w_end, P2.w2_end))
local printed_unit = "sign of omega (-1 clockwise, +1 counter-clockwise), [M] §4.4, Fig 23; "
  .. "offset 2.0, eqs 26 and 20-21 as printed"
lamina.report{
  printed_sense_pinching = { sign(P1.pinch), paper = -1, tol = 0, unit = printed_unit .. ", cell 0.25" },
  printed_sense_after = { sign(P1.w_end), paper = 1, tol = 0, unit = printed_unit .. ", cell 0.25" },
  printed_omega_after = P1.w_end,
  printed_sense_after_cell_0125 = { sign(P2.w_end), paper = 1, tol = 0, unit = printed_unit .. ", cell 0.125" },
  printed_omega_after_cell_0125 = P2.w_end,
  omega_pinch_I = w_pinch1, omega_pinch_II = w_pinch2,
  omega_end_I = w1[#w1], omega_end_II = w2[#w2],
  clockwise_while_pinching = w_pinch1 < 0 and w_pinch2 < 0,
  counter_clockwise_after = w1[#w1] > 0 and w2[#w2] > 0,
  offset2_omega_pinch = w_pinchB, offset2_omega_leaving = w_leave or 0,
  offset2_omega_end = wB[#wB],
  offset2_angle_stopped = { theta_stop or 0, unit = "rad" },
  offset2_angle_leaving = { theta_leave or 0, unit = "rad" },
  -- both set-ups' states (assets/lua/hashes.lua)
  state_hash = require("hashes").fold{ sim:hash(), simB:hash(), P1.sim:hash(), P2.sim:hash() },
}
