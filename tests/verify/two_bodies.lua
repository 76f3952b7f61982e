-- Verification case (issue 30 item 1): two bodies approaching in one
-- velocity field (lamina's default: no sim:contact pair). Two elastic bars
-- 1 x 2 (E = 1e4, rho = 1, nu = 0.3, plane stress, 4 points a cell), the
-- left one moving right at 1, the right one at rest, 1.0 apart (their
-- material edges: the region boundaries).
-- Exact: two bodies exchange no momentum until they touch, at gap 0
-- (t = 1.0). In one grid field they exchange it as soon as a grid node
-- carries mass of both (the single velocity field of [M] §4.1): the
-- measured quantity is the gap at the first step after which the right bar
-- has any momentum (|p| > 1e-12 of the left's), gap = 1.0 - (the left bar's
-- travel), its error in per cent of a cell (100 %: they interact a cell
-- apart; the order of convergence in length is then 1, as the gap scales
-- with the cell). Resolution: level 1, 2 = cell 0.25, 0.125.
local V = require("lib.vcase")
local h = 0.5 / 2 ^ V.level
local sim = V.sim{ domain = {0, 0, 4, 5}, cell = h, dt = 0.2 * h / 100 }
local mat = lamina.elastic{ rho = 1, E = 1e4, nu = 0.3, plane = "stress" }
local left = sim:body{ material = mat, ppc = 4, velocity = {1, 0},
                       region = lamina.rect{ min = {0.5, 1.5}, max = {1.5, 3.5} } }
local right = sim:body{ material = mat, ppc = 4, region = lamina.rect{ min = {2.5, 1.5}, max = {3.5, 3.5} } }
local x0 = left:com()
local p0 = left:mass() * 1
local gap
sim:every(sim.dt, function(s)
  if gap then return end
  local vx, vy = right:velocity()
  if math.sqrt(vx * vx + vy * vy) * right:mass() > 1e-12 * p0 then
    gap = 1.0 - (left:com() - x0)
  end
end)
sim:run{ t_end = 1.2 }
V.result{ quantity = "interaction_gap", value = gap or 0, exact = 0, scale = h, h = h }
