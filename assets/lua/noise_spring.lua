-- noise_spring.lua - the ten-point spring of [T] App. A.2 (Fig 102), shared
-- by scripts/paper/noise_spring.lua and tests/physics/noise_spring.lua.
--
-- [T] gives the picture, not the numbers: ten material points numbered top
-- to bottom, the top one held (zero-velocity BC), the bottom one 100 x the
-- others' mass, gravity; point 6 crosses a cell edge near the apex of the
-- oscillation; the stresses are 1.2e5-1.8e5 (Figs 103-104). Chosen here:
-- a string (law "uniaxial") of E 1e7, rho 2500, thickness 0.01, hanging
-- from the fixed top wall of a 0.2-wide column (symmetry sides) along the
-- middle of the first column of cells, x = 0.05 (on a node line, as
-- scripts/paper/membrane_spring_mass.lua, the point quadrature is the same,
-- but the cell-centred stress would put half the force on the empty node
-- column beside it: o.x = 0.1 shows that),
-- cell 0.1, g 10, released unstretched: the static stress is
-- 100 m g / A ~ 1e5 and the swing takes it from 0 to ~2e5, so the cells
-- hold 1.2e5-1.8e5 near the bottom apex as in Figs 103-104. Length 0.3545:
-- 2.5 points per cell ("a cell with two other points ... the cell above left
-- with only two"), and point 6 starts 0.0031 above the edge y = 1.8 and
-- reaches 0.0036 below its start, so it crosses at 86 % of its travel, near
-- the apex, where its speed is small ([T] A.2). dt = 0.5 h/c, below the
-- segment forces' limit, the same for every variant.
local M = {}

M.E, M.rho, M.A, M.h, M.g, M.N = 1e7, 2500, 0.01, 0.1, 10, 10
M.L, M.top, M.cf = 0.3545, 2.0, 0.5
M.m0 = M.rho * M.A * M.L / (M.N - 1)          -- one point of the ten
M.mass = 100 * M.m0                           -- the heavy bottom point
M.k = M.E * M.A / M.L
M.T = 2 * math.pi / math.sqrt(M.k / M.mass)   -- period of the mass on the spring
M.d_static = M.mass * M.g / M.k
-- the swing's energy: the largest kinetic energy of the ideal spring
M.E_ref = 0.5 * M.k * M.d_static ^ 2
M.dt = M.cf * M.h / math.sqrt(M.E / M.rho)

-- One variant: o.stress, o.force, o.scheme as the engine's keys, o.count
-- points (the same string and end mass: more points per cell), o.x the
-- string's line (0.05), o.sim extra
-- lamina.sim keys (a basis). Returns sim, string, or nil and the error
-- when lamina.sim refuses the variant (a basis this build lacks).
function M.setup(o)
  o = o or {}
  local def = { domain = {0, 1.4, 0.2, M.top}, cell = M.h, dt = M.dt, gravity = {0, -M.g},
                stress = o.stress, scheme = o.scheme, basis = "linear",
                mass = "lumped",   -- the papers' lumped mass ([M] eq 7), every variant
                boundary = { left = "symmetry", right = "symmetry" } }
  for key, v in pairs(o.sim or {}) do def[key] = v end
  local ok, sim = pcall(lamina.sim, def)
  if not ok then return nil, sim end
  local wire = lamina.membrane{ rho = M.rho, E = M.E, nu = 0, thickness = M.A, law = "uniaxial" }
  local s = sim:membrane{ material = wire, count = o.count or M.N, end_mass = M.mass,
                          force = o.force or "point", name = "spring",
                          curve = lamina.segment{ from = {o.x or 0.05, M.top},
                                                 to = {o.x or 0.05, M.top - M.L} } }
  return sim, s
end

-- The energy growth: the largest rise of the total energy averaged over a
-- period, against the first period's mean, in units of the swing's energy
-- E_ref (the start's energy is 0: unstretched, at rest, potential datum
-- at the seeding positions).
function M.growth(rec)
  local t = rec:column("t")
  local e0 = rec:mean("total", 0, M.T)
  local worst, last = -math.huge, 0
  local n = math.floor(t[#t] / M.T + 1e-9)
  for k = 2, n do
    last = (rec:mean("total", (k - 1) * M.T, k * M.T) - e0) / M.E_ref
    worst = math.max(worst, last)
  end
  return worst, last
end

-- Nodal force f_y of each node row (the string at mid-cell splits its
-- weights half and half between the row's two nodes: the sum is shown)
-- from the point stresses, as step 2 forms it with point quadrature:
-- f_i = -sum_p V_p sigma_p . grad N_i(x_p) + m_i g (fi: the internal part
-- alone); and each cell's volume-weighted mean sigma_y (the "sy" of Figs
-- 103-104).
M.Y0 = 1.4      -- the domain's bottom: node rows at Y0 + j h
function M.probe(s)
  local P = s:particles()
  local f, fi, sy, vol = {}, {}, {}, {}
  for q = 1, P.n do
    local fy = (P.y[q] - M.Y0) / M.h
    local j = math.max(0, math.floor(fy))
    local eta = fy - j
    local V = P.mass[q] / P.rho[q]
    local push = V * P.syy[q] / M.h
    f[j] = (f[j] or 0) + push - M.g * P.mass[q] * (1 - eta)
    f[j + 1] = (f[j + 1] or 0) - push - M.g * P.mass[q] * eta
    fi[j] = (fi[j] or 0) + push
    fi[j + 1] = (fi[j + 1] or 0) - push
    sy[j] = (sy[j] or 0) + V * P.syy[q]
    vol[j] = (vol[j] or 0) + V
  end
  for j, v in pairs(vol) do sy[j] = sy[j] / v end
  return { f = f, fi = fi, sy = sy, y6 = P.y[6], row6 = math.floor((P.y[6] - M.Y0) / M.h) }
end

return M
