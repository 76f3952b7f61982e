-- Verification case (issue 30 item 1): a body resting on the floor (no
-- creep, no sinking). An elastic block 0.5 x 0.5 (E = 1e4, rho = 1,
-- nu = 0, plane strain; 4 points a cell) laid unstressed on the fixed floor
-- y = 0 under g = 10 and released.
-- Exact: with nu = 0 every column is a 1D bar under its own weight
-- (Timoshenko & Goodier, Theory of Elasticity §100's column): sigma_yy =
-- -rho g (H - y), u(y) = -rho g (H y - y^2/2) / E, and the mean of u over
-- the block, the drop of its centre of mass in equilibrium, is
-- delta = rho g H^2 / (3E) = 8.333e-5. Released unstressed, the block rings
-- about that state (period 4H/c = 0.02 s), so the time mean of the drop is
-- delta and it does not change with time. Measured: the mean drop over
-- t = 0.1-0.5 (settle), and the change of the mean drop from t = 0.1-0.2 to
-- t = 0.4-0.5 (creep, exact 0; its error in per cent of delta), each mean
-- taken over the whole ringing periods in its window (V.ringing_mean: the
-- periods' ends at the drop's upward crossings of its mean). The ringing's
-- amplitude is about delta (it starts unstressed), so a window ending part-way
-- through a period carries up to delta / periods with it: five periods in
-- 0.1 s gave a "creep" of 3.8 % of delta from the sampling alone
-- (docs/robustness.md "Verification cases on the default").
-- Resolution: level 1, 2, 3 = cell 0.1, 0.05, 0.025.
local V = require("lib.vcase")
local H, E, rho, g = 0.5, 1e4, 1, 10
local h = 0.2 / 2 ^ V.level
local c = math.sqrt(E / rho)
local delta = rho * g * H * H / (3 * E)
local sim = V.sim{ domain = {0, 0, 1.5, 1.0}, cell = h, dt = 0.2 * h / c, gravity = {0, -g} }
local mat = lamina.elastic{ rho = rho, E = E, nu = 0, plane = "strain" }
local block = sim:body{ material = mat, ppc = 4, region = lamina.rect{ min = {0.5, 0}, max = {1.0, H} } }
local _, y0 = block:com()
local rec = sim:record{ every = 2.5e-4, values = { drop = function() return y0 - select(2, block:com()) end } }
sim:run{ t_end = 0.5 }
local t, drop = rec:column("t"), rec:column("drop")
local settle = V.ringing_mean(t, drop, 0.1, 0.5)
V.result{ quantity = "settle", value = settle, exact = delta, h = h }
V.result{ quantity = "creep", value = V.ringing_mean(t, drop, 0.4, 0.5) - V.ringing_mean(t, drop, 0.1, 0.2),
          exact = 0, scale = delta, h = h }
