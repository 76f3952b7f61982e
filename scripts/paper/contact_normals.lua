-- title: Contact grid normals from the colour function: a bar's face, and a ball and net
-- source: York, Sulsky & Schreyer 1999 (membranes), §4.1, Fig 19; York 1997
--   (dissertation), App. A.1.4 and A.1.6, Figs 94 and 101
-- look: the normals the release test reads ([M] eqs 27-28, [T] eq 9.11:
--   each body's colour spread to the cell centres with the quadratic
--   B-spline, its gradient taken to the nodes) at the nodes where two bodies
--   meet, as the papers show only "the pertinent normals". Left: the two
--   bars of contact_two_bar at the step they first share nodes (t = 0.1575),
--   each bar's normals (its colour) pointing out of its face, square to it
--   along the face and tilted at the corners. Right: the deck's ball and net
--   ([T] A.4.13) at t = 1, the ball's normals pointing out of the ball and
--   the net's away from the net on both of its sides - the net's "effective
--   thickness" ([T] A.1.6). Arrows 2 (bars) and 1.5 (ball, net) times their
--   usual 0.6 cell, node marks grey: moved together, green: released
-- checks: along the bars' faces, at least two cells from their ends, the
--   largest angle of a bar's normal from its face normal (+x for the left
--   bar, -x for the right) against ours, 0: the bars' points are still the
--   uniform lattice they were seeded on, whose colour is the same at every
--   height there (the quadratic B-spline sums to one over a lattice), so
--   the gradient is square to the face - to round-off (1e-12 rad). Of the
--   net's normals at the ball's contact nodes, the share pointing away from
--   the net (from its nearest point) and the number of the net's sides that
--   have some, against [T] A.1.6's "the normals from the membrane are
--   directed outward from both sides of the membrane" (1 and 2, exact); of
--   the ball's, the share pointing away from its centre (ours: 1, exact),
--   with their largest angle from the radial direction printed (the colour
--   of a disk cut from a lattice is not round: several degrees)
-- assumed: contact_two_bar's bars ([T] A.4.12) and the deck's ball and net
--   of contact_scenes.ball_net ([T] A.4.13, Box 16: R = 1.5 at (5.625, 5);
--   the net, whose deck is not printed, straight and unstressed at x = 7.5),
--   both on the bilinear basis at cell 0.25 with law "release"
-- thumb: normals.png
local out = lamina.param("out", "out/contact_normals")
local scenes = require("contact_scenes")

-- the bars: the first step at which they share nodes
local bars, left, right = scenes.two_bar{ release = true }
local face = {}
bars:every(7e-4, function(s)
  if face.t then return end
  local c = s:contact_info()
  if not (c and c.stick + c.release > 0) then return end
  face.t = s.t
  for _, b in ipairs{ { left, 1, "left" }, { right, -1, "right" } } do
    local N = s:contact_normals(b[1])
    local worst, n = 0, 0
    for i = 1, #N.x do
      -- two cells clear of the bars' ends (y = 0.25, 4.75)
      if N.y[i] >= 0.75 - 1e-9 and N.y[i] <= 4.25 + 1e-9 then
        worst = math.max(worst, math.abs(math.atan(N.ny[i], b[2] * N.nx[i])))
        n = n + 1
      end
    end
    face[b[3]] = { worst = worst, n = n, all = #N.x }
  end
  s:frame{ file = out .. "/bars.png", width = 420, height = 600, window = { 1.75, 0, 3.5, 5 },
           contact = { every = 1, scale = 2 },
           title = string.format("Fig 19 / 94: the bars' normals, t = %.4f", s.t) }
end)
bars:run{ t_end = 0.2 }

-- the deck's ball and net at t = 1
local sim, ball, net = scenes.ball_net{}
local bn = {}
sim:at(1.0, function(s)
  local cx, cy = ball:com()
  local NB, NN, W = s:contact_normals(ball), s:contact_normals(net), net:particles()
  bn.ball_n, bn.ball_out, bn.ball_worst = #NB.x, 0, 0
  for i = 1, #NB.x do
    local dx, dy = NB.x[i] - cx, NB.y[i] - cy
    local c = (NB.nx[i] * dx + NB.ny[i] * dy) / math.sqrt(dx * dx + dy * dy)
    if c > 0 then bn.ball_out = bn.ball_out + 1 end
    bn.ball_worst = math.max(bn.ball_worst, math.deg(math.acos(math.min(1, c))))
  end
  bn.net_n, bn.net_out, bn.left, bn.right = #NN.x, 0, 0, 0
  for i = 1, #NN.x do
    local best, bj = math.huge, 1
    for j = 1, #W.x do
      local d = (W.x[j] - NN.x[i]) ^ 2 + (W.y[j] - NN.y[i]) ^ 2
      if d < best then best, bj = d, j end
    end
    local dx, dy = NN.x[i] - W.x[bj], NN.y[i] - W.y[bj]
    if NN.nx[i] * dx + NN.ny[i] * dy > 0 then bn.net_out = bn.net_out + 1 end
    if dx < 0 then bn.left = bn.left + 1 else bn.right = bn.right + 1 end
  end
  s:frame{ file = out .. "/normals.png", width = 820, height = 440,
           title = "Fig 101: the ball's and the net's normals, t = 1",
           panels = { { title = "the box" },
                      { title = "close-up", window = { 6, 3, 9, 7 },
                        contact = { every = 1, scale = 1.5 } } } }
end)
sim:run{ t_end = 1.0 }

print(string.format("bars at t = %.4f: left %d of %d nodes off the ends, worst %.3g rad; right %d "
  .. "of %d, worst %.3g rad", face.t, face.left.n, face.left.all, face.left.worst, face.right.n,
  face.right.all, face.right.worst))
print(string.format("ball and net at t = 1: ball %d of %d outward (worst %.1f deg from radial); "
  .. "net %d of %d away from it, %d on its left, %d on its right", bn.ball_out, bn.ball_n,
  bn.ball_worst, bn.net_out, bn.net_n, bn.left, bn.right))
lamina.report{
  bar_face_left = { face.left.worst, ref = 0, tol = 1e-12,
    unit = "rad, largest angle from +x two cells off the ends (ours: the lattice's colour)" },
  bar_face_right = { face.right.worst, ref = 0, tol = 1e-12,
    unit = "rad, largest angle from -x two cells off the ends (ours: the lattice's colour)" },
  bar_face_nodes = face.left.n + face.right.n,
  first_contact = { face.t, unit = "t" },
  net_outward = { bn.net_n > 0 and bn.net_out / bn.net_n or -1, paper = 1, tol = 0,
    unit = "of the net's normals at t = 1 ([T] A.1.6: 'directed outward')" },
  net_sides = { (bn.left > 0 and 1 or 0) + (bn.right > 0 and 1 or 0), paper = 2, tol = 0,
    unit = "sides of the net with normals ([T] A.1.6: 'from both sides of the membrane')" },
  ball_outward = { bn.ball_n > 0 and bn.ball_out / bn.ball_n or -1, ref = 1, tol = 0,
    unit = "of the ball's normals at t = 1 pointing away from its centre" },
  ball_worst_from_radial = { bn.ball_worst, unit = "degrees" },
  state_hash = require("hashes").fold{ bars:hash(), sim:hash() },
}
