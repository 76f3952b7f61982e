-- title: Ball and net: a disk caught by a wire and thrown back, with contact-release
-- source: York 1997 (dissertation), §5.9 (Figs 40-42, Table 2) and App. A.1.6
--   (Figs 97-101, Table 11), input deck A.4.13 (Box 16)
-- look: the ball (left) flies into the net, stretches it into a V and is
--   thrown back; with release it leaves the net as its velocity to the left
--   is greatest and then flies at constant speed while the net rings on;
--   with friction (lamina's addition, mu = 0.3) the net holds the ball a
--   little longer (the impact is symmetric, so no spin); each frame's
--   close-up (right) shows the contact normals of the ball and the net at
--   every other node where they meet ([T] Fig 101), with the node's state
--   (grey: moved together, green: released, magenta: slid)
-- checks: the time the ball leaves the net (paper about 2.8: when its
--   velocity settles) and its speed afterwards (paper about -0.7, §5.9), the
--   total energy's spread once it has left (the net keeps ringing); beside
--   them ours, a rigid ball in the potential of a massless string that
--   wraps it (assets/lua/ball_net_ref.lua): it turns at 2.92, settles at
--   4.75 and leaves at -1 (no loss); lamina turns and settles within 1 % of
--   it and leaves at -0.86, nearer -1 on finer cells (-0.92 at 0.125,
--   tests/physics/contact_ball_net_ref.lua) — so this net, not lamina's
--   contact, is why the release comes later than the paper's
-- assumed: the texts disagree (docs/physics.md V10). This page follows App.
--   A.1.6, whose deck it is: a plane-stress ball of radius 1.5 (the deck's
--   rex = 1.5; §5.9's "R = 3" would not fit the deck's 10 x 10 box with the
--   net) at (5.625, 5), v0 = 1, and a uniaxial net (§5.9 has a plane-strain
--   ball and a plane-stress net). The net's own deck (input file 2) is not
--   printed: here a straight net from (7.5, 0) to (7.5, 10), held by the
--   fixed walls at its ends, rho 0.5, E 1e4, thickness 0.0125, three points
--   per cell, tension along segments. Cell 0.25 (41 x 41 nodes), 4 ppc,
--   dt = 1e-3 as the deck, but to t = 6 (the deck stops at 4.02): with this
--   net the ball turns at t = 3 and leaves near t = 4.8, later than the
--   paper's 2.8 and faster (-0.85 against -0.7), so the missing net deck
--   was likely stiffer or tighter than this guess
-- visual: t_end=1.5
-- thumb: ball_velocity.png
local out = lamina.param("out", "out/contact_ball_net")
local t_end = lamina.param("t_end", 6)
local h = 0.25

local ref_turn, ref_settle, _, ref_v, ref_t, ref_vt = require("ball_net_ref").run{
  R = 1.5, mass = math.pi * 1.5 ^ 2, EA = 1e4 * 0.0125, L = 10, xn = 7.5, x0 = 5.625, v0 = 1 }

local function run(law, mu, frames)
  local sim, ball = require("contact_scenes").ball_net{ cell = h, law = law, mu = mu }
  local t, v, e, spin = {}, {}, {}, {}
  local function omega()
    local P = ball:particles()
    local cx, cy = ball:com()
    local vx, vy = ball:velocity()
    local L, I = 0, 0
    for i = 1, #P.x do
      local rx, ry = P.x[i] - cx, P.y[i] - cy
      L = L + P.mass[i] * (rx * (P.vy[i] - vy) - ry * (P.vx[i] - vx))
      I = I + P.mass[i] * (rx * rx + ry * ry)
    end
    return L / I
  end
  local turn
  sim:every(0.02, function(s)
    t[#t + 1], v[#v + 1] = s.t, ball:velocity()
    if not turn and v[#v] < 0 then turn = s.t end
    e[#e + 1] = s:energy().total   -- the net's energy is small beside the ball's
    spin[#spin + 1] = omega()
  end)
  if frames then
    for _, ft in ipairs{0, 1, 2, 3, 4, 5, 6} do
      if ft <= t_end then
        sim:at(ft, function(s)
          -- the whole box, and a close-up of where the ball meets the net
          -- with the contact normals of every other node, 1.5 times their
          -- usual length, so that single arrows can be judged
          -- (docs/gallery.md, "Legibility checklist" 2)
          s:frame{ file = string.format("%s/%s_t%.1f.png", out, law, ft), width = 820, height = 440,
                   title = string.format("%s: t = %.1f", law, ft),
                   panels = { { title = "the box" },
                              { title = "contact normals, close-up", window = {6, 3, 10, 7},
                                contact = { every = 2, scale = 1.5 } } } }
        end)
      end
    end
  end
  sim:run{ t_end = t_end }
  -- the ball has left when its velocity stays within 1 % of v0 of the
  -- final one (free flight; the net only pulls while they touch)
  local left_at = nil
  for i = #v, 1, -1 do
    if math.abs(v[i] - v[#v]) > 0.01 then break end
    left_at = t[i]
  end
  if left_at and left_at >= t[#t] - 0.2 then left_at = nil end   -- not yet
  return { t = t, v = v, e = e, spin = spin, left = left_at, turn = turn, sim = sim }
end

local rel = run("release", nil, true)
local fr = run("friction", 0.3, true)

lamina.plot{ file = out .. "/ball_velocity.png", csv = true,
             title = "Fig 42 / 100: the ball's velocity", xlabel = "t", ylabel = "v_x",
             series = { { x = rel.t, y = rel.v, label = "release" },
                        { x = fr.t, y = fr.v, label = "friction, mu = 0.3", dashed = true },
                        { x = ref_t, y = ref_vt, label = "ours: rigid ball, massless string",
                          dashed = true } } }
lamina.plot{ file = out .. "/energy.png", csv = true, title = "Fig 100: total energy",
             xlabel = "t", ylabel = "energy",
             series = { { x = rel.t, y = rel.e, label = "release" },
                        { x = fr.t, y = fr.e, label = "friction", dashed = true } } }
lamina.plot{ file = out .. "/ball_spin.png", csv = true, title = "The ball's angular velocity", legend = "best",
             xlabel = "t", ylabel = "omega",
             series = { { x = rel.t, y = rel.spin, label = "release" },
                        { x = fr.t, y = fr.spin, label = "friction, mu = 0.3" } } }

-- the ball's energy after it has left: its spread relative to its mean
local function after(r)
  if not r.left then return nil, nil end
  local lo, hi, vs, n = math.huge, -math.huge, 0, 0
  for i = 1, #r.t do
    if r.t[i] >= r.left then
      lo, hi = math.min(lo, r.e[i]), math.max(hi, r.e[i])
      vs, n = vs + r.v[i], n + 1
    end
  end
  return vs / n, (hi - lo) / (0.5 * (hi + lo))
end
local v_rel, spread_rel = after(rel)
local v_fr = after(fr)
print(string.format("release: left the net at t = %s, then v = %s (paper -0.7); friction: "
  .. "left at %s, v = %s, spin %.3f", tostring(rel.left), tostring(v_rel), tostring(fr.left),
  tostring(v_fr), fr.spin[#fr.spin]))
lamina.report{
  release_time = { rel.left or -1, paper = 2.8, ref = ref_settle, tol = 0.3, unit = "t" },
  ball_velocity = { v_rel or 0, paper = -0.7, ref = ref_v, tol = 0.1 },
  turn_time = { rel.turn or -1, ref = ref_turn, tol = 0.02 * ref_turn, unit = "t (ours: rigid ball, massless string)" },
  energy_spread_after = spread_rel and { 100 * spread_rel, unit = "%" } or "not left",
  friction_release_time = fr.left or -1,
  friction_velocity = v_fr or 0,
  friction_spin = fr.spin[#fr.spin],
  state_hash = rel.sim:hash(),
}
