-- cylinder_equilibrium.lua - issue 32 item 7: is normals_cylinder_expansion's
-- Laplace equilibrium ([T] §7.5.2, Fig 73; the page's reference, ours) right,
-- and does the run reach it? The page's scene (cylinder of radius 1 in
-- quarter symmetry, walls at 1.5; gas rho 1, p0 1000, gamma 1.4, mu 0.2, 16
-- ppc clipped; membrane rho 0.5, E 1e6, nu 0.3, t 0.1 plane stress, 181
-- points, point forces, connectivity normals; linear basis, MUSL, cell 0.1,
-- dt 2e-5) and the same scene at other cells, point counts and bases.
--   lamina run scripts/measure/cylinder_equilibrium.lua [--set fine=true]
-- (fine = true adds the linear basis at cell 0.025, 20 s more.)
--
-- The reference: a circle of radius r holding plane-strain gas (area ~ r^2)
-- whose tension is E t ln(r/R) / (1 - nu^2) (the engine's plane-stress law is
-- linear in the logarithmic strain, the thickness its material's): Laplace,
-- p(r) = T / r. p(r) follows the gas's path; printed for four readings, to
-- show how little the 13 % the page once missed can come from the path or the
-- strain measure.
local fine = lamina.param("fine", false)
local C = require("cylinder_expansion")   -- the page's scene and reference
local R, p0, gam, nu, th = C.R, C.p0, C.gamma, C.nu, C.thickness
local Ep = C.E / (1 - nu * nu)
local A0 = math.pi * R * R / 4

local function bisect(F)
  local a, b = R, 2 * R
  for _ = 1, 200 do
    local m = 0.5 * (a + b)
    if F(m) > 0 then a = m else b = m end
  end
  return 0.5 * (a + b)
end
-- the page's: adiabatic from the start, p0 (R/r)^(2 gamma)
local d_eq = C.equilibrium()
-- the oscillation's energy dissipated into the gas (an undamped run keeps it
-- as motion): the gas's internal energy is the start's less the strain
-- energy, E_t L0 t [(eps - 1) e^eps + 1] for the quarter's length L0 = pi R / 2
local Eint0 = p0 * A0 / (gam - 1)
local d_heat = bisect(function(r)
  local e = math.log(r / R)
  local Es = Ep * th * (math.pi / 2 * R) * ((e - 1) * math.exp(e) + 1)
  return (gam - 1) * (Eint0 - Es) / (math.pi * r * r / 4) - Ep * th * e / r
end) - R
local d_iso = bisect(function(r) return p0 * (R / r) ^ 2 - Ep * th * math.log(r / R) / r end) - R
local d_lin = bisect(function(r) return p0 * (R / r) ^ (2 * gam) - Ep * th * (r / R - 1) / r end) - R
print(string.format("equilibrium delta r: adiabatic %.6f (the page's); the oscillation's energy turned to "
  .. "heat %.6f (%+.2f %%); isothermal %.6f (%+.2f %%); engineering strain %.6f (%+.2f %%)",
  d_eq, d_heat, 100 * (d_heat / d_eq - 1), d_iso, 100 * (d_iso / d_eq - 1), d_lin, 100 * (d_lin / d_eq - 1)))

-- One run; the time means over [t0, t1] of: every point's delta r, the
-- area's equivalent (sqrt(A / A0) R - R), [T]'s 3 points (0, 45, 90 deg),
-- the points at 0 and 45 deg, every point's strain; the gas's pressure over
-- the membrane's space against p0 (A0 / A)^gamma (largest relative gap over
-- the samples), and the total energy's drift.
local function run(o)
  local radius = o.radius or R
  local whole = o.whole
  local count = o.count or (whole and 720 or 181)
  local sim, gas, mem = C.setup(o)
  local c = (not whole) and {0, 0} or nil
  local q = whole and count // 4 or count - 1   -- the point at 90 deg, less one
  local area0 = mem:enclosed_area(c)
  local function r_of(P, i) return math.sqrt(P.x[i] ^ 2 + P.y[i] ^ 2) - radius end
  local worst_p = 0
  local rec = sim:record{ every = 2.5e-4, energy = true, values = {
    all = function() return C.dr_all(mem, radius) end,
    area = function() return math.sqrt(mem:enclosed_area(c) / area0) * radius - radius end,
    three = function() return C.dr3(mem, q, radius) end,
    at0 = function() return r_of(mem:particles(), 1) end,
    at45 = function() return r_of(mem:particles(), 1 + q // 2) end,
    et = function() return C.strain(mem) end,
    padiab = function()
      local A = mem:enclosed_area(c)
      local gap = gas:pressure(mem, c) / (p0 * (area0 / A) ^ gam) - 1
      worst_p = math.max(worst_p, math.abs(gap))
      return gap end } }
  sim:run{ t_end = o.t1 or 0.05 }
  local t0, t1 = o.t0 or 0.01, o.t1 or 0.05
  local tot = rec:column("total")
  local r = {}
  for _, k in ipairs{ "all", "area", "three", "at0", "at45", "et" } do r[k] = rec:mean(k, t0, t1) end
  r.padiab, r.drift, r.t0, r.t1 = worst_p, math.abs(tot[#tot] / tot[1] - 1), t0, t1
  r.eq = C.equilibrium(radius)
  return r
end

print("\ntime means; delta r and strain as % of the equilibrium's (delta r, ln(1 + delta r))")
print("| run | t | every point | area | [T]'s 3 points | 0 deg | 45 deg | strain | gas vs adiabat (max) | energy drift |")
print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|")
local function row(name, o)
  local r = run(o)
  local function pc(x) return string.format("%+.1f %%", 100 * (x / r.eq - 1)) end
  print(string.format("| %s | %g-%g | %s | %s | %s | %s | %s | %+.1f %% | %.2g | %.2g |", name, r.t0, r.t1,
    pc(r.all), pc(r.area), pc(r.three), pc(r.at0), pc(r.at45), 100 * (r.et / math.log(1 + r.eq) - 1),
    r.padiab, r.drift))
end
row("the page's (linear, point, cell 0.1, 181)", {})
row("the page's, run on", { t0 = 0.15, t1 = 0.2 })
row("whole circle (720 points, fixed walls)", { whole = true })
row("radius 1.05 (off the grid line; its own equilibrium)", { radius = 1.05 })
row("linear, point, cell 0.05, 361", { cell = 0.05, count = 361 })
row("linear, point, cell 0.05, 181", { cell = 0.05, count = 181 })
if fine then row("linear, point, cell 0.025, 721", { cell = 0.025, count = 721 }) end
row("bspline2, point, cell 0.1, 181", { basis = "bspline2" })
row("bspline2, point, cell 0.05, 361", { basis = "bspline2", cell = 0.05, count = 361 })
row("bspline2, segment, cell 0.1, 121", { basis = "bspline2", force = "segment", count = 121 })
row("bspline2, segment, cell 0.05, 241", { basis = "bspline2", force = "segment", cell = 0.05, count = 241 })
