-- title: Ball and net: a disk caught by a wire and thrown back, with contact-release
-- source: York 1997 (dissertation), §5.9 (Figs 40-42, Table 2) and App. A.1.6
--   (Figs 97-100, Table 11), input deck A.4.13 (Box 16); the close-ups draw
--   the grid normals too, whose page, with checks, is contact_normals
-- look: the ball (left) flies into the net, stretches it into a V and is
--   thrown back; with release it leaves the net as its velocity to the left
--   is greatest and then flies at constant speed while the net rings on;
--   with friction (lamina's addition, mu = 0.3) the net holds the ball a
--   little longer (the impact is symmetric, so no spin); each frame's
--   close-up (right) shows the contact normals of the ball and the net at
--   every other node where they meet ([T] Fig 101), with the node's state
--   (grey: moved together, green: released, magenta: slid)
-- checks: the time the ball leaves the net (paper: "at about t=2.8 the ball
--   releases", [T] §5.9, Figs 41-42) and its speed afterwards (paper:
--   "constant at about -0.7", §5.9, Fig 42), each within 0.05, half the
--   printed last digit (as contact_two_bar reads [T]'s "about 0.3"; it was
--   10 % of the value, ours); the
--   total energy's spread once it has left (the net keeps ringing); beside
--   them ours, a rigid ball in the potential of a massless string that
--   wraps it (assets/lua/ball_net_ref.lua), for this ball and net: it turns
--   at 3.91, settles at 6.43 and leaves at -1 (no loss); the turn is checked
--   against it within 2 % (what the reference leaves out: the net's mass,
--   0.2 % of the ball's, and the ball's squeeze; tests/physics/
--   contact_ball_net_ref.lua checks the deck's ball so). Measured: lamina
--   turns at 3.82, 2.3 % before ours (a miss, shown: the contact begins up
--   to a cell before the ball's edge reaches the net, and with this ball's
--   longer stroke that moves the turn more than the deck ball's 1 %),
--   settles at 6.04 and leaves at -0.85; the paper's 2.8 and -0.7 missed
--   Beside them, checked against the same two numbers: the papers'
--   contact-release as printed (sim:contact{test = "eq26", update =
--   "eq21"}; §5.9 names [T] eq 9.9, both bodies against the centre of mass,
--   which is eq 26's test), for this ball: leaves at 5.86 at -0.895; and
--   the deck's own ball (A.4.13, Box 16: R = 1.5 at (5.625, 5), the net at
--   the box's x = 7.5) with lamina's release: it turns at 2.90 and leaves
--   at 4.70 at -0.864, with ours (2.92, 4.75) - so the deck's ball turns
--   about when the text says it leaves. Derived: for ours to leave at the
--   text's 2.8, the net would need about 10 times Table 11's EA = 125
--   (computed on the page by bisection), so the net's unprinted deck was not
--   Table 11's plain unstressed net; and a ball that leaves at -0.7 has lost
--   half its kinetic energy, which no contact form here loses (lamina -0.85,
--   as printed -0.90, ours -1)
-- assumed: the texts disagree (docs/physics.md V10). App. A.1.6 says "a disk
--   (called a ball) of radius R=3" and the page follows the text (issue 32):
--   a plane-stress ball of radius 3, v0 = 1, and a uniaxial net (§5.9 has a
--   plane-strain ball and a plane-stress net). The deck (A.4.13, Box 16) has
--   rex = 1.5 at (5.625, 5): its R = 3 may be the diameter. A ball of radius
--   3 does not fit the deck's 10 x 10 box beside a net at the deck's
--   position, so here the ball sits at (3.625, 5) and the net at x = 7, the
--   same 0.375 gap as the deck's ball to a net at 7.5: the ball's stroke
--   (2.7, from ours) then ends 0.3 short of the right wall. The net's own
--   deck (input file 2) is not printed: here a straight net from (7, 0) to
--   (7, 10), held by the fixed walls at its ends, rho 0.5, E 1e4, thickness
--   0.0125, three points per cell, tension along segments. Cell 0.25
--   (41 x 41 nodes), 4 ppc, dt = 1e-3 as the deck, but to t = 8.2 (the deck
--   stops at 4.02; the ball, four times the deck's mass, turns only at
--   3.9), stopped before the ball reaches the left wall. With this net the
--   ball leaves later than the paper's 2.8 and faster than its -0.7, so the
--   missing net deck was likely stiffer or tighter than this guess
-- visual: t_end=1.5
-- thumb: ball_velocity.png
local out = lamina.param("out", "out/contact_ball_net")
local t_end = lamina.param("t_end", 8.2)
local h = 0.25
-- the text's ball (App. A.1.6: R = 3) and where it fits the box (header)
local R, x0, xn = 3, 3.625, 7.0

local ref_turn, ref_settle, _, ref_v, ref_t, ref_vt = require("ball_net_ref").run{
  R = R, mass = math.pi * R ^ 2, EA = 1e4 * 0.0125, L = 10, xn = xn, x0 = x0, v0 = 1 }

-- o: another ball or form than the page's (R, x0, xn, test, update, t_end)
local function run(law, mu, frames, o)
  o = o or {}
  local sim, ball = require("contact_scenes").ball_net{ cell = h, law = law, mu = mu, R = o.R or R,
    x0 = o.x0 or x0, xn = o.xn or xn, test = o.test, update = o.update }
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
    for _, ft in ipairs{0, 2, 4, 6, 8} do
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
  sim:run{ t_end = o.t_end or t_end }
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
-- the papers' form as printed (header), the page's ball; to t = 7.4: it
-- comes back faster and nears the left wall sooner (measured: slowed by it
-- from t = 7.6)
local printed = run("release", nil, false, { test = "eq26", update = "eq21", t_end = 7.4 })
-- the deck's ball (A.4.13, Box 16: rex = 1.5 at (5.625, 5)) against a net
-- at the deck box's x = 7.5, lamina's release; to t = 6.5, before it
-- reaches the left wall; beside it ours for it, and the stiffness the net
-- would need for ours to leave at the paper's t = 2.8 (EA times k, by
-- bisection on k: the reference's release time falls as k grows)
local deck = run("release", nil, false, { R = 1.5, x0 = 5.625, xn = 7.5, t_end = 6.5 })
local function deck_ref(k)
  return require("ball_net_ref").run{ R = 1.5, mass = math.pi * 1.5 ^ 2, EA = 1e4 * 0.0125 * k,
                                      L = 10, xn = 7.5, x0 = 5.625, v0 = 1 }
end
local deck_turn_ref, deck_settle_ref = deck_ref(1)
local k_lo, k_hi = 1, 64
for _ = 1, 20 do
  local k = math.sqrt(k_lo * k_hi)
  local _, settle = deck_ref(k)
  if settle > 2.8 then k_lo = k else k_hi = k end
end
local k_28 = math.sqrt(k_lo * k_hi)

lamina.plot{ file = out .. "/ball_velocity.png", csv = true,
             title = "Fig 42 / 100: the ball's velocity", xlabel = "t", ylabel = "v_x",
             series = { { x = rel.t, y = rel.v, label = "release" },
                        { x = fr.t, y = fr.v, label = "friction, mu = 0.3", dashed = true },
                        { x = printed.t, y = printed.v, label = "release, eqs 26/21 as printed", dashed = true },
                        { x = deck.t, y = deck.v, label = "the deck's ball (R = 1.5), release" },
                        { x = ref_t, y = ref_vt, label = "ours (R = 3): rigid ball, massless string",
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
local v_printed = after(printed)
local v_deck = after(deck)
print(string.format("eqs 26/21 as printed: left the net at t = %s, then v = %s; the deck's ball: turns "
  .. "at %s (ours %.3f), leaves at %s (ours %.3f), v = %s; ours leaves at 2.8 with the net's EA x %.2f",
  tostring(printed.left), tostring(v_printed), tostring(deck.turn), deck_turn_ref, tostring(deck.left),
  deck_settle_ref, tostring(v_deck), k_28))
print(string.format("release: left the net at t = %s, then v = %s (paper -0.7); friction: "
  .. "left at %s, v = %s, spin %.3f", tostring(rel.left), tostring(v_rel), tostring(fr.left),
  tostring(v_fr), fr.spin[#fr.spin]))
lamina.report{
  -- [T] §5.9: "at about t=2.8", "constant at about -0.7"; half the last
  -- printed digit each (header)
  release_time = { rel.left or -1, paper = 2.8, ref = ref_settle, tol = 0.05, unit = "t (tol: half the printed digit)" },
  ball_velocity = { v_rel or 0, paper = -0.7, ref = ref_v, tol = 0.05, unit = "(tol: half the printed digit)" },
  turn_time = { rel.turn or -1, ref = ref_turn, tol = 0.02 * ref_turn, unit = "t (ours: rigid ball, massless string)" },
  energy_spread_after = spread_rel and { 100 * spread_rel, unit = "%" } or "not left",
  printed_release_time = { printed.left or -1, paper = 2.8, tol = 0.05,
                           unit = "t, eqs 26 and 20-21 as printed (tol: half the printed digit)" },
  printed_ball_velocity = { v_printed or 0, paper = -0.7, tol = 0.05,
                            unit = "eqs 26 and 20-21 as printed (tol: half the printed digit)" },
  deck_release_time = { deck.left or -1, paper = 2.8, ref = deck_settle_ref, tol = 0.05,
                        unit = "t, the deck's ball R = 1.5 (tol: half the printed digit)" },
  deck_ball_velocity = { v_deck or 0, paper = -0.7, ref = -1, tol = 0.05,
                         unit = "the deck's ball (tol: half the printed digit)" },
  deck_turn_time = { deck.turn or -1, ref = deck_turn_ref, tol = 0.02 * deck_turn_ref,
                     unit = "t, the deck's ball (ours: rigid ball, massless string)" },
  net_stiffness_for_2_8 = { k_28, unit = "x Table 11's EA: ours (rigid ball, the deck's) leaves at t = 2.8" },
  friction_release_time = fr.left or -1,
  friction_velocity = v_fr or 0,
  friction_spin = fr.spin[#fr.spin],
  -- both runs' states (assets/lua/hashes.lua)
  state_hash = require("hashes").fold{ rel.sim:hash(), fr.sim:hash(), printed.sim:hash(), deck.sim:hash() },
}
