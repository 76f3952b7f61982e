-- Sod's shock tube in 3D (issue 34; [F] §4.1, Fig 6; docs/3d.md): a tube
-- 1 m long along z and 2 x 2 cells square between symmetry faces, closed
-- at both ends; gas at rho = 1, p = 1 in the lower half, rho = 0.125,
-- p = 0.1 in the upper, gamma = 1.4, the paper's artificial viscosity.
-- What to look for: a shock running up the tube (at z = 0.75 by t =
-- 0.143), the contact behind it and a rarefaction running down; between
-- contact and shock the density and pressure sit near the exact star state
-- (p* = 0.30313, rho*R = 0.26557, u* = 0.92745, shock speed 1.75216: the
-- exact Riemann solution, Toro, Riemann Solvers, §4.3, test 1; our
-- assets/lua/riemann.lua gives the same digits). tests/physics/sim3_sod.lua
-- checks this scene against the exact solution. Between the fan and the
-- contact the pressure sits low and noisy, as on the 2D page (issue 30's
-- left plateau: the same law, the same scheme).
-- Writes out/sod3d/profile.png and profile.csv (density and pressure along
-- the tube at the end, the means over each cross-section). Runs in about a
-- second: lamina run scripts/examples/sod3d.lua
local t_end = lamina.param("t_end", 0.143)
local out   = lamina.param("out", "out/sod3d")
local dx = 0.005
local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, 2 * dx, 2 * dx, 1}, cell = dx, dt = 1e-4,
                        basis = "linear",
                        boundary = { x0 = "symmetry", x1 = "symmetry", y0 = "symmetry",
                                     y1 = "symmetry", z0 = "fixed", z1 = "fixed" } }
local function half(z0, z1)
  return lamina.box{ x0 = 0, y0 = 0, z0 = z0, x1 = 2 * dx, y1 = 2 * dx, z1 = z1 }
end
-- 3 points a cell along the tube, one a cell across (the 2D page's ppc = {3, 1})
local high = sim:body{ material = lamina.gas{ rho = 1, p = 1, gamma = 1.4, av = true },
                       ppc = {1, 1, 3}, region = half(0, 0.5), name = "high" }
local low  = sim:body{ material = lamina.gas{ rho = 0.125, p = 0.1, gamma = 1.4, av = true },
                       ppc = {1, 1, 3}, region = half(0.5, 1), name = "low" }
print(string.format("%d particles; Courant number %.3f", sim.n, sim:courant_number()))
-- each particle's station along the tube, from where it starts (the gas
-- compresses behind the shock, so the stations move closer together)
local station = {}
for _, b in ipairs{high, low} do
  local q, st = b:particles(), {}
  for i = 1, q.n do st[i] = math.floor(q.z[i] / (dx / 3)) end
  station[b] = st
end
sim:run{ t_end = t_end }

-- the means over each cross-section (a station's four particles)
local z, rho, p, n = {}, {}, {}, {}
for _, b in ipairs{high, low} do
  local q = b:particles()
  for i = 1, q.n do
    local k = station[b][i]
    if not n[k] then n[k], z[k], rho[k], p[k] = 0, 0, 0, 0 end
    n[k], z[k], rho[k], p[k] = n[k] + 1, z[k] + q.z[i], rho[k] + q.rho[i], p[k] + q.pressure[i]
  end
end
local keys = {}
for k in pairs(n) do keys[#keys + 1] = k end
table.sort(keys)
local zs, rs, ps = {}, {}, {}
for _, k in ipairs(keys) do
  zs[#zs + 1], rs[#rs + 1], ps[#ps + 1] = z[k] / n[k], rho[k] / n[k], p[k] / n[k]
end
lamina.plot{ file = out .. "/profile.png", csv = true,
             title = string.format("Sod's tube along z, t = %.3f s", sim.t),
             xlabel = "z (m)", ylabel = "density, pressure",
             series = { { x = zs, y = rs, label = "density" },
                        { x = zs, y = ps, label = "pressure (gamma - 1) rho e" } } }
-- the star state between the contact (speed u* = 0.92745) and the shock
-- (1.75216), a fifth of the gap kept clear at each end (tests/physics/sod.lua's window)
local u_star, s_shock = 0.92745, 1.75216
local gap = (s_shock - u_star) * sim.t
local a, b = 0.5 + u_star * sim.t + 0.2 * gap, 0.5 + s_shock * sim.t - 0.2 * gap
local sr, sp, m = 0, 0, 0
for i = 1, #zs do
  if zs[i] > a and zs[i] < b then sr, sp, m = sr + rs[i], sp + ps[i], m + 1 end
end
if m > 0 then
  print(string.format("t = %.3f: between contact and shock rho %.4f (exact 0.26557), p %.4f "
                      .. "(exact 0.30313) over %d stations", sim.t, sr / m, sp / m, m))
end
print("wrote " .. out .. "/profile.png and profile.csv")
