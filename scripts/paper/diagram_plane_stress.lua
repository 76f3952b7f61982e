-- title: The plane stress assumptions of a membrane point, and the stresses lamina gives it
-- source: York's dissertation §5.8, Fig 39 (eq 5.12)
-- look: a small element of the membrane with its local axes: 1' along the
--   membrane in the plane of the figure, 2' out of the plane (along the
--   cylinder's length in a 2-D run), 3' normal to the surface. [T] Fig 39:
--   sigma_1' != 0 and eps_1' != 0; sigma_2' != 0 with eps_2' = 0 (plane
--   strain along 2'); sigma_3' = 0 with eps_3' != 0 (the free surface)
-- checks: a membrane of law "plane_stress" at 30 degrees, held at a
--   tangential strain eps, after one step: the engine's stress rotated into
--   the local axes against eq 5.12's consequences (closed form): sigma_1' =
--   E eps / (1 - nu^2), sigma_2' = nu sigma_1', sigma_3' = 0 and no shear,
--   to round-off; beside it the uniaxial law's sigma_2' = 0
-- assumed: E 1e6, nu 0.3, eps 0.01 (the figure has no numbers)
-- thumb: diagram_plane_stress.png
local out = lamina.param("out", "out/diagram_plane_stress")

local E, nu, eps, ang = 1e6, 0.3, 0.01, math.rad(30)
local c, s = math.cos(ang), math.sin(ang)
local function local_stress(law)
  local sim = lamina.sim{ basis = "linear", domain = {0, 0, 1, 1}, cell = 0.1, dt = 1e-7 }
  local m = sim:membrane{ material = lamina.membrane{ rho = 1, E = E, nu = nu, thickness = 0.01, law = law },
                          curve = lamina.segment{ from = {0.3, 0.3}, to = {0.3 + 0.4 * c, 0.3 + 0.4 * s} },
                          count = 5, initial_strain = eps }
  m:pin{ points = "all" }
  sim:run{ t_end = 1e-7 }
  local P = m:particles()
  local k = 3
  local t1 = {c, s}            -- 1': along the membrane
  local n3 = {-s, c}           -- 3': its normal in the plane
  local function q(a, b)
    return a[1] * (P.sxx[k] * b[1] + P.sxy[k] * b[2]) + a[2] * (P.sxy[k] * b[1] + P.syy[k] * b[2])
  end
  return { s1 = q(t1, t1), s3 = q(n3, n3), s13 = q(t1, n3), s2 = P.szz[k], et = P.et[k] }
end
local ps = local_stress("plane_stress")
local ua = local_stress("uniaxial")
local s1_ref = E * ps.et / (1 - nu * nu)
local miss = math.max(math.abs(ps.s1 - s1_ref), math.abs(ps.s2 - nu * s1_ref), math.abs(ps.s3),
                      math.abs(ps.s13)) / s1_ref

local fig = lamina.figure{ width = 1000, height = 560, panels = {2, 1},
  title = "[T] Fig 39: plane stress assumptions of a membrane point" }
fig:panel{ index = 1, box = {0, 0, 0, 1, 1, 1}, azimuth = -60, elevation = 25,
           title = "a membrane element and its local axes" }
-- the element: a thin slab of the membrane (its surface the 1'-2' plane)
local z0, z1 = 0.4, 0.5
for _, z in ipairs{z0, z1} do
  fig:polyline{ points = {{0, 0, z}, {1, 0, z}, {1, 1, z}, {0, 1, z}, {0, 0, z}}, colour = "black", width = 1.5 }
end
for _, xy in ipairs{{0, 0}, {1, 0}, {1, 1}, {0, 1}} do
  fig:polyline{ points = {{xy[1], xy[2], z0}, {xy[1], xy[2], z1}}, colour = "black", width = 1.5 }
end
fig:arrows{ at = {{0.5, 0.5, z1}, {0.5, 0.5, z1}, {0.5, 0.5, z1}},
            dir = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, length = 0.45, colour = "computed", width = 2 }
fig:text{ text = "1'", at = {1.0, 0.45, z1} }
fig:text{ text = "2'", at = {0.5, 1.02, z1 + 0.03} }
fig:text{ text = "3'", at = {0.52, 0.5, 0.98} }
fig:text{ text = "surface", at = {0.1, 0.1, z1 + 0.03} }
fig:panel{ index = 2, window = {0, 0, 1, 1}, title = "eq 5.12 and lamina's stresses (eps = 0.01)",
           caption = string.format("plane_stress against the closed form: %.0e of sigma_1'", miss) }
local lines = {
  "1' along the membrane, 2' out of the 2-D plane, 3' normal",
  "[T] Fig 39:",
  "  sigma_1' != 0,  eps_1' != 0",
  "  sigma_2' != 0,  eps_2' = 0",
  "  sigma_3' = 0,   eps_3' = -nu eps_1' / (1 - nu)",
  "",
  "lamina, law = \"plane_stress\":",
  string.format("  sigma_1' = %.2f   (E eps/(1 - nu^2) = %.2f)", ps.s1, s1_ref),
  string.format("  sigma_2' = %.2f   (nu sigma_1' = %.2f)", ps.s2, nu * s1_ref),
  string.format("  sigma_3' = %.1e,  shear 1'3' = %.1e", ps.s3, ps.s13),
  "",
  "law = \"uniaxial\" (a string):",
  string.format("  sigma_1' = %.2f,  sigma_2' = %.2f", ua.s1, ua.s2),
}
for i, l in ipairs(lines) do fig:text{ text = l, at = {0.02, 1.0 - 0.072 * i} } end
fig:write(out .. "/diagram_plane_stress.png")

print(string.format("plane stress: s1 %.6f (ref %.6f), s2 %.6f (ref %.6f), s3 %.3e, s13 %.3e; uniaxial s1 %.6f s2 %.6f",
                    ps.s1, s1_ref, ps.s2, nu * s1_ref, ps.s3, ps.s13, ua.s1, ua.s2))
lamina.report{
  plane_stress = { miss, ref = 0, tol = 1e-12,
                   unit = "largest miss of sigma_1', sigma_2', sigma_3', shear against eq 5.12's, of sigma_1'" },
  uniaxial_sigma_2 = { math.abs(ua.s2) / (E * eps), ref = 0, tol = 1e-12, unit = "of E eps (a string: no sigma_2')" },
  uniaxial_sigma_1 = { math.abs(ua.s1 - E * ua.et) / (E * eps), ref = 0, tol = 1e-12, unit = "of E eps (sigma_1' = E eps)" },
}
