-- gas_balloon.lua - a gas-filled circle (plane, quarter model) or sphere
-- (axisymmetric, half section), shared by the circle_* and sphere_* cases:
-- the issue 30 sphere, radius r = 0.3, gas p0 = 200 (rho 1, gamma 1.4,
-- mu 0.2, 4 points a cell, fill = "clipped"), membrane E = 1e6, nu = 0.3,
-- t = 0.05, rho = 0.5, plane stress, laid unstressed on the circle and
-- released; means over t = 0.06-0.1 (after the first swings).
--
-- Exact (the membrane equilibrium of a pressurised shell, Timoshenko &
-- Woinowsky-Krieger, Theory of Plates and Shells §105; [F] §4.3 for the
-- circle): a circle of radius r under the pressure difference p carries the
-- tension sigma t = p r (the force on a half circle, 2 r p, against the two
-- cut ends, 2 sigma t); a sphere carries sigma t = p r / 2 in every
-- direction (pi r^2 p against 2 pi r sigma t), meridional and hoop. p is
-- the pressure over the space the gas fills (gas:pressure(membrane), the
-- sum the internal forces use) and r the radius of the circle (sphere) of
-- the enclosed area (the section's half disc on the sphere): both taken at every sample, so the check is
-- the equilibrium relation, whatever radius the gas settles at.
-- Measured: the time means of the membrane's mean tangential stress
-- (membrane:hoop_stress(), the meridional one on the sphere) and, on the
-- sphere, of its points' hoop stress sigma_thth (szz, docs/api.md
-- axisymmetric; each point weighted by its ring's area m / rho), sampled
-- every 1e-4 (the skin rings with a period of ~4e-3), against the time mean
-- of p r / t (p r / 2t).
-- The gas has lamina's default 4 points a cell, what a new user's scene
-- gets; with 16 the sphere came closer at level 1 (measured: meridional
-- -2.0 / -3.1 / -1.0 %, hoop -2.9 / -3.2 / -0.2 % at spacings 0.2 / 0.4 / 0.8
-- cells, against -12.9 / -15.7 % at 0.4 with 4), the circle alike (-0.5 %).
-- Resolution: level 1, 2 = cell 0.05, 0.025; `spacing` the points' spacing
-- in cells (at the natural length).
local V = require("lib.vcase")
local M = {}

function M.run(o)
  local r, p0, E, nu, t = 0.3, 200, 1e6, 0.3, 0.05
  local axi = o.sphere
  local h = 0.1 / 2 ^ V.level
  local c = math.sqrt(E / (0.5 * (1 - nu * nu))) / 0.75
  local sim = V.sim{ domain = axi and {0, -0.5, 0.5, 0.5} or {0, 0, 0.5, 0.5}, cell = h,
                     dt = 0.4 * h / c, axisymmetric = axi or nil,
                     boundary = { left = "symmetry", bottom = axi and "fixed" or "symmetry",
                                  right = "fixed", top = "fixed" } }
  local air = lamina.gas{ rho = 1, p = p0, gamma = 1.4, mu = 0.2 }
  local skin = lamina.membrane{ rho = 0.5, E = E, nu = nu, thickness = t, law = "plane_stress" }
  local gas = sim:body{ material = air, ppc = 4, name = "gas", fill = "clipped",
                        region = lamina.disk{ center = {0, 0}, radius = r } }
  local from, to = 0, 90
  if axi then from, to = 90, -90 end
  local length = math.pi * r * math.abs(to - from) / 180
  local count = math.ceil(length / (o.spacing * h) - 1e-9) + 1
  local mem = V.membrane(sim, { material = skin, count = count, name = "membrane", orient = {0, 0},
                                curve = lamina.arc{ center = {0, 0}, radius = r, from = from, to = to } })
  local s_t, s_h, s_x, n = 0, 0, 0, 0
  sim:every(1e-4, function(s)   -- the skin rings with a period of ~4e-3: sampling at 1e-3 aliased it
    if s.t < 0.06 - 1e-9 then return end
    local p = gas:pressure(mem, {0, 0})
    local R
    if axi then
      R = math.sqrt(2 * mem:enclosed_area({0, 0}) / math.pi)   -- the half disc of the section
    else
      R = math.sqrt(4 * mem:enclosed_area({0, 0}) / math.pi)   -- a quarter disc
    end
    s_x = s_x + (axi and p * R / (2 * t) or p * R / t)
    s_t = s_t + mem:hoop_stress()
    if axi then
      local q = mem:particles()
      -- each point weighted by its ring's area, m / rho (as hoop_stress()
      -- weights the meridional stress): a mean by count gives the points
      -- within a cell of the axis, 1.4 % of the surface, the weight of the
      -- rest (docs/robustness.md "Point spacing")
      local sh, w = 0, 0
      for i = 1, q.n do
        local a = q.mass[i] / q.rho[i]
        sh, w = sh + a * q.szz[i], w + a
      end
      s_h = s_h + sh / w
    end
    n = n + 1
  end)
  sim:run{ t_end = 0.1 }
  local hs = o.spacing * h
  if axi then
    V.result{ quantity = "meridional_stress", value = s_t / n, exact = s_x / n, h = h }
    V.result{ quantity = "hoop_stress", value = s_h / n, exact = s_x / n, h = h }
  else
    V.result{ quantity = "hoop_stress", value = s_t / n, exact = s_x / n, h = h }
  end
  return hs
end

return M
