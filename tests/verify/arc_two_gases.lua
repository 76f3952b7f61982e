-- Verification case (issue 30 item 1): a pressurised arc between two gases
-- (T = dp R). The unit box; a membrane (uniaxial, E = 1e5, thickness 0.01,
-- rho = 10) from (0, 0.5) to (1, 0.5), its ends on the fixed side walls,
-- laid on the circular arc of radius R = 1 through them (centre
-- (0.5, 0.5 - sqrt(0.75)), bulging up to 0.634) with the strain
-- eps0 = dp R / (E t) = 0.01; below it gas at p = 110, above it p = 100
-- (rho 1, gamma 1.4, inviscid, 4 points a cell, fill = "clipped").
-- Exact (Laplace's law for a membrane, the equilibrium of a short piece of
-- arc: T dtheta = dp R dtheta; any statics text, e.g. Timoshenko &
-- Woinowsky-Krieger §105): the arc with T = dp R = 10 is in equilibrium;
-- nothing moves. Measured, as time means over t = 0.02-0.1: the tension
-- (membrane:hoop_stress() x t) against dp R, and the difference of the two
-- gases' gas:pressure() readings (the particle means) against dp.
-- Resolution: level 1, 2 = cell 0.05, 0.025; points h/2 apart.
-- verify: membrane
local V = require("lib.vcase")
local R, E, t, plo, phi = 1, 1e5, 0.01, 100, 110
local dp = phi - plo
local yc = 0.5 - math.sqrt(R * R - 0.25)
local function arc(x) return yc + math.sqrt(R * R - (x - 0.5) ^ 2) end
local h = 0.1 / 2 ^ V.level
local sim = V.sim{ domain = {0, 0, 1, 1}, cell = h, dt = 0.4 * h / (math.sqrt(E / 10) / 0.75) }
local below = sim:body{ material = lamina.gas{ rho = 1, p = phi, gamma = 1.4 }, ppc = 4, fill = "clipped",
                        name = "below", region = function(x, y) return y < arc(x) end }
local above = sim:body{ material = lamina.gas{ rho = 1, p = plo, gamma = 1.4 }, ppc = 4, fill = "clipped",
                        name = "above", region = function(x, y) return y > arc(x) end }
local skin = lamina.membrane{ rho = 10, E = E, nu = 0, thickness = t, law = "uniaxial" }
local a0 = math.asin(0.5 / R)
local length = 2 * a0 * R
local count = math.floor(length / (h / 2)) + 2
local mem = V.membrane(sim, { material = skin, count = count, name = "arc", initial_strain = dp * R / (E * t),
  curve = function(u)
    local a = math.pi / 2 + a0 - 2 * a0 * u
    return math.min(1, math.max(0, 0.5 + R * math.cos(a))), yc + R * math.sin(a)   -- rounding kept inside
  end })
local rec = sim:record{ every = 1e-3, values = {
  T = function() return mem:hoop_stress() * t end,
  dp = function() return below:pressure() - above:pressure() end } }
sim:run{ t_end = 0.1 }
V.result{ quantity = "tension", value = rec:mean("T", 0.02, 0.1), exact = dp * R, h = h }
V.result{ quantity = "pressure_reading", value = rec:mean("dp", 0.02, 0.1), exact = dp, h = h }
