-- gas_spacing.lua - issue 30 item 4: a gas-filled membrane at a chosen point
-- spacing, for tests/physics/spacing_*.lua and docs/robustness.md "Point
-- spacing". Two closed forms, each from a free body cut through the centre:
--   sphere (axisymmetric, the half circle in (r, z) from pole to pole):
--     the gas on the equatorial disc, p pi r^2, against the skin's ring,
--     sigma t 2 pi r: sigma t = p r / 2, meridional and hoop alike;
--   circle (plane, the quarter model): p 2 r against 2 sigma t:
--     sigma t = p r.
-- Set-up (the issue's): radius 0.3, p 200, membrane E 1e6, nu 0.3, t 0.05,
-- rho 0.5, plane stress; gas rho 1, gamma 1.4, mu 0.2, 4 ppc (the default),
-- clipped; cell 0.05, dt 2.5e-5; the membrane starts unstressed, so the
-- gas pushes it out and it rings about the equilibrium (period about
-- 4 ms, still +-60 % at t = 0.1: the gas's viscosity damps it slowly).
-- The stresses are time-averaged over t in [0.06, 0.1] sampled every 1e-4
-- (ten periods; a coarser sampling aliases the ringing) against p r / 2 t
-- (p r / t) with p and r of the same run at the same samples: p the gas's
-- pressure over the space the membrane encloses (gas:pressure(mem)) and r
-- the points' mean distance from the centre (the sphere grows by 1.3e-4
-- from its unstressed 0.3).
local M = {}

local P0, R, T, E, NU, H = 200, 0.3, 0.05, 1e6, 0.3, 0.05

-- o.shape "sphere" | "circle"; o.spacing in cells (points evenly along the
-- arc, count rounded up); o.t0, o.t_end (default 0.06, 0.1).
-- Returns {mer, hoop, ref, pts = {mer[k], hoop[k]}, n, ds}: the time
-- averages of the membrane's mean meridional (tangential) stress
-- (mem:hoop_stress(): over the surface, axisymmetric by ring area) and mean
-- hoop stress sigma_thth (sphere; by ring area), of each point's two
-- stresses, and of the closed form, all times t.
function M.run(o)
  local sphere = o.shape == "sphere"
  local sim
  if sphere then
    sim = lamina.sim{ domain = {0, -0.5, 0.5, 0.5}, cell = H, dt = 2.5e-5, axisymmetric = true,
                      boundary = { left = "symmetry", bottom = "fixed", right = "fixed",
                                   top = "fixed" } }
  else
    sim = lamina.sim{ domain = {0, 0, 0.5, 0.5}, cell = H, dt = 2.5e-5,
                      boundary = { left = "symmetry", bottom = "symmetry", right = "fixed",
                                   top = "fixed" } }
  end
  local air = lamina.gas{ rho = 1, p = P0, gamma = 1.4, mu = 0.2 }
  local skin = lamina.membrane{ rho = 0.5, E = E, nu = NU, thickness = T, law = "plane_stress" }
  local gas = sim:body{ material = air, name = "gas", fill = "clipped",
                        region = lamina.disk{ center = {0, 0}, radius = R } }
  local arc = sphere and lamina.arc{ center = {0, 0}, radius = R, from = -90, to = 90 }
                      or lamina.arc{ center = {0, 0}, radius = R, from = 0, to = 90 }
  local mem = sim:membrane{ material = skin, spacing = o.spacing * H, name = "skin",
                            orient = {0, 0}, curve = arc }
  local n = #mem
  local t0, t_end = o.t0 or 0.06, o.t_end or 0.1
  local acc = { mer = 0, hoop = 0, ref = 0, k = 0, pm = {}, ph = {} }
  for k = 1, n do acc.pm[k], acc.ph[k] = 0, 0 end
  sim:every(1e-4, function()
    if sim.t < t0 - 1e-9 then return end
    local s = mem:particles()
    local r, hoop, w = 0, 0, 0
    for k = 1, n do
      r = r + math.sqrt(s.x[k] ^ 2 + s.y[k] ^ 2)
      local v = s.mass[k] / s.rho[k]   -- the ring's area times t (axisym.c)
      hoop, w = hoop + v * s.szz[k], w + v
      acc.pm[k] = acc.pm[k] + (s.sxx[k] + s.syy[k]) * T   -- sigma_t t(x)t: trace sigma_t
      acc.ph[k] = acc.ph[k] + s.szz[k] * T
    end
    r = r / n
    acc.mer = acc.mer + mem:hoop_stress() * T
    acc.hoop = acc.hoop + hoop / w * T
    acc.ref = acc.ref + gas:pressure(mem) * r / (sphere and 2 or 1)
    acc.k = acc.k + 1
  end)
  sim:run{ t_end = t_end }
  local out = { mer = acc.mer / acc.k, hoop = acc.hoop / acc.k, ref = acc.ref / acc.k,
                n = n, ds = mem:particles().ds[1] / H, pm = {}, ph = {}, escaped = mem:escaped(gas) }
  for k = 1, n do out.pm[k], out.ph[k] = acc.pm[k] / acc.k, acc.ph[k] / acc.k end
  return out
end

return M
