-- running_sphere3.lua - the running sphere of the 3D normals pages
-- (normals3d_running_fig5, normals3d_running_fig11: [N] Figs 5 and 11's
-- constructions on a membrane in a simulation, issue 34 item 5).
--
-- The balloon of test_sim3_membrane.c and physics.sim3_membrane: a sphere
-- r0 = 0.3 at the centre of the unit box, cell h = 0.05 on the quadratic
-- B-spline grid (MUSL), points at spacing h/3 (a Fibonacci lattice, each of
-- area 4 pi r0^2 / N exactly), a plane-stress sheet (E = 1 MPa, nu = 0.3,
-- t = 1 mm, rho = 1000), p = 100 Pa on its points, damped (200 1/s, the
-- breathing mode's 176 rad/s at 0.57 of critical), dt = 5e-4 (0.3 of the
-- sheet's Courant limit h / c, c = 1048 m/s). It inflates to where
-- Laplace's 2 T / r = p holds, T = E t ln(r / r0) / (1 - nu): r = 0.303201.
--
-- The membrane steps with its own normals from connectivity (t1 x t2 of
-- the convected frame), so the construction decides nothing in the run;
-- every `every` steps both constructions are made from the points alone
-- (m:normals: the trilinear 8 x 8 fit of [N] Fig 5 and the triquadratic
-- 27 x 27 of Fig 11 on the running grid's centred elements) and measured
-- against the radial direction from the centre.
local M = {}

M.h, M.r0, M.p, M.c = 0.05, 0.3, 100, {0.5, 0.5, 0.5}
M.E, M.nu, M.t = 1e6, 0.3, 1e-3

function M.setup()
  local skin = lamina.membrane{ rho = 1000, E = M.E, nu = M.nu, thickness = M.t, law = "plane_stress" }
  local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, 1, 1, 1}, cell = M.h, dt = 5e-4,
                          basis = "bspline2", scheme = "musl" }
  local m = sim:membrane{ material = skin, spacing = M.h / 3, pressure = M.p, damping = 200,
                          surface = lamina.sphere{ center = M.c, radius = M.r0 } }
  return sim, m
end

-- The radius Laplace's law gives (ln(r / r0) = p r (1 - nu) / (2 E t),
-- fixed-point iteration: a contraction, p (1 - nu) r / (2 E t) = 0.01).
function M.laplace_radius()
  local r = M.r0
  for _ = 1, 100 do r = M.r0 * math.exp(M.p * r * (1 - M.nu) / (2 * M.E * M.t)) end
  return r
end

-- Each construction's angles to radial at the present points: the worst,
-- the rms and how many points are beyond 2 degrees.
function M.angles(m)
  local p = m:particles()
  local out = {}
  for _, basis in ipairs{"linear", "quadratic"} do
    local n = m:normals(basis)
    local worst, ss, beyond = 0, 0, 0
    for i = 1, p.n do
      local dx, dy, dz = p.x[i] - M.c[1], p.y[i] - M.c[2], p.z[i] - M.c[3]
      local r = math.sqrt(dx * dx + dy * dy + dz * dz)
      local cs = (n.nx[i] * dx + n.ny[i] * dy + n.nz[i] * dz) / r
      local a = math.deg(math.acos(math.max(-1, math.min(1, cs))))
      worst = math.max(worst, a)
      ss = ss + a * a
      if a > 2 then beyond = beyond + 1 end
    end
    out[basis] = { worst = worst, rms = math.sqrt(ss / p.n), beyond = beyond, undefined = n.undefined }
  end
  return out
end

-- A close-up camera on the point whose trilinear normal is worst (both
-- pages look at the same spot): aimed at the point, from 50 degrees round
-- the sphere from its radial direction, so that arrows show side-on.
function M.closeup(m)
  local p, n = m:particles(), m:normals("linear")
  local worst, at = -1, 1
  for i = 1, p.n do
    local dx, dy, dz = p.x[i] - M.c[1], p.y[i] - M.c[2], p.z[i] - M.c[3]
    local r = math.sqrt(dx * dx + dy * dy + dz * dz)
    local a = math.acos(math.max(-1, math.min(1, (n.nx[i] * dx + n.ny[i] * dy + n.nz[i] * dz) / r)))
    if a > worst then worst, at = a, i end
  end
  local dx, dy, dz = p.x[at] - M.c[1], p.y[at] - M.c[2], p.z[at] - M.c[3]
  local r = math.sqrt(dx * dx + dy * dy + dz * dz)
  local el = math.deg(math.asin(dz / r))
  return { target = {p.x[at], p.y[at], p.z[at]}, distance = 0.25,
           azimuth = math.deg(math.atan(dy, dx)) + 50, elevation = math.max(-60, math.min(60, el)) },
         math.deg(worst)
end

-- The mean radius and the mean tension over the points.
function M.state(m)
  local p = m:particles()
  local rm, Tm = 0, 0
  for i = 1, p.n do
    rm = rm + math.sqrt((p.x[i] - M.c[1])^2 + (p.y[i] - M.c[2])^2 + (p.z[i] - M.c[3])^2) / p.n
    Tm = Tm + p.tension[i] / p.n
  end
  return rm, Tm
end

-- Runs to `steps`, sampling every `every` steps (and at 0); calls
-- shot(t, step) at the steps listed in `shots`. Returns the series.
function M.run(sim, m, steps, every, shots, shot)
  local s = { t = {}, linear_worst = {}, linear_rms = {}, quadratic_worst = {}, quadratic_rms = {},
              linear_beyond = {}, quadratic_beyond = {}, undefined = 0 }
  local want = {}
  for _, k in ipairs(shots or {}) do want[k] = true end
  for k = 0, steps do
    if k % every == 0 then
      local a = M.angles(m)
      s.t[#s.t + 1] = k * sim.dt
      for _, b in ipairs{"linear", "quadratic"} do
        s[b .. "_worst"][#s.t] = a[b].worst
        s[b .. "_rms"][#s.t] = a[b].rms
        s[b .. "_beyond"][#s.t] = a[b].beyond
        s.undefined = math.max(s.undefined, a[b].undefined)
      end
    end
    if want[k] and shot then shot(k * sim.dt, k) end
    if k < steps then sim:step(1) end
  end
  return s
end

function M.max(a)
  local v = -math.huge
  for _, x in ipairs(a) do v = math.max(v, x) end
  return v
end

return M
