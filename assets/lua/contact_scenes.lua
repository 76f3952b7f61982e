-- contact_scenes.lua - the contact set-ups that gallery pages, tests and
-- measurements share (issue 14), so that each is written once.
--   * two_bar: [M] §4.1-4.2 / [T] A.4.12's deck: bars [1, 2.25] and
--     [2.75, 4] x [0.25, 4.75] on a 5 x 5 domain, 4 ppc, E 1e5, nu 0.3,
--     plane stress, the left one at 2; dt 7e-4 at cell 0.25, scaled with
--     the cell (the deck's Courant number);
--   * disks_wire: [M] §4.3-4.4's wire pinned at both ends between two
--     disks (the figures give no dimensions: scripts/paper/contact_disks_wire.lua
--     says what was assumed), the disks' centres and velocities given;
--   * incline: a block on a pinned plane with friction, gravity tilted by
--     theta (issue 14 item 5; Bardenhagen et al. 2001's check), and slide,
--     its measured acceleration against g (sin theta - mu cos theta).
local M = {}

-- o.cell (0.25), o.basis ("linear"), o.threads, o.release (sim:contact
-- law "release" between the bars), o.test and o.update (sim:contact's:
-- "eq26" and "eq21" run the papers' form as printed). Returns sim, left, right.
function M.two_bar(o)
  local cell = o.cell or 0.25
  local sim = lamina.sim{ basis = o.basis or "linear", domain = {0, 0, 5, 5}, cell = cell,
                          dt = 7e-4 * cell / 0.25, threads = o.threads }
  local mat = lamina.elastic{ rho = 1, E = 1e5, nu = 0.3, plane = "stress" }
  local l = sim:body{ material = mat, ppc = 4, velocity = {2, 0}, name = "left",
                      region = lamina.rect{ min = {1, 0.25}, max = {2.25, 4.75} } }
  local r = sim:body{ material = mat, ppc = 4, name = "right",
                      region = lamina.rect{ min = {2.75, 0.25}, max = {4, 4.75} } }
  if o.release then sim:contact{ l, r, law = "release", test = o.test, update = o.update } end
  return sim, l, r
end

-- o.centres {{x, y}, {x, y}} and o.velocities {{vx, vy}, {vx, vy}} of
-- disks I and II, o.basis ("linear"), o.threads, o.release (the three
-- release pairs: each disk with the wire, and the disks with each other),
-- o.test, o.update (sim:contact's, for every pair), o.cell (0.25; dt 1e-3
-- scaled with it). Returns sim, wire, disk I, disk II, h.
function M.disks_wire(o)
  local h = o.cell or 0.25
  local sim = lamina.sim{ basis = o.basis or "linear", domain = {-2, 1, 12, 9}, cell = h,
                          dt = 1e-3 * h / 0.25, threads = o.threads }
  local diskm = lamina.elastic{ rho = 1, E = 1e4, nu = 0.3, plane = "stress" }
  local wirem = lamina.membrane{ rho = 1, E = 1e4, nu = 0, thickness = 0.05, law = "uniaxial" }
  local wire = sim:membrane{ material = wirem, curve = lamina.segment{ from = {5, 2}, to = {5, 8} },
                             spacing = h / 3, force = "segment", name = "wire" }
  wire:pin{ points = "ends" }
  local d1 = sim:body{ material = diskm, ppc = 4, velocity = o.velocities[1], name = "disk I",
                       region = lamina.disk{ center = o.centres[1], radius = 0.75 } }
  local d2 = sim:body{ material = diskm, ppc = 4, velocity = o.velocities[2], name = "disk II",
                       region = lamina.disk{ center = o.centres[2], radius = 0.75 } }
  if o.release then
    local f = { test = o.test, update = o.update }
    sim:contact{ d1, wire, law = "release", test = f.test, update = f.update }
    sim:contact{ d2, wire, law = "release", test = f.test, update = f.update }
    sim:contact{ d1, d2, law = "release", test = f.test, update = f.update }
  end
  return sim, wire, d1, d2, h
end

-- [T] §5.9 / A.1.6's ball and net: by default the deck's ball (A.4.13, Box
-- 16: rex = 1.5 at (5.625, 5)), speed 1, and a straight unstressed uniaxial
-- net at x = 7.5 held by the box's fixed walls; o.R, o.x0 and o.xn move the
-- ball's radius, its centre's x and the net's line (scripts/paper/
-- contact_ball_net.lua runs the text's R = 3); o.cell (0.25; dt 1e-3 scaled
-- with it), o.law ("release"), o.mu, o.test, o.update (sim:contact's).
-- Returns sim, ball, net.
function M.ball_net(o)
  local h = o.cell or 0.25
  local sim = lamina.sim{ basis = "linear", domain = {0, 0, 10, 10}, cell = h, dt = 1e-3 * h / 0.25,
                          mass = "lumped" }   -- the papers' lumped mass ([F] eq 7)
  local ballm = lamina.elastic{ rho = 1, E = 1e4, nu = 0.3, plane = "stress" }
  local netm = lamina.membrane{ rho = 0.5, E = 1e4, nu = 0, thickness = 0.0125, law = "uniaxial" }
  local R, x0, xn = o.R or 1.5, o.x0 or 5.625, o.xn or 7.5
  local net = sim:membrane{ material = netm, curve = lamina.segment{ from = {xn, 0}, to = {xn, 10} },
                            spacing = h / 3, force = "segment", name = "net" }
  local ball = sim:body{ material = ballm, ppc = 4, velocity = {1, 0}, name = "ball",
                         region = lamina.disk{ center = {x0, 5}, radius = R } }
  -- law = "none": no contact pair, ball and net in the single velocity field
  -- ([T] Fig 98, the run without contact-release)
  if o.law ~= "none" then
    sim:contact{ ball, net, law = o.law or "release", mu = o.mu, test = o.test, update = o.update }
  end
  return sim, ball, net
end

-- o.theta (degrees), o.mu, o.basis, o.threads, o.third (a third body in a
-- release pair with the block), o.scheme, o.law ("friction" by default; a
-- "release" pair takes no mu). Returns sim, block, g.
function M.incline(o)
  local g, th = 10, math.rad(o.theta)
  local sim = lamina.sim{ domain = {0, 0, 4, 1.5}, cell = 0.1, dt = 2e-4, basis = o.basis,
                          threads = o.threads, scheme = o.scheme,
                          gravity = {g * math.sin(th), -g * math.cos(th)} }
  local mat = lamina.elastic{ rho = 1, E = 1e4, nu = 0.3, plane = "strain" }
  local plane = sim:body{ material = mat, ppc = 4, name = "plane",
                          region = lamina.rect{ min = {0.2, 0.2}, max = {3.8, 0.6} } }
  plane:pin{ points = "all" }
  local block = sim:body{ material = mat, ppc = 4, name = "block",
                          region = lamina.rect{ min = {0.5, 0.6}, max = {1.0, 0.9} } }
  local third = o.third and sim:body{ material = mat, ppc = 4, name = "third", velocity = {-1, 0},
                                      region = lamina.rect{ min = {1.6, 0.6}, max = {2.0, 0.9} } }
  local law = o.law or "friction"
  sim:contact{ block, plane, law = law, mu = law == "friction" and o.mu or nil }
  if third then sim:contact{ third, block, law = "release" } end
  return sim, block, g
end

-- The incline run to t = 0.6: the block's acceleration as the least-squares
-- slope of its speed over [0.2, 0.6] (after the start's transient), the
-- exact g (sin theta - mu cos theta), and its speed at the end; printed.
function M.slide(theta, mu, basis)
  local sim, block, g = M.incline{ theta = theta, mu = mu, basis = basis }
  local th = math.rad(theta)
  local n, st, sv, stt, stv = 0, 0, 0, 0, 0
  sim:every(0.01, function(s)
    if s.t >= 0.2 - 1e-9 then
      local v = block:velocity()
      n, st, sv, stt, stv = n + 1, st + s.t, sv + v, stt + s.t * s.t, stv + s.t * v
    end
  end)
  sim:run{ t_end = 0.6 }
  local a = (n * stv - st * sv) / (n * stt - st * st)
  local exact = g * (math.sin(th) - mu * math.cos(th))
  local vx, vy = block:velocity()
  print(string.format("%s theta %g mu %g: a = %.4f, g(sin - mu cos) = %.4f (%.2f %%), "
    .. "v(0.6) = (%.4f, %.4f)", basis, theta, mu, a, exact, 100 * (a - exact) / exact, vx, vy))
  return a, exact, math.sqrt(vx * vx + vy * vy)
end

return M
