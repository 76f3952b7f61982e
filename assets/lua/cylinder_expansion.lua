-- cylinder_expansion.lua - [T] §7.5.2's expanding cylindrical membrane (Figs
-- 73-75), shared by its pages (scripts/paper/normals_cylinder_expansion*.lua),
-- tests/physics/cylinder_equilibrium.lua and scripts/measure/
-- cylinder_equilibrium.lua. [T] gives no parameters: the normals paper's
-- circle (circle_membrane.lua) scaled to radius 1.0, walls at x, y = 1.5
-- (zero velocity, as [T]); gas rho 1, p0 1000, gamma 1.4, mu 0.2, 16 ppc
-- (clipped fill); membrane rho 0.5, E 1e6, nu 0.3, t 0.1 plane stress, point
-- forces; cell 0.1, linear basis, dt 2e-5 (scaled with the cell).
local M = { R = 1.0, p0 = 1000, gamma = 1.4, E = 1e6, nu = 0.3, thickness = 0.1, cell = 0.1 }

-- The equilibrium's delta r (ours): Laplace's law for a circle of radius r
-- holding plane-strain gas compressed adiabatically, the tension linear in
-- the logarithmic strain at the material's thickness (the engine's
-- plane-stress law), p0 (R/r)^(2 gamma) = E t ln(r/R) / ((1 - nu^2) r),
-- by bisection; 0.008995 for R = 1.
function M.equilibrium(radius)
  local R = radius or M.R
  local function F(r)
    return M.p0 * (R / r) ^ (2 * M.gamma) - M.E * M.thickness * math.log(r / R) / ((1 - M.nu * M.nu) * r)
  end
  local a, b = R, 2 * R
  for _ = 1, 100 do
    local m = 0.5 * (a + b)
    if F(m) > 0 then a = m else b = m end
  end
  return 0.5 * (a + b) - R
end

-- o: normals (default "connectivity"), whole (the whole circle in
-- [-1.5, 1.5]^2, fixed walls on every side, 720 points; else the quarter,
-- symmetry on the axes, 181 points), gas_colour (the gas's points carry the
-- colour: colour_points), and for measurements basis, cell, count, force,
-- radius. Returns sim, gas, membrane.
function M.setup(o)
  o = o or {}
  local h, R = o.cell or M.cell, o.radius or M.R
  local sim
  if o.whole then
    sim = lamina.sim{ basis = o.basis or "linear", domain = {-1.5, -1.5, 1.5, 1.5}, cell = h,
      dt = 2e-5 * h / M.cell, boundary = { left = "fixed", bottom = "fixed", right = "fixed", top = "fixed" } }
  else
    sim = lamina.sim{ basis = o.basis or "linear", domain = {0, 0, 1.5, 1.5}, cell = h, dt = 2e-5 * h / M.cell,
      boundary = { left = "symmetry", bottom = "symmetry", right = "fixed", top = "fixed" } }
  end
  local gas = sim:body{ material = lamina.gas{ rho = 1, p = M.p0, gamma = M.gamma, mu = 0.2 }, ppc = 16,
                        name = "gas", fill = "clipped", region = lamina.disk{ center = {0, 0}, radius = R } }
  local mem = sim:membrane{ material = lamina.membrane{ rho = 0.5, E = M.E, nu = M.nu, thickness = M.thickness,
                                                        law = "plane_stress" },
                            curve = lamina.arc{ center = {0, 0}, radius = R, from = 0, to = o.whole and 360 or 90 },
                            count = o.count or (o.whole and 720 or 181), force = o.force or "point",
                            normals = o.normals or "connectivity", orient = {0, 0},
                            colour_points = o.gas_colour and gas or nil, name = "membrane" }
  return sim, gas, mem
end

-- [T]: "the change in the radius of material points at 0, 45, and 90
-- degrees are averaged" (points 1, 91 and 181 on the quarter and on the
-- whole circle alike; for another count the first, middle and last of the
-- quarter: q the index step from 0 to 90 degrees).
function M.dr3(mem, q, radius)
  local P, R = mem:particles(), radius or M.R
  q = q or 180
  local s = 0
  for _, i in ipairs{1, 1 + q // 2, 1 + q} do s = s + math.sqrt(P.x[i] ^ 2 + P.y[i] ^ 2) - R end
  return s / 3
end

-- Every point's mean delta r (the circle's radius), and its mean strain.
function M.dr_all(mem, radius)
  local P, R, s = mem:particles(), radius or M.R, 0
  for i = 1, P.n do s = s + math.sqrt(P.x[i] ^ 2 + P.y[i] ^ 2) - R end
  return s / P.n
end

function M.strain(mem)
  local P, s = mem:particles(), 0
  for i = 1, P.n do s = s + P.et[i] end
  return s / P.n
end

return M
