-- Issue 36 item 1: lamina.sim{viscous_limit = kappa} (src/mpm/material_gas.c,
-- lm_gas_mu; docs/performance.md "The gas's step beside a membrane"). The
-- gas's viscous stress 2 mu edot is explicit: a diffusion of the velocity
-- with nu = mu / rho, stable only while nu dt / h^2 stays below a bound of
-- order 1/4 in 2-D. A point rarefied far enough crosses it at a step the
-- Courant check allows; the limit lowers such a point's mu to
-- kappa rho h^2 / dt.
--
-- The scene: a shear wave v_x = A cos(pi y / H) in a pressureless gas
-- (e = 0) filling [0, 2] x [0, H], symmetry walls at y = 0 and H (v_y = 0,
-- v_x free), free sides at x; the amplitude is taken over the points in
-- x in [0.5, 1.5], where the free ends (whose shear stress must vanish)
-- have not reached by t = 0.2 (sqrt(nu t) <= 0.1). Closed form (ours): the
-- viscous decay A(t) = A exp(-nu k^2 t), k = pi / H, at the run's own t.
-- 1. Dense (rho = 1, nu dt / h^2 = 0.02): the limit does not act; the run
--    with viscous_limit = 0.1 has the plain run's hash, and the amplitude
--    follows the closed form with nu = mu / rho.
-- 2. Rarefied (rho = 0.01, the same mu and dt: nu dt / h^2 = 2): the plain
--    step is unstable — the velocities grow past their start (or the run
--    stops) — and with viscous_limit = 0.1 every point has mu = kappa rho
--    h^2 / dt, so the wave decays with nu = kappa h^2 / dt: the closed form
--    with that nu, and the plain step of a dense gas given that nu (rho = 1,
--    mu = kappa h^2 / dt; its nu dt / h^2 = kappa) to 0.1 %.
-- 3. viscous_limit reads back; 0 is the plain step.
local H, h, A, mu = 1, 1 / 16, 0.1, 0.01
local k = math.pi / H
local dt = 0.02 * h * h / mu          -- nu dt / h^2 = 0.02 at rho = 1
local t_end = 0.2

local function run(rho, limit, mu_run)
  local sim = lamina.sim{ domain = {-0.5, 0, 2.5, H}, cell = h, dt = dt, viscous_limit = limit,
                          boundary = { left = "free", right = "free", bottom = "symmetry", top = "symmetry" } }
  local gas = sim:body{ material = lamina.gas{ rho = rho, e = 0, mu = mu_run or mu }, ppc = {3, 3}, name = "gas",
                        region = lamina.rect{ x0 = 0, y0 = 0, x1 = 2, y1 = H },
                        velocity = function(_, y) return A * math.cos(k * y), 0 end }
  -- the mode's amplitude: sum m v_x cos(k y) / sum m cos^2(k y)
  local function amplitude()
    local p = gas:particles()
    local num, den, vmax = 0, 0, 0
    for i = 1, p.n do
      if p.x[i] > 0.5 and p.x[i] < 1.5 then
        local c = math.cos(k * p.y[i])
        num, den = num + p.mass[i] * p.vx[i] * c, den + p.mass[i] * c * c
      end
      vmax = math.max(vmax, math.abs(p.vx[i]), math.abs(p.vy[i]))
    end
    return num / den, vmax
  end
  local ok, err = pcall(function() sim:run{ t_end = t_end } end)
  local a, vmax = amplitude()
  return { ok = ok, err = err, a = a, vmax = vmax, hash = sim:hash(), limit = sim.viscous_limit, t = sim.t }
end

-- 1. dense
local plain = run(1, 0)
local limited = run(1, 0.1)
local want = A * math.exp(-(mu / 1) * k * k * plain.t)
print(string.format("dense: A(t) %.6f plain, %.6f limited, closed form %.6f (%+.3f %%)", plain.a, limited.a,
                    want, 100 * (plain.a / want - 1)))
assert(plain.ok and limited.ok, "dense: a run stopped")
assert(plain.hash == limited.hash, "dense: viscous_limit changed a run it should not touch")
assert(limited.limit == 0.1 and plain.limit == 0, "viscous_limit does not read back")
assert(math.abs(plain.a / want - 1) < 0.01, string.format("dense: decay off the closed form by %.3f %%",
                                                         100 * (plain.a / want - 1)))

-- 2. rarefied
local rare = run(0.01, 0)
local capped = run(0.01, 0.1)
local nu_eff = 0.1 * h * h / dt
local want_r = A * math.exp(-nu_eff * k * k * capped.t)
print(string.format("rarefied (nu dt / h^2 = %.2f): plain %s at t = %.4f, largest speed %.3g; "
                    .. "limited A(t) %.6f, closed form with nu = kappa h^2 / dt = %.4f: %.6f (%+.3f %%)",
                    (mu / 0.01) * dt / h ^ 2, rare.ok and "ran" or "stopped", rare.t, rare.vmax, capped.a, nu_eff,
                    want_r, 100 * (capped.a / want_r - 1)))
assert(not rare.ok or rare.vmax > A, "rarefied: the plain step did not go unstable (the check cannot tell)")
assert(capped.ok, "rarefied, limited: " .. tostring(capped.err))
assert(capped.vmax <= A, string.format("rarefied, limited: a speed %.3g above the start's %.3g", capped.vmax, A))
assert(math.abs(capped.a / want_r - 1) < 0.01, string.format("rarefied, limited: decay off the closed form by %.3f %%",
                                                            100 * (capped.a / want_r - 1)))
local same = run(1, 0, nu_eff)
print(string.format("the plain step with nu = %.4f at rho = 1: A(t) %.6f (limited rarefied %+.4f %% from it)", nu_eff,
                    same.a, 100 * (capped.a / same.a - 1)))
assert(same.ok and math.abs(capped.a / same.a - 1) < 1e-3,
       string.format("rarefied, limited: %.4f %% from the plain step with the same nu", 100 * (capped.a / same.a - 1)))
