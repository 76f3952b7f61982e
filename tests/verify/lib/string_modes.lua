-- string_modes.lua - a taut string's transverse modes, shared by the
-- string_* cases. A string of length L = 1 along a line, both ends held
-- (by fixed walls, or by body:pin anywhere), stretched by eps0 = 0.01
-- (uniaxial, E = 5e4, nu = 0, thickness 0.01, rho = 100: tension
-- T = E eps0 t = 5 per unit depth), laid on y = A sin(n pi s / L) with
-- A = 2e-4 L and released from rest: mode n alone.
--
-- Exact: the wave equation of a taut string, mu y_tt = T y_ss (any text on
-- vibrating strings, e.g. Graff, Wave Motion in Elastic Solids §1.1), with
-- y = 0 at both ends, has the modes sin(n pi s / L) cos(omega_n t),
-- omega_n = (n pi / L) sqrt(T / mu): the period P_n = 2 L / (n sqrt(T/mu)).
-- T = E eps0 t is the membrane law's (docs/api.md lamina.membrane:
-- sigma_t = E eps_t, force per unit length sigma_t t); mu, the mass per unit
-- of present length, is read from the string's own particles (an interior
-- point's mass over the spacing L / intervals):
-- the mass convention (rho t ds e^(-eps0), issue 30 item 7) is not what is
-- checked here. The amplitude is small enough that the stretch the shape
-- adds, (n pi A / L)^2 / 4 <= 1e-6, changes T by at most 1e-4 relative.
-- The period is measured from the upward zero crossings of the string's
-- normal displacement at the first antinode, s = L / 2n, over 3 periods; the
-- energy kept is the largest kinetic energy in the last period over that in
-- the first (exact 1: nothing dissipates).
--
-- Resolution: level 1, 2, 3 = cell 1/16, 1/32, 1/64; points h/2 apart.
local V = require("lib.vcase")
local M = {}

-- o.ends "wall" | "pin", o.mode n, o.angle (degrees from the x axis; pins
-- only), o.offset (fraction of a cell the string lies off the node line)
function M.run(o)
  local L, E, rho, t, eps0 = 1, 5e4, 100, 0.01, 0.01
  local n = o.mode
  local h = 1 / (8 * 2 ^ V.level)
  local A = 2e-4 * L
  local th = math.rad(o.angle or 0)
  local ux, uy = math.cos(th), math.sin(th)       -- along the string
  local nx, ny = -uy, ux                           -- across it
  local x0, y0, domain, boundary
  if o.ends == "wall" then
    x0, y0 = 0, 0.25 + (o.offset or 0) * h
    domain = {0, 0, L, 0.5}
    boundary = "fixed"
  else
    local W, H = L * ux + 0.5, L * uy + 0.5
    x0, y0 = 0.25, 0.25 + (o.offset or 0) * h
    domain = {0, 0, W, H}
    boundary = "fixed"
  end
  local c_long = math.sqrt(E / rho) / 0.75          -- the Courant check's segment speed
  local sim = V.sim{ domain = domain, cell = h, dt = 0.4 * h / c_long, boundary = boundary }
  local wire = lamina.membrane{ rho = rho, E = E, nu = 0, thickness = t, law = "uniaxial" }
  local count = math.floor(2 * L / h + 0.5) + 1
  local s = V.membrane(sim, { material = wire, count = count, initial_strain = eps0, name = "string",
    curve = function(u)
      local w = A * math.sin(n * math.pi * u)
      return x0 + L * u * ux + w * nx, y0 + L * u * uy + w * ny
    end })
  if o.ends == "pin" then s:pin{ points = {1} }; s:pin{ points = {count} } end
  -- mu from an interior point (the end points are held: their mass, whatever
  -- it is, does not move): its mass over its share of the present length
  local p = s:particles()
  local mu = p.mass[2] / (L / (count - 1))
  local T = E * eps0 * t
  local P = 2 * L / (n * math.sqrt(T / mu))
  -- the point nearest the first antinode s = L / 2n
  local k = math.floor((count - 1) / (2 * n) + 0.5) + 1
  local rec = sim:record{ every = P / 100, energy = true,
    values = { w = function()
      local q = s:particles()
      return (q.x[k] - x0) * nx + (q.y[k] - y0) * ny
    end } }
  sim:run{ t_end = 3.02 * P }
  local tt, w, ke = rec:column("t"), rec:column("w"), rec:column("kinetic")
  local period = V.period(tt, w, 0)
  local k1, k3 = 0, 0
  for i = 1, #tt do
    if tt[i] <= P then k1 = math.max(k1, ke[i]) end
    if tt[i] >= 2 * P then k3 = math.max(k3, ke[i]) end
  end
  V.result{ quantity = "period_mode" .. n, value = period, exact = P, h = h }
  V.result{ quantity = "energy_kept", value = k3 / k1, exact = 1, h = h }
end

return M
