-- A 3D frame draws the membranes' points, normals and phi = 1 surfaces
-- (frame3d's lr_membrane3d and triangles; tests/io/frame3d_membrane.sh
-- reads the lamina:layers chunk): a sphere and a pinned sheet, drawn with
-- normals, without, without phi, with the trilinear construction's normals
-- and phi, and without membranes. --set out=DIR
local out = lamina.param("out", "out/frame3d_membrane")
local skin = lamina.membrane{ rho = 1000, E = 1e6, nu = 0.3, thickness = 1e-3, law = "plane_stress" }
local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, 1, 1, 1}, cell = 0.05, dt = 5e-4, basis = "bspline2" }
local a = sim:membrane{ material = skin, spacing = 0.05, pressure = 100, damping = 200,
                        surface = lamina.sphere{ center = {0.5, 0.5, 0.55}, radius = 0.3 } }
local b = sim:membrane{ material = skin, spacing = 0.025, initial_strain = 0.01, pin = "edges",
                        surface = lamina.rect3{ origin = {0.1, 0.1, 0.1}, u = {0.8, 0, 0}, v = {0, 0.8, 0} } }
print(string.format("points %d %d", #a, #b))
sim:step(20)
sim:frame{ file = out .. "/normals.png" }
sim:frame{ file = out .. "/points.png", normals = false }
sim:frame{ file = out .. "/nophi.png", normals = false, phi = false }
sim:frame{ file = out .. "/linear.png", normals = "linear", phi = "linear" }
-- a bad value is refused naming the key
local ok, err = pcall(function() sim:frame{ file = out .. "/bad.png", phi = "cubic" } end)
assert(not ok and err:find('phi = cubic: must be true, false, "linear" or "quadratic"', 1, true), tostring(err))
sim:frame{ file = out .. "/none.png", membranes = false }
-- m:normals(basis): the construction's normals on the present points, unit,
-- out of the sphere (the triquadratic fit), one per point
local nq = a:normals("quadratic")
assert(nq.n == #a and #nq.nx == #a, "one normal a point")
local pa = a:particles()
for i = 1, nq.n do
  assert(math.abs(nq.nx[i]^2 + nq.ny[i]^2 + nq.nz[i]^2 - 1) < 1e-9, "unit normal")
  assert(nq.nx[i] * (pa.x[i] - 0.5) + nq.ny[i] * (pa.y[i] - 0.5) + nq.nz[i] * (pa.z[i] - 0.55) > 0,
         "outward at point " .. i)
end
local ok2, err2 = pcall(function() return a:normals("cubic") end)
assert(not ok2 and err2:find("invalid option 'cubic'", 1, true), tostring(err2))
