-- The ball and net of [T] §5.9 / A.1.6 as contact_ball_net.lua sets it up
-- (plane-stress ball of radius 1.5 at speed 1, a straight unstressed
-- uniaxial net at x = 7.5, contact-release), against our quasi-static
-- reference: a rigid ball in the potential of a massless elastic string
-- that wraps it (assets/lua/ball_net_ref.lua): it turns at t = 2.924, its
-- velocity settles within 0.01 of the final one at 4.746, and it leaves at
-- its impact speed, -1. The paper's release at about 2.8 and -0.7 are for a
-- net whose deck is not printed (docs/physics.md V10); they are the page's
-- (not reached, shown there).
-- Checks, at cells 0.25 (the deck's) and 0.125:
--  * the turning time and the settling time within 2 % of the reference's:
--    what it leaves out is about 1 % (the net's mass beside the ball's) or
--    less (the ball's squeeze, ~1e-3 of a stroke of ~2; the contact
--    beginning up to a cell early matters little where the string's force
--    grows as the cube of the stroke);
--  * the speed it leaves with approaches 1 with refinement: the contact's
--    loss (the merging of the fields where they stick, O(h) as in the
--    two-bar impact) shrinks.
local ref = require("ball_net_ref")
local r_turn, r_settle, _, r_v = ref.run{ R = 1.5, mass = math.pi * 1.5 ^ 2, EA = 1e4 * 0.0125,
                                          L = 10, xn = 7.5, x0 = 5.625, v0 = 1 }
local function mpm(h)
  local sim, ball = require("contact_scenes").ball_net{ cell = h }
  local t, v, turn = {}, {}, nil
  sim:every(0.01, function(s)
    local vx = ball:velocity()
    t[#t + 1], v[#v + 1] = s.t, vx
    if not turn and vx < 0 then turn = s.t end
  end)
  sim:run{ t_end = 6 }
  local settled
  for i = #v, 1, -1 do
    if math.abs(v[i] - v[#v]) > 0.01 then break end
    settled = t[i]
  end
  return turn, settled, v[#v]
end
local err = {}
for k, h in ipairs{ 0.25, 0.125 } do
  local turn, settled, vf = mpm(h)
  print(string.format("cell %g: turns at %.3f (ours %.3f), settles at %.3f (ours %.3f), "
    .. "leaves at %.4f (ours %.4f)", h, turn, r_turn, settled, r_settle, vf, r_v))
  assert(math.abs(turn / r_turn - 1) <= 0.02, "turning time " .. turn)
  assert(math.abs(settled / r_settle - 1) <= 0.02, "settling time " .. settled)
  err[k] = math.abs(vf - r_v)
end
assert(err[2] < err[1], "the speed it leaves with does not approach the reference's")
