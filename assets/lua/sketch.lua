-- sketch.lua - the marks the papers' set-up sketches are made of (walls with
-- hatching, coil springs, boxes, circles, dimension lines, force arrows),
-- drawn with lamina.figure's lines, arrows and text in the panel's units.
-- Used by the sketch_* pages of scripts/paper ([M] Fig 7, [T] Figs 24, 30,
-- 44, 57; [F] Figs 5, 7).
local M = {}

local function unit(dx, dy)
  local l = math.sqrt(dx * dx + dy * dy)
  return dx / l, dy / l, l
end

-- A wall along a -> b with hatch strokes of length h on the side of the
-- normal (the segment's direction turned +90 degrees when side > 0, -90 else).
function M.wall(fig, a, b, o)
  o = o or {}
  local h, n, side = o.hatch or 0.05, o.strokes or 10, o.side or 1
  local tx, ty, l = unit(b[1] - a[1], b[2] - a[2])
  local nx, ny = -ty * side, tx * side
  fig:polyline{ points = {a, b}, colour = "black", width = 2 }
  for k = 0, n do
    local x, y = a[1] + tx * l * k / n, a[2] + ty * l * k / n
    fig:polyline{ points = {{x, y}, {x + h * (nx - tx) * 0.7071, y + h * (ny - ty) * 0.7071}},
                  colour = "black", width = 1 }
  end
end

-- A coil spring from a to b: straight leads of a sixth of its length at each
-- end, zigzags of half-width w between them.
function M.spring(fig, a, b, o)
  o = o or {}
  local coils, w = o.coils or 6, o.width or 0.05
  local tx, ty, l = unit(b[1] - a[1], b[2] - a[2])
  local nx, ny = -ty, tx
  local lead = l / 6
  local pts = { a, {a[1] + tx * lead, a[2] + ty * lead} }
  local zl, m = l - 2 * lead, 2 * coils
  for k = 1, m do
    local s = lead + zl * (k - 0.5) / m
    local sgn = (k % 2 == 1) and 1 or -1
    pts[#pts + 1] = {a[1] + tx * s + nx * w * sgn, a[2] + ty * s + ny * w * sgn}
  end
  pts[#pts + 1] = {b[1] - tx * lead, b[2] - ty * lead}
  pts[#pts + 1] = b
  fig:polyline{ points = pts, colour = "black", width = 1.5 }
end

function M.box(fig, x0, y0, x1, y1, o)
  o = o or {}
  fig:polyline{ points = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}, {x0, y0}},
                colour = o.colour or "black", width = o.width or 1.5, dashed = o.dashed }
end

function M.circle(fig, cx, cy, r, o)
  o = o or {}
  local pts, n = {}, o.segments or 72
  local a0, a1 = math.rad(o.from or 0), math.rad(o.to or 360)
  for k = 0, n do
    local t = a0 + (a1 - a0) * k / n
    pts[#pts + 1] = {cx + r * math.cos(t), cy + r * math.sin(t)}
  end
  fig:polyline{ points = pts, colour = o.colour or "black", width = o.width or 1.5,
                dashed = o.dashed }
end

-- A force or motion arrow from a to b, with an optional label beside its head.
function M.arrow(fig, a, b, label, o)
  o = o or {}
  local tx, ty, l = unit(b[1] - a[1], b[2] - a[2])
  fig:arrows{ at = {a}, dir = {{tx, ty}}, length = l, colour = o.colour or "black",
              width = o.width or 1.6 }
  if label then
    fig:text{ text = label, at = o.at or {b[1] + (o.dx or 0.02), b[2] + (o.dy or 0)},
              align = o.align or "left" }
  end
end

-- A dimension line between a and b, offset by off along the normal, with
-- arrows at both ends and the label at its middle.
function M.dim(fig, a, b, label, o)
  o = o or {}
  local off = o.offset or 0
  local tx, ty, l = unit(b[1] - a[1], b[2] - a[2])
  local nx, ny = -ty, tx
  local p = {a[1] + nx * off, a[2] + ny * off}
  local q = {b[1] + nx * off, b[2] + ny * off}
  if off ~= 0 then
    fig:polyline{ points = {a, {p[1] + nx * 0.2 * off, p[2] + ny * 0.2 * off}}, colour = "grey" }
    fig:polyline{ points = {b, {q[1] + nx * 0.2 * off, q[2] + ny * 0.2 * off}}, colour = "grey" }
  end
  local mid = {0.5 * (p[1] + q[1]), 0.5 * (p[2] + q[2])}
  fig:arrows{ at = {mid, mid}, dir = {{tx, ty}, {-tx, -ty}}, length = 0.5 * l,
              colour = "black", width = 1 }
  if label then
    fig:text{ text = label, at = o.at or {mid[1] + nx * (o.gap or 0.03), mid[2] + ny * (o.gap or 0.03)},
              align = o.align or "center" }
  end
end

return M
