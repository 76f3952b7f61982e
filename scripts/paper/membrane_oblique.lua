-- title: A membrane oblique to the grid: are the grid's forces tangent to it?
-- source: York's dissertation [T] §5.4.1, Fig 22
-- look: a straight line of membrane points at 30 degrees across the
--   Cartesian grid, stretched and held at its ends. [T] asks whether mapping
--   the divergence of the points' stress to the grid gives accelerations
--   tangent to the membrane. After ten steps the points' velocities (arrows,
--   unit length, drawn just above each point) lie along the membrane: with the papers' point quadrature the
--   points bunch and spread along it (cell-crossing noise, tangential only);
--   with lamina's segment forces (default) they do not move at all
-- checks: every nodal force is sigma_t (t . sum V grad N) t (point form) or
--   -F t [N(b) - N(a)] (segments), parallel to t, so the velocities' normal
--   component vanishes (closed form): to round-off of the tangential for the
--   point form, of c eps for segments; and segments keep a uniformly
--   stretched membrane in equilibrium at any angle (docs/api.md), so their
--   tangential velocities vanish too. [T] answers from its examples ("does
--   indeed work"); no number
-- assumed: E 1e6, rho 1, t 0.01, strain 0.01, points 0.05 apart (half a
--   cell), the line from (0.13, 0.21) 0.75 long; dt 1e-5, ten steps
-- thumb: membrane_oblique.png
local out = lamina.param("out", "out/membrane_oblique")

local E, rho, eps, a = 1e6, 1, 0.01, math.rad(30)
local tx, ty = math.cos(a), math.sin(a)
local scale = math.sqrt(E / rho) * eps    -- c eps, the velocity a release of the strain would give
local function run(force)
  local sim = lamina.sim{ basis = "linear", domain = {0, 0, 1, 1}, cell = 0.1, dt = 1e-5 }
  local m = sim:membrane{ material = lamina.membrane{ rho = rho, E = E, nu = 0, thickness = 0.01 },
    curve = lamina.segment{ from = {0.13, 0.21}, to = {0.13 + 0.75 * tx, 0.21 + 0.75 * ty} },
    spacing = 0.05, initial_strain = eps, force = force, name = force }
  m:pin{ points = "ends" }
  sim:run{ t_end = 1e-4 }
  local P = m:particles()
  local vt, vn, pts, dirs, lens = 0, 0, {}, {}, {}
  for i = 2, P.n - 1 do
    vt = math.max(vt, math.abs(P.vx[i] * tx + P.vy[i] * ty))
    vn = math.max(vn, math.abs(-P.vx[i] * ty + P.vy[i] * tx))
  end
  for i = 1, P.n do pts[i] = {P.x[i], P.y[i]} end
  return { vt = vt, vn = vn, pts = pts, P = P, hash = sim:hash() }
end
local pt, sg = run("point"), run("segment")

local fig = lamina.figure{ width = 1100, height = 560, panels = {2, 1},
  title = "[T] Fig 22: membrane points oblique to the grid, after ten steps" }
local function panel(i, r, title)
  fig:panel{ index = i, window = {0, 0, 1, 1}, title = title,
             caption = string.format("largest |v| along t %.2g, across %.1g (c eps = %.0f)", r.vt, r.vn, scale) }
  fig:grid{ box = {0, 0, 1, 1}, cells = {10, 10} }
  local at, dir = {}, {}
  for k = 2, #r.pts - 1 do
    local vx, vy = r.P.vx[k], r.P.vy[k]
    local l = math.sqrt(vx * vx + vy * vy)
    if l > 1e-9 * scale then
      -- drawn a little off the line (on its normal) so that they are not under the points
      at[#at + 1], dir[#dir + 1] = {r.pts[k][1] - 0.035 * ty, r.pts[k][2] + 0.035 * tx}, {vx / l, vy / l}
    end
  end
  if #at > 0 then fig:arrows{ at = at, dir = dir, length = 0.06, colour = "computed", width = 1.6 } end
  fig:points{ points = r.pts, style = "circle", size = 7, colour = "black" }
end
panel(1, pt, "point quadrature (the papers')")
panel(2, sg, "segment forces (lamina's default)")
fig:write(out .. "/membrane_oblique.png")

print(string.format("point: |v_t| %.4g, |v_n| %.3g; segment: |v_t| %.3g, |v_n| %.3g (c eps %.1f)",
                    pt.vt, pt.vn, sg.vt, sg.vn, scale))
lamina.report{
  point_normal_velocity = { pt.vn / pt.vt, ref = 0, tol = 1e-12, unit = "of the tangential (forces parallel to t)" },
  point_tangential_velocity = { pt.vt, unit = "(noise along the membrane)" },
  segment_normal_velocity = { sg.vn / scale, ref = 0, tol = 1e-12, unit = "of c eps" },
  segment_tangential_velocity = { sg.vt / scale, ref = 0, tol = 1e-12, unit = "of c eps (exact equilibrium)" },
  state_hash = pt.hash,
}
