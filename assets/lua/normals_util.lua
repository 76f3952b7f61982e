-- normals_util.lua - measuring normals against exact ones, shared by the
-- normals paper's figure scripts and the normals tests ([N] Tables I-III
-- compare the angle between computed and exact normals; the sign of a
-- computed normal is arbitrary in [N], so the angle ignores it).
local M = {}

-- The angle between two normals, sign ignored, in radians (2D or 3D).
function M.angle(n, e)
  local d = 0
  for a = 1, #n do d = d + n[a] * e[a] end
  local c2
  if #n == 2 then
    c2 = (n[1] * e[2] - n[2] * e[1]) ^ 2
  else
    c2 = (n[2] * e[3] - n[3] * e[2]) ^ 2 + (n[3] * e[1] - n[1] * e[3]) ^ 2
       + (n[1] * e[2] - n[2] * e[1]) ^ 2
  end
  return math.atan(math.sqrt(c2), math.abs(d))
end

-- Largest angle, root mean square, and the paper's "rms" sqrt(sum e^2)/n
-- (docs/normals.md: Table III's numbers fit that, not a true rms).
function M.errors(ns, ex)
  local m, s2 = 0, 0
  for k = 1, #ns do
    local a = M.angle(ns[k], ex[k])
    m, s2 = math.max(m, a), s2 + a * a
  end
  return m, math.sqrt(s2 / #ns), math.sqrt(s2) / #ns
end

function M.max_angle(ns, ex)
  return (M.errors(ns, ex))
end

-- The median (sorts v in place).
function M.median(v)
  table.sort(v)
  local n = #v
  return n % 2 == 1 and v[(n + 1) / 2] or 0.5 * (v[n / 2] + v[n / 2 + 1])
end

-- a0, a0 + step, ... (n values).
function M.spaced(a0, step, n)
  local v = {}
  for k = 0, n - 1 do v[k + 1] = a0 + step * k end
  return v
end

-- A closed polygon of n + 1 points around a circle (for drawing).
function M.circle(cx, cy, r, n)
  local c = {}
  for k = 0, n do
    local t = 2 * math.pi * k / n
    c[#c + 1] = {cx + r * math.cos(t), cy + r * math.sin(t)}
  end
  return c
end

-- n points spread over the first octant of the sphere of radius r (golden
-- angle spiral), with their exact normals.
function M.sphere_points(n, r)
  local golden = (3 - math.sqrt(5)) / 2 * 2 * math.pi    -- the golden angle
  local pts, ex = {}, {}
  for k = 0, n - 1 do
    local c = (k + 0.5) / n
    local s = math.sqrt(1 - c * c)
    local ph = 0.5 * math.pi * ((k * golden) % 1.0)
    local e = {s * math.cos(ph), s * math.sin(ph), c}
    pts[#pts + 1], ex[#ex + 1] = {r * e[1], r * e[2], r * e[3]}, e
  end
  return pts, ex
end

-- The plane 0.5x + 0.25y - z = 0 over the unit cube, dashed ([N] Figs 5, 11).
function M.plane_outline(fig)
  fig:polyline{points = {{0, 0, 0}, {1, 0, 0.5}, {1, 1, 0.75}, {0, 1, 0.25}, {0, 0, 0}},
               dashed = true}
end

return M
