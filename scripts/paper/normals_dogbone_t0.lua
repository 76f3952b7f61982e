-- title: Dog-bone membrane at t = 0: normals by the quadratic mass matrix method against connectivity
-- source: York's dissertation [T] §7.7, Fig 86
-- look: the quarter dog-bone's membrane points at the start, the normals
--   from the points' connectivity (dashed) and from the mass matrix method
--   with quadratic functions, cell by cell (solid): they lie on each other
--   round the lobe and along the neck; a close-up of the neck, where the
--   outline turns, shows the largest difference. [T]'s reason for the
--   quadratic functions: the linear ones gave errors (printed beside)
-- checks: the median angle between the quadratic mass matrix normals and the
--   connectivity ones within 1 degree ([T]: "the normals are accurate with
--   the mass matrix method"; the tolerance is ours), and below the linear
--   functions' ([T] §7.7: with linear functions "the membrane expanded too
--   much indicating errors in the normal vectors"); the largest (at the neck's
--   corner) printed
-- assumed: lamina's dog-bone (assets/lua/dogbone.lua, the superellipse
--   construction) at cell 0.1 with 200 points ([T] does not say which run
--   Fig 86 comes from); lamina.normals per cell with the normal equations
--   (method = "mass_matrix"), cells short of points merged 2 x 2 (the ghost
--   cell, normals_ghost_cell); the random point from seed 1
-- thumb: normals_dogbone_t0.png
local nu = require("normals_util")
local dog = require("dogbone")
local out = lamina.param("out", "out/normals_dogbone_t0")

local h = 0.1
local sim, _, mem = dog.setup(h, { basis = "linear", force = "point", normals = "connectivity" })
local P = mem:particles()
local pts, con = {}, {}
for i = 1, P.n do pts[i], con[i] = {P.x[i], P.y[i]}, {P.nx[i], P.ny[i]} end
local function by(basis)
  local r = lamina.normals{ points = pts, box = {0, 0, 1.6, 1.6}, cells = {16, 16}, basis = basis,
                            method = "mass_matrix", seed = 1, orient = {0, 0} }
  local v, w, at = {}, 0, 1
  for i = 2, P.n - 1 do   -- the end points sit on the symmetry lines
    v[#v + 1] = math.deg(nu.angle(r.normals[i], con[i]))
    if v[#v] > w then w, at = v[#v], i end
  end
  return r, nu.median(v), w, at
end
local rq, medq, maxq, atq = by("quadratic")
local rl, medl, maxl = by("linear")

local fig = lamina.figure{ width = 1100, height = 580, panels = {2, 1},
  title = "[T] Fig 86: dog-bone normals at t = 0, quadratic mass matrix against connectivity" }
local every = {}
for i = 1, P.n, 4 do every[#every + 1] = i end
local function draw(idx, sel, len)
  local a, dq, dc = {}, {}, {}
  for _, i in ipairs(sel) do a[#a + 1], dq[#dq + 1], dc[#dc + 1] = pts[i], rq.normals[i], con[i] end
  fig:arrows{ at = a, dir = dc, length = len, style = "dashed" }
  fig:arrows{ at = a, dir = dq, length = len }
  fig:points{ points = a, style = "circle", size = 5 }
end
fig:panel{ index = 1, window = {-0.05, -0.05, 1.3, 1.3}, title = "every 4th point",
           caption = string.format("median %.3f deg, largest %.1f deg (linear: %.2f, %.1f)", medq, maxq, medl, maxl) }
fig:grid{ box = {0, 0, 1.3, 1.3}, cells = {13, 13} }
draw(1, every, 0.08)
local c = pts[atq]
local sel = {}
for i = 1, P.n do   -- every other point: they are 0.09 cells apart
  if i % 2 == atq % 2 and math.abs(pts[i][1] - c[1]) < 0.12 and math.abs(pts[i][2] - c[2]) < 0.12 then
    sel[#sel + 1] = i
  end
end
fig:panel{ index = 2, window = {c[1] - 0.15, c[2] - 0.15, c[1] + 0.15, c[2] + 0.15},
           title = string.format("close-up where they differ most (point %d), every other point", atq) }
fig:grid{ box = {math.floor((c[1] - 0.15) / h) * h, math.floor((c[2] - 0.15) / h) * h,
                 math.ceil((c[1] + 0.15) / h) * h, math.ceil((c[2] + 0.15) / h) * h},
          cells = {math.ceil((c[1] + 0.15) / h) - math.floor((c[1] - 0.15) / h),
                   math.ceil((c[2] + 0.15) / h) - math.floor((c[2] - 0.15) / h)} }
draw(2, sel, 0.04)
fig:write(out .. "/normals_dogbone_t0.png")

print(string.format("quadratic mass matrix against connectivity: median %.4f deg, largest %.2f deg at point %d "
  .. "(%.3f, %.3f); linear: median %.3f, largest %.2f", medq, maxq, atq, c[1], c[2], medl, maxl))
lamina.report{
  median_quadratic = { medq, ref = 0, tol = 1, unit = "deg from connectivity ([T]: accurate; tol ours)" },
  quadratic_better = { medq < medl and 1 or 0, ref = 1, tol = 0, unit = "(1: median below the linear functions')" },
  largest_quadratic = { maxq, unit = "deg (at the neck's corner)" },
  median_linear = { medl, unit = "deg" },
  largest_linear = { maxl, unit = "deg" },
}
