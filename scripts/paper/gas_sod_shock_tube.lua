-- title: Sod's shock tube: the gas model against the exact Riemann solution
-- source: York, Sulsky & Schreyer 2000 (fluid-membrane), §4.1, Figs 5 and 6
-- look: density, velocity, pressure and internal energy along x at
--   t = 0.143 follow the dashed exact solution: the rarefaction on the left,
--   the contact near 0.63 and the shock at 0.75, slightly smeared by the
--   artificial viscosity; a small dip at the contact where the diaphragm was
-- checks: shock position within 2 cells, post-shock plateau pressure and
--   density within 5 % of exact
-- assumed: [F]'s set-up: 200 x 1 cells of 0.005, 3 points per cell in a row,
--   AV g = sqrt(2) dx, lambda = 0.75, c1 = c2 = 1; dt = 1e-4 (not given);
--   the AV formula as reconstructed in src/mpm/material_gas.c (eq 24 lost a
--   square in print); values plotted at the particles, not at grid nodes
-- visual: t_end=0.05
-- thumb: fig6_density.png
local out = lamina.param("out", "out/gas_sod_shock_tube")
local t_end = lamina.param("t_end", 0.143)
local riemann = require("riemann")

local dx = 0.005
local sim = lamina.sim{ domain = {0, 0, 1, dx}, cell = dx, dt = 1e-4,
                        boundary = { left = "fixed", right = "fixed",
                                     bottom = "symmetry", top = "symmetry" } }
local hi = lamina.gas{ rho = 1, p = 1, gamma = 1.4, av = true }
local lo = lamina.gas{ rho = 0.125, p = 0.1, gamma = 1.4, av = true }
local L = sim:body{ material = hi, ppc = {3, 1}, name = "left",
                    region = lamina.rect{ x0 = 0, y0 = 0, x1 = 0.5, y1 = dx } }
local R = sim:body{ material = lo, ppc = {3, 1}, name = "right",
                    region = lamina.rect{ x0 = 0.5, y0 = 0, x1 = 1, y1 = dx } }
sim:run{ t_end = t_end }

local exact = riemann.solve{ left = {1, 0, 1}, right = {0.125, 0, 0.1}, gamma = 1.4 }
local x, rho, u, p, e = {}, {}, {}, {}, {}
for _, b in ipairs{L, R} do
  local q = b:particles()
  for i = 1, q.n do
    x[#x + 1], rho[#rho + 1], u[#u + 1], p[#p + 1], e[#e + 1] = q.x[i], q.rho[i], q.vx[i], q.p[i], q.e[i]
  end
end
local xe, re, ue, pe, ee = {}, {}, {}, {}, {}
for i = 0, 1000 do
  local xi = i / 1000
  xe[#xe + 1] = xi
  re[#re + 1], ue[#ue + 1], pe[#pe + 1], ee[#ee + 1] = exact:sample((xi - 0.5) / sim.t)
end
for _, f in ipairs{ {"density", rho, re}, {"velocity", u, ue}, {"pressure", p, pe},
                    {"energy", e, ee} } do
  lamina.plot{ file = string.format("%s/fig6_%s.png", out, f[1]), csv = true, width = 640, height = 400,
               title = string.format("Fig 6: %s at t = %.3f", f[1], sim.t), xlabel = "x", ylabel = f[1],
               legend = "best",
               series = { { x = x, y = f[2], label = "MPM (particles)" },
                          { x = xe, y = f[3], label = "exact", dashed = true, color = 8 } } }
end

local x_shock = 0.5 + exact.shock_speed * sim.t
local mid = 0.5 * (exact.rho_star_right + 0.125)
local found = -1
for i = #x, 2, -1 do
  if rho[i - 1] >= mid and rho[i] < mid then
    found = x[i - 1] + (x[i] - x[i - 1]) * (rho[i - 1] - mid) / (rho[i - 1] - rho[i])
    break
  end
end
local xc = 0.5 + exact.u_star * sim.t
local a, b = xc + 0.2 * (x_shock - xc), x_shock - 0.2 * (x_shock - xc)
local sr, sp, n = 0, 0, 0
for i = 1, #x do if x[i] > a and x[i] < b then sr, sp, n = sr + rho[i], sp + p[i], n + 1 end end
lamina.report{
  shock_position = { found, paper = x_shock, tol = 2 * dx },
  plateau_pressure = { n > 0 and sp / n or -1, paper = exact.p_star, tol = 0.05 * exact.p_star },
  plateau_density = { n > 0 and sr / n or -1, paper = exact.rho_star_right,
                      tol = 0.05 * exact.rho_star_right },
  state_hash = sim:hash(),
}
