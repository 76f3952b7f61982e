-- ball_net_ref.lua - an independent reference for the ball and net (ours,
-- issue 14): a rigid ball against a massless elastic string, quasi-static.
--
-- The net (length L, stiffness EA, unstressed and straight between its two
-- anchors) is far lighter than the ball (0.5 x 0.0125 x 10 = 0.0625 against
-- 7.07 in contact_ball_net.lua) and its waves cross it in a fraction of the
-- contact time (transverse ~0.1 of ~5 s, longitudinal ~0.04), so at each
-- instant it is in equilibrium: two straight runs from the anchors,
-- tangent to the ball, and the arc it wraps, frictionless, one tension
-- throughout, EA (l - L) / L. Its energy 1/2 EA (l - L)^2 / L is a function
-- of the ball's position alone, and the ball moves in that potential:
-- M x'' = -dU/dx, integrated here with a small step. Neglected: the net's
-- mass (1 %), the ball's deformation (its contact force of ~10 squeezes it
-- by ~1e-3 against a stroke of ~2), and the no-slip the release law
-- imposes while the two press together (it shares the tension unevenly over
-- the wrap). Conservative: the ball leaves at its impact speed.
local M = {}

-- The net's length with the ball's centre at x (anchors at (xn, y0 - L/2)
-- and (xn, y0 + L/2), the ball's centre at height y0): straight while the
-- ball is clear of it, else the two tangents and the arc between.
local function length(x, o)
  local u, half, R = x - o.xn, o.L / 2, o.R
  if u <= -R then return o.L end
  local D = math.sqrt(u * u + half * half)
  -- angle of the lower tangent point from the centre, measured from +x:
  -- the anchor's direction turned by the tangent angle
  local a = math.atan(-half, -u) + math.acos(R / D)
  return 2 * math.sqrt(D * D - R * R) + 2 * R * (-a)
end

-- o: R, mass, EA, L, xn (the net's line), x0 (the centre at t0, clear of
-- the net), v0 (> 0, towards it), t0, dt. Returns the time the ball turns,
-- the time after which its velocity stays within o.settle (0.01) of the
-- final one (as contact_ball_net.lua measures the release), the time it
-- clears the net, its final velocity, and its velocity history (times and
-- velocities, every o.every, 0.02).
function M.run(o)
  local function U(x)
    local e = (length(x, o) - o.L) / o.L
    return e > 0 and 0.5 * o.EA * e * e * o.L or 0
  end
  local dt, eps = o.dt or 1e-4, 1e-7
  local x, v, t = o.x0, o.v0, o.t0 or 0
  local hist_t, hist_v, turn = {}, {}, nil
  local out_t, out_v, every, next_out = { t }, { v }, o.every or 0.02, t + (o.every or 0.02)
  repeat
    local f = -(U(x + eps) - U(x - eps)) / (2 * eps)
    v = v + dt * f / o.mass          -- symplectic Euler: the energy stays bounded
    x = x + dt * v
    t = t + dt
    if not turn and v < 0 then turn = t end
    hist_t[#hist_t + 1], hist_v[#hist_v + 1] = t, v
    if t >= next_out - dt / 2 then
      out_t[#out_t + 1], out_v[#out_v + 1], next_out = t, v, next_out + every
    end
  until turn and x - o.xn <= -o.R
  local settle, vf, settled = o.settle or 0.01, v, nil
  for i = #hist_v, 1, -1 do
    if math.abs(hist_v[i] - vf) > settle then break end
    settled = hist_t[i]
  end
  return turn, settled, t, vf, out_t, out_v
end

return M
