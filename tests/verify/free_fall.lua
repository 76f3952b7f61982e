-- Verification case (issue 30 item 1): free fall. An elastic disk (radius
-- 0.2, E = 1e4, rho = 1, nu = 0.3, 4 points a cell) at rest at height 1.5
-- in a domain whose sides are far, under g = 10, for t = 0.4.
-- Exact (Newton: no force but its weight, which acts on every point alike,
-- so the body stays unstressed): its centre of mass falls g t^2 / 2 = 0.8
-- and moves at g t = 4. Measured: the fall and the speed at t = 0.4.
-- Resolution: level 1, 2 = cell 0.1, 0.05.
local V = require("lib.vcase")
local g, T = 10, 0.4
local h = 0.2 / 2 ^ V.level
local sim = V.sim{ domain = {0, 0, 1, 2}, cell = h, dt = 0.2 * h / 100, gravity = {0, -g} }
local mat = lamina.elastic{ rho = 1, E = 1e4, nu = 0.3, plane = "strain" }
local disk = sim:body{ material = mat, ppc = 4, region = lamina.disk{ center = {0.5, 1.5}, radius = 0.2 } }
local _, y0 = disk:com()
sim:run{ t_end = T }
local _, y1 = disk:com()
local _, vy = disk:velocity()
V.result{ quantity = "fall", value = y0 - y1, exact = 0.5 * g * sim.t ^ 2, h = h }
V.result{ quantity = "speed", value = -vy, exact = g * sim.t, h = h }
