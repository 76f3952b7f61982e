-- title: Offset disks pinching a wire: rotation from no-slip contact
-- source: York, Sulsky & Schreyer 1999 (membranes), §4.4, Fig 23
-- look: the disks, offset vertically, meet the wire from both sides at the
--   same speed and pinch it; while pressed they stick to it (the release
--   law's contact is no-slip) and start to turn clockwise; the stretched
--   wire and the disks' own collision through it push them apart again.
--   [M] sees them turn counter-clockwise after release; here they keep
--   turning clockwise, more slowly (the angular-velocity plot; the set-up is
--   point-symmetric, so the two curves lie on each other)
-- checks: each disk's angular velocity (its particles' angular momentum
--   about its centre over their moment of inertia) while pinching (paper:
--   clockwise, < 0) and at the end (paper: counter-clockwise, > 0)
-- assumed: as contact_disks_wire.lua (the figure gives no dimensions), the
--   disks at (3.9, 5.5) and (6.1, 4.5), both at speed 1 toward the wire;
--   an offset of 1.0 is less than the diameter 1.5, so the disks also meet
--   each other through the wire, which is what turns them back so soon
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

lamina.plot{ file = out .. "/omega.png", csv = true,
             title = "Angular velocity of the disks (> 0: counter-clockwise)", xlabel = "t",
             ylabel = "omega", series = { { x = t, y = w1, label = "disk I (upper, left)" },
                                          { x = t, y = w2, label = "disk II (lower, right)" } } }
print(string.format("omega while pinching %.3f / %.3f, at t = %g %.3f / %.3f", w_pinch1,
                    w_pinch2, t_end, w1[#w1], w2[#w2]))
lamina.report{
  omega_pinch_I = w_pinch1, omega_pinch_II = w_pinch2,
  omega_end_I = w1[#w1], omega_end_II = w2[#w2],
  clockwise_while_pinching = w_pinch1 < 0 and w_pinch2 < 0,
  counter_clockwise_after = w1[#w1] > 0 and w2[#w2] > 0,
  state_hash = sim:hash(),
}
