-- title: A membrane in three dimensions and the section a two-dimensional run computes
-- source: York's dissertation [T] §5.1, Fig 19
-- look: (a) a cylindrical membrane (radius 1, a half turn, 2 long) as
--   rings of material points, its normals, the section plane z = 1 and the
--   ring the plane cuts (blue); (b) the section view: the membrane's line of
--   material points as lamina seeds it for a 2-D run, its thickness drawn
--   about it (exaggerated), each point's normal and tangent: a single layer
--   of points carries a tangential stress, constant through the thickness
--   ([T] §5.1: "stresses exist only in the plane of the surface", "the
--   tangent stress does not vary through the thickness")
-- checks: lamina's 2-D membrane points (an arc of radius 1 over the same
--   half turn) lie on the 3-D surface's section, to round-off; held at a
--   tangential strain for one step, their stress is tangential only: |sigma
--   n| / sigma_t to round-off
-- assumed: 13 points a ring, radius 1, thickness 0.05 (drawn 4x), E 1e6,
--   strain 0.01 (the figure has no numbers)
-- thumb: diagram_membrane_section.png
local out = lamina.param("out", "out/diagram_membrane_section")

local R, n, t, E, eps = 1, 13, 0.05, 1e6, 0.01
local sim = lamina.sim{ basis = "linear", domain = {-1.5, -0.5, 1.5, 1.5}, cell = 0.5, dt = 1e-7 }
local mem = sim:membrane{ material = lamina.membrane{ rho = 1, E = E, nu = 0, thickness = t },
                          curve = lamina.arc{ center = {0, 0}, radius = R, from = 0, to = 180 },
                          count = n, initial_strain = eps, force = "point", name = "membrane" }
mem:pin{ points = "all" }
sim:run{ t_end = 1e-7 }
local P = mem:particles()
local on_section, worst_sn = 0, 0
for i = 1, P.n do
  on_section = math.max(on_section, math.abs(math.sqrt(P.x[i]^2 + P.y[i]^2) - R))
  if i > 1 and i < P.n then
    local nx, ny = P.nx[i], P.ny[i]
    local tx, ty = -ny, nx
    local st = tx * tx * P.sxx[i] + 2 * tx * ty * P.sxy[i] + ty * ty * P.syy[i]
    local snx, sny = P.sxx[i] * nx + P.sxy[i] * ny, P.sxy[i] * nx + P.syy[i] * ny
    worst_sn = math.max(worst_sn, math.sqrt(snx * snx + sny * sny) / math.abs(st))
  end
end

local fig = lamina.figure{ width = 1100, height = 540, panels = {2, 1},
  title = "[T] Fig 19: a membrane in three dimensions (left) and its section" }
fig:panel{ index = 1, box = {-1.2, -0.2, 0, 1.2, 1.2, 2}, azimuth = -60, elevation = 25, axes = "outside",
           title = "(a) the membrane, rings of material points" }
for k = 0, 4 do
  local z = 0.5 * k
  local ring, nrm = {}, {}
  for i = 1, P.n do
    ring[i] = {P.x[i], P.y[i], z}
    nrm[i] = {P.x[i] / R, P.y[i] / R, 0}
  end
  local cut = k == 2
  fig:polyline{ points = ring, colour = cut and "computed" or "grey", width = cut and 2 or 1 }
  fig:points{ points = ring, style = "dot", size = cut and 7 or 5, colour = cut and "computed" or "black" }
  if cut then fig:arrows{ at = ring, dir = nrm, length = 0.25, colour = "computed" } end
end
fig:polyline{ points = {{-1.2, -0.2, 1}, {1.2, -0.2, 1}, {1.2, 1.2, 1}, {-1.2, 1.2, 1}, {-1.2, -0.2, 1}},
              colour = "grey", dashed = true }
fig:panel{ index = 2, window = {-1.4, -0.35, 1.4, 1.4}, title = "(b) the section z = 1: what a 2-D run computes",
           caption = string.format("lamina's points on the section to %.0e; |sigma n| / sigma_t %.0e", on_section,
                                   worst_sn) }
local line, inner, outer, tan = {}, {}, {}, {}
local h = 2 * t                        -- half the thickness, drawn 4x
for i = 1, P.n do
  local a = math.atan(P.y[i], P.x[i])
  line[i] = {P.x[i], P.y[i]}
  inner[i] = {(R - h) * math.cos(a), (R - h) * math.sin(a)}
  outer[i] = {(R + h) * math.cos(a), (R + h) * math.sin(a)}
  tan[i] = {-math.sin(a), math.cos(a)}
end
fig:polyline{ points = inner, colour = "grey" }
fig:polyline{ points = outer, colour = "grey" }
fig:polyline{ points = line, colour = "black", dashed = true }
local nn = {}
for i = 1, P.n do nn[i] = {P.nx[i], P.ny[i]} end
fig:arrows{ at = line, dir = nn, length = 0.22, colour = "computed" }
fig:arrows{ at = line, dir = tan, length = 0.15, colour = "exact" }
fig:points{ points = line, style = "dot", size = 8, colour = "black" }
fig:text{ text = "thickness t (drawn 4x)", at = {0.55, -0.25} }
fig:text{ text = "n (blue), t (vermilion)", at = {-1.35, -0.25} }
fig:write(out .. "/diagram_membrane_section.png")

print(string.format("on the section to %.2e; |sigma n| / sigma_t %.2e over %d interior points", on_section,
                    worst_sn, P.n - 2))
lamina.report{
  on_section = { on_section, ref = 0, tol = 1e-12, unit = "largest | |x_p| - R | (round-off)" },
  stress_in_plane = { worst_sn, ref = 0, tol = 1e-12,
                      unit = "largest |sigma n| / sigma_t ([T] §5.1: stresses only in the plane of the surface; round-off)" },
  state_hash = sim:hash(),
}
