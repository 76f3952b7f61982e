-- title: The normals paper's geometry: one element and its shape functions in 1-D and 2-D
-- source: normals paper Figs 1, 2 and 8 ([N] §3-4 and §6)
-- look: (a) Fig 1: one element with nodes x_I and x_I+1 and one material point
--   x_p (the "membrane"), with the two linear shape functions S(x - x_I) and
--   S(x - x_I+1) over it; (b) Fig 2: a mesh of quadrilaterals, the membrane
--   as points along a curve, element I with its four nodes I, I+1, I+N_x,
--   I+N_x+1 (the unknowns of its system); (c) Fig 8: the quadratic B-splines
--   centred on the element centres x_I-1/2, x_I+1/2, x_I+3/2, the three a
--   point x_p in element I reaches
-- checks: the systems the figures set up, as lamina.normals builds them:
--   the linear element has 4 unknowns ([N] §4: "four unknowns for element I")
--   and three points and the random point make it square and of full rank;
--   the quadratic one is 9 by 9 ([N] §6) and underdetermined with 7 membrane
--   points and the random point (rank 8), of full rank with 8 ([N] §6:
--   "underdetermined unless there are at least 8 membrane points along with
--   one random point"); the drawn shape functions sum to one at x_p
-- assumed: the figures have no numbers: x_p at 0.25 of its element; in (b)
--   and the checks, points on y = 0.2 + 0.6 x^3 (a circle would leave the
--   quadratic system a null direction at any count: the biquadratic
--   splines contain its equation)
-- thumb: normals_geometry.png
local out = lamina.param("out", "out/normals_geometry")

local xi = 0.25
local function hat(x) return math.max(0, 1 - math.abs(x)) end
local function b2(x)   -- the quadratic B-spline centred at 0, support [-1.5, 1.5]
  local a = math.abs(x)
  if a < 0.5 then return 0.75 - a * a end
  if a < 1.5 then return 0.5 * (1.5 - a) ^ 2 end
  return 0
end

-- the checks on lamina.normals' systems
local function curve(n)
  local pts = {}
  for k = 1, n do
    local x = 0.1 + 0.8 * (k - 1) / (n - 1)
    pts[k] = {x, 0.2 + 0.6 * x ^ 3}
  end
  return pts
end
local lin = lamina.normals{ points = curve(3), box = {0, 0, 1, 1}, basis = "linear", seed = 1 }
local q7 = lamina.normals{ points = curve(7), box = {0, 0, 1, 1}, basis = "quadratic", seed = 1 }
local q8 = lamina.normals{ points = curve(8), box = {0, 0, 1, 1}, basis = "quadratic", seed = 1 }
local sum_lin = hat(xi) + hat(xi - 1)
local sum_q = b2(xi + 0.5) + b2(xi - 0.5) + b2(xi - 1.5)

local fig = lamina.figure{ width = 1200, height = 520, panels = {3, 1},
  title = "Normals paper Figs 1, 2 and 8: the geometry of one element" }
local function samples(f, a, b, c)
  local pts = {}
  for k = 0, 200 do
    local x = a + (b - a) * k / 200
    pts[#pts + 1] = {x, c * f(x)}
  end
  return pts
end
-- (a) Fig 1
fig:panel{ index = 1, window = {-0.6, -0.45, 1.6, 1.3}, title = "(a) Fig 1: linear, one dimension",
           caption = string.format("at x_p: %.2f + %.2f = %.0f", hat(xi), hat(xi - 1), sum_lin) }
fig:polyline{ points = {{-0.5, 0}, {1.5, 0}}, colour = "black", width = 1 }
fig:polyline{ points = samples(function(x) return hat(x) end, -0.5, 1.5, 1), colour = "computed", width = 2 }
fig:polyline{ points = samples(function(x) return hat(x - 1) end, -0.5, 1.5, 1), colour = "exact", width = 2 }
fig:points{ points = {{0, 0}, {1, 0}}, style = "circle", size = 9, colour = "black" }
fig:points{ points = {{xi, 0}}, style = "dot", size = 9, colour = "black" }
fig:polyline{ points = {{xi, 0}, {xi, 1}}, colour = "grey", dashed = true }
fig:text{ text = "x_I", at = {0, -0.15}, align = "center" }
fig:text{ text = "x_I+1", at = {1, -0.15}, align = "center" }
fig:text{ text = "x_p", at = {xi, -0.15}, align = "center" }
fig:text{ text = "S(x - x_I)", at = {-0.2, 0.95}, align = "center", colour = "computed" }
fig:text{ text = "S(x - x_I+1)", at = {1.25, 0.95}, align = "center", colour = "exact" }
-- (b) Fig 2
fig:panel{ index = 2, window = {-0.1, -0.1, 3.1, 2.1}, title = "(b) Fig 2: two dimensions",
           caption = string.format("element I: %d unknowns, %d rows, rank %d", lin.unknowns, lin.rows, lin.rank) }
fig:grid{ box = {0, 0, 3, 2}, cells = {3, 2} }
local pts = {}
for k = 0, 24 do
  local x = 0.1 + 2.8 * k / 24
  pts[#pts + 1] = {x, 0.25 + 1.2 * (x / 3) ^ 3 + 0.3 * math.sin(x)}
end
fig:polyline{ points = pts, colour = "grey", dashed = true }
fig:points{ points = pts, style = "circle", size = 6, colour = "black" }
fig:outline{ box = {1, 0, 2, 1}, width = 2.5 }
fig:text{ text = "element I", at = {1.5, 0.12}, align = "center" }
for _, nd in ipairs{ {1, 0, "x_I"}, {2, 0, "x_I+1"}, {1, 1, "x_I+Nx"}, {0, 1, "x_I+Nx-1"},
                     {1, 2, "x_I+2Nx"} } do
  fig:text{ text = nd[3], at = {nd[1] + 0.04, nd[2] + 0.05} }
end
fig:text{ text = "x_I+Nx+1", at = {1.96, 1.05}, align = "right" }   -- off the points
fig:text{ text = "x", at = {3.05, -0.07} }
fig:text{ text = "y", at = {-0.07, 2.02}, align = "right" }
-- (c) Fig 8
fig:panel{ index = 3, window = {-1.6, -0.45, 2.6, 1.3}, title = "(c) Fig 8: quadratic, one dimension",
           caption = string.format("at x_p: %.3f + %.3f + %.3f = %.0f; 2-D rank with 7 / 8 points: %d / %d of %d",
                                   b2(xi + 0.5), b2(xi - 0.5), b2(xi - 1.5), sum_q, q7.rank, q8.rank, q8.unknowns) }
fig:polyline{ points = {{-1.5, 0}, {2.5, 0}}, colour = "black", width = 1 }
for i, c in ipairs{ -0.5, 0.5, 1.5 } do
  fig:polyline{ points = samples(function(x) return b2(x - c) end, c - 1.5, c + 1.5, 1),
                colour = ({"computed", "exact", "green"})[i], width = 2 }
  fig:points{ points = {{c, 0}}, style = "asterisk", size = 10, colour = "black" }
end
fig:points{ points = {{0, 0}, {1, 0}}, style = "circle", size = 9, colour = "black" }
fig:points{ points = {{xi, 0}}, style = "dot", size = 9, colour = "black" }
fig:polyline{ points = {{xi, 0}, {xi, 0.8}}, colour = "grey", dashed = true }
fig:text{ text = "x_I-1/2", at = {-0.5, -0.15}, align = "center" }
fig:text{ text = "x_I+1/2", at = {0.5, -0.15}, align = "center" }
fig:text{ text = "x_I+3/2", at = {1.5, -0.15}, align = "center" }
fig:text{ text = "x_I", at = {0, -0.32}, align = "center" }
fig:text{ text = "x_I+1", at = {1, -0.32}, align = "center" }
fig:text{ text = "x_p", at = {xi, 0.85}, align = "center" }
fig:write(out .. "/normals_geometry.png")

print(string.format("linear: %d unknowns, %d rows, rank %d; quadratic: 7 points rank %d of %d (%s), "
  .. "8 points rank %d of %d; sums at x_p %.15g, %.15g", lin.unknowns, lin.rows, lin.rank, q7.rank,
  q7.unknowns, tostring(q7.underdetermined), q8.rank, q8.unknowns, sum_lin, sum_q))
lamina.report{
  linear_unknowns = { lin.unknowns, paper = 4, tol = 0, unit = "([N] §4: four unknowns for element I)" },
  linear_rank_3_points = { lin.rank, ref = 4, tol = 0, unit = "(3 points + the random point)" },
  quadratic_unknowns = { q8.unknowns, paper = 9, tol = 0, unit = "([N] §6: 9 by 9)" },
  quadratic_rank_7_points = { q7.rank, ref = 8, tol = 0, unit = "(7 points + random: underdetermined, [N] §6)" },
  quadratic_rank_8_points = { q8.rank, ref = 9, tol = 0, unit = "(8 points + random: full, [N] §6)" },
  partition_of_unity = { math.max(math.abs(sum_lin - 1), math.abs(sum_q - 1)), ref = 0, tol = 1e-15,
                         unit = "(the drawn shape functions at x_p)" },
}
