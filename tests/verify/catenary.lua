-- Verification case (issue 30 item 1): a hanging chain under gravity (the
-- elastic catenary). A uniaxial string of natural length L0 = 1.2
-- (E = 1e5, thickness t = 0.01: EA = 1000; rho t = 1, g = 10: weight
-- w = 10 per unit natural length), one_way (a chain takes no compression),
-- its ends held by body:pin at (0.25, 0.8) and (1.25, 0.8): span l = 1.
--
-- Exact (the elastic catenary, Irvine, Cable Structures §2.2, with
-- lamina's logarithmic strain): s the natural arc length from the lowest
-- point, the tension is T(s) = sqrt(H^2 + (w s)^2) (H the horizontal
-- tension, the same everywhere: no horizontal load), the stretch
-- lambda = exp(T / EA) (sigma = E ln lambda, docs/api.md lamina.membrane),
-- and the slope dy/dx = w s / H, so
--   dx/ds = lambda H / T,  dy/ds = lambda w s / T.
-- H is the root of 2 int_0^{L0/2} lambda H / T ds = l (bisection), and the
-- sag is int_0^{L0/2} lambda w s / T ds. Both are
-- integrated here by Simpson's rule on 2000 intervals (exact to 1e-10).
-- The chain is laid on that curve with the strain ln lambda of each point
-- (initial_strain as a function of the arc-length fraction u) and released:
-- an exact method would not move. Measured, as time means over 2 s (about
-- two of its swinging periods): the sag of the lowest point below the
-- supports, and H as the left pin's reaction (pin:reaction, docs/api.md).
-- Resolution: level 1, 2, 3 = cell 1/16, 1/32, 1/64; points h/2 apart.
-- verify: membrane
local V = require("lib.vcase")
local L0, E, t, rho, g, l = 1.2, 1e5, 0.01, 100, 10, 1
local EA, w = E * t, rho * t * g
local x0, ys = 0.25, 0.8

-- the half chain for a given H: half span, sag, and a table of present
-- arc length -> (x, y, strain) from the lowest point
local function half(H, keep)
  local n = 2000
  local ds = L0 / 2 / n
  local function f(s)
    local T = math.sqrt(H * H + (w * s) ^ 2)
    local lam = math.exp(T / EA)
    return lam * H / T, lam * w * s / T, lam, T
  end
  local X, Y, S = 0, 0, 0
  local tab = keep and { {0, 0, 0, H / EA} } or nil
  for i = 1, n do
    local a, b = (i - 1) * ds, i * ds
    local xa, ya, la = f(a)
    local xm, ym, lm = f(0.5 * (a + b))
    local xb, yb, lb, Tb = f(b)
    X = X + ds / 6 * (xa + 4 * xm + xb)
    Y = Y + ds / 6 * (ya + 4 * ym + yb)
    S = S + ds / 6 * (la + 4 * lm + lb)
    if keep then tab[#tab + 1] = {S, X, Y, Tb / EA} end
  end
  return X, Y, S, tab
end
local lo, hi = 0.1, 1e4
for _ = 1, 200 do
  local mid = 0.5 * (lo + hi)
  if half(mid) * 2 < l then lo = mid else hi = mid end
end
local H = 0.5 * (lo + hi)
local _, sag, S, tab = half(H, true)

-- position and strain at present arc length sigma from the left end
local function at(sigma)
  local d = math.abs(sigma - S)                  -- distance from the middle
  local j = 1
  while j < #tab - 1 and tab[j + 1][1] < d do j = j + 1 end
  local a, b = tab[j], tab[j + 1]
  local f = (d - a[1]) / (b[1] - a[1])
  local x = a[2] + f * (b[2] - a[2])
  local y = a[3] + f * (b[3] - a[3])
  local e = a[4] + f * (b[4] - a[4])
  return x0 + l / 2 + (sigma < S and -x or x), ys - sag + y, e
end

local h = 1 / (8 * 2 ^ V.level)
local c = math.sqrt(E / rho) / 0.75
local sim = V.sim{ domain = {0, 0, 1.5, 1.0}, cell = h, dt = 0.4 * h / c, gravity = {0, -g} }
local chain = lamina.membrane{ rho = rho, E = E, nu = 0, thickness = t, law = "uniaxial", one_way = true }
local count = math.floor(2 * (2 * S) / h + 0.5) + 1
local m = V.membrane(sim, { material = chain, count = count, name = "chain",
  curve = function(u) local x, y = at(u * 2 * S); return x, y end,
  initial_strain = function(u) local _, _, e = at(u * 2 * S); return e end })
local left = m:pin{ points = {1} }
m:pin{ points = {count} }
local rec = sim:record{ every = 0.01,
  values = { sag = function()
               local q = m:particles()
               local low = math.huge
               for i = 1, q.n do low = math.min(low, q.y[i]) end
               return ys - low
             end,
             H = function() return -(left:reaction()) end } }
sim:run{ t_end = 2.0 }
V.result{ quantity = "sag", value = rec:mean("sag", 0.01, 2.0), exact = sag, h = h }
V.result{ quantity = "horizontal_tension", value = rec:mean("H", 0.01, 2.0), exact = H, h = h }
