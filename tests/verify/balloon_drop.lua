-- Verification case (issue 30 item 1): a balloon dropped on the floor. A
-- closed membrane circle, radius 0.2 at (0.5, 0.45) (plane stress, E = 1e3,
-- nu = 0.3, thickness 0.01, rho = 10; points h/2 apart, laid unstressed),
-- filled with gas at p = 3 (rho 1, gamma 1.4, inviscid, 4 points a cell,
-- fill = "clipped"), falls under g = 10 onto the fixed floor of the unit box
-- and bounces, for t = 0.6.
-- Exact: nothing adds energy (no pin drives it, gravity is constant, the
-- walls are fixed), so the total energy (kinetic + strain + internal +
-- potential, sim:energy()) never rises above its start; and the membrane is
-- closed, so no gas particle is ever outside it. Measured: the largest rise
-- of the total energy over its start at any sample, in per cent of the
-- potential energy the fall releases (m g 0.25, the drop to the floor), and
-- the largest count of gas points escaped from the membrane in per cent of
-- the gas points: membrane:escaped(gas)'s first value, the points more than
-- a quarter cell outside its polygon (docs/api.md: the last row of gas,
-- half a spacing from the points, grazes the chords within a quarter cell
-- and is not a leak; it is its third value, not counted here). Both exact 0.
-- Measured (docs/robustness.md "Verification cases on the default"): at
-- cell 0.05 none escapes (the deepest 0.081 cells out, up to 10 grazing);
-- at 0.025 one of 856 leaks at t = 0.517 and flies off (the run warns).
-- Resolution: level 1, 2 = cell 0.05, 0.025.
-- verify: membrane
local V = require("lib.vcase")
local g, r = 10, 0.2
local h = 0.1 / 2 ^ V.level
local E, nu, rho_m = 1e3, 0.3, 10
local c = math.sqrt(E / (rho_m * (1 - nu * nu))) / 0.75
local sim = V.sim{ domain = {0, 0, 1, 1}, cell = h, dt = 0.4 * h / c, gravity = {0, -g} }
local gas = sim:body{ material = lamina.gas{ rho = 1, p = 3, gamma = 1.4 }, ppc = 4, fill = "clipped",
                      name = "gas", region = lamina.disk{ center = {0.5, 0.45}, radius = r } }
local skin = lamina.membrane{ rho = rho_m, E = E, nu = nu, thickness = 0.01, law = "plane_stress" }
local count = math.ceil(2 * math.pi * r / (h / 2))
local mem = V.membrane(sim, { material = skin, count = count, name = "skin",
                              curve = lamina.arc{ center = {0.5, 0.45}, radius = r, from = 0, to = 360 } })
local e0 = sim:energy().total
local scale = (gas:mass() + mem:mass()) * g * 0.25
local rise, out = 0, 0
sim:every(1e-3, function()
  rise = math.max(rise, sim:energy().total - e0)
  out = math.max(out, (mem:escaped(gas)))   -- the count alone, not depth and grazers too
end)
sim:run{ t_end = 0.6 }
V.result{ quantity = "energy_rise", value = rise, exact = 0, scale = scale, h = h }
V.result{ quantity = "gas_outside", value = out, exact = 0, scale = #gas, h = h }
