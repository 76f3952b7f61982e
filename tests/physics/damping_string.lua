-- Issue 35 item 2: lamina.sim{damping = c} on a ringing string, against the
-- closed form, and the energy it removes.
--
-- The string of tests/verify/lib/string_modes.lua (length L = 1 between the
-- fixed side walls, uniaxial, E = 5e4, t = 0.01, rho = 100, stretched by
-- eps0 = 0.01: T = 5, mu = 1, so P = 2 L / sqrt(T / mu) = 0.890 s), cell
-- h = 1/16, laid on mode 1 (amplitude 2e-4 L) and released; run 4 periods
-- with c = 1 /s and, as the reference, with c = 0.
--
-- Exact (ours, from the equation of motion): the damping force -c m v is
-- mass-proportional, so every mode obeys x'' + c x' + w^2 x = 0 and its
-- amplitude decays as exp(-c t / 2); the peaks of |x| half a damped period
-- apart fall by exactly exp(-c T_d / 4), whatever the phase, so the slope of
-- ln|peak| against t is -c / 2.
-- What the grid changes, derived here: the damping acts on the grid velocity
-- v_i = sum_p m_p N_ip v_p / m_i, and the particles take back its
-- interpolation sum_i N_ip v_i (FLIP, [F] eq 12). For a velocity sin(k x)
-- carried by a uniform density, each of the two transfers multiplies it by
-- the quadratic B-spline's Fourier symbol sinc(k h / 2)^3 (the spline is
-- three boxes of width h convolved), so the particles see the rate c S with
-- S = sinc(k h / 2)^6 = 1 - (k h)^2 / 4 + ... = 0.99040 for k = pi / L:
-- the amplitude's rate is c S / 2.
-- Tolerance on c S / 2: the implicit update's own error c dt / 2 (its factor
-- per step is 1 / (1 + c dt), not exp(-c dt)), plus the undamped run's decay
-- rate (its numerical dissipation, measured here, over c / 2), plus 0.1 %
-- for what the continuous symbol leaves out (2 points a cell, not a
-- continuum; the aliased terms are O((k h / 2pi)^3)). Against c / 2 itself
-- the tolerance adds 1 - S.
-- Measured (2026-12-04): slope -0.495326 (c S / 2 = 0.495200: +0.025 %;
-- tolerance 0.20 %); against c / 2: -0.93 % (tolerance 1.16 %).
--
-- Energy: total (sim:energy()) + damped (the damping's work, c dt sum
-- |p_i^L|^2 / m_i a step) is conserved. Tolerance: the undamped run's own
-- drift of its total over the same time (the scheme's energy error, measured
-- here: 7.4e-10, 1.5e-3 of the energy the damped run removes), which the
-- damping, taking motion out, does not add to. Measured: 2.6e-11 (5.5e-5 of
-- the energy damped).
--
-- A body moving freely (an elastic block at uniform velocity, no gravity, no
-- stress): every node it touches has v_i = v, so the implicit update gives
-- exactly v_n = v_0 / (1 + c dt)^n (ours, from v^L = (v + dt f/m)/(1 + c dt)
-- with f = 0), and the damped energy is all of the kinetic energy's drop;
-- both to 1e-12 relative (rounding over the steps).
--
-- On lamina.sim{mass = "membrane"} (--set mass=membrane, ctest
-- physics.damping_string.membrane; issue 30 item 2): the one Neumann step
-- towards the consistent mass multiplies the grid velocity by 2 - S (the
-- consistent mass's symbol over the lumped one is S), so the particles see
-- c S (2 - S) = c (1 - (1 - S)^2); the energy check is the same. Measured
-- (2026-12-05): slope -0.499683 against c S (2 - S) / 2 = 0.499954:
-- -0.054 % (tolerance 0.14 %); total + damped drifts 7.0e-12 (the undamped
-- run 4.6e-11). Before the damping's account read the lumped p_i
-- (damping.c) it drifted 4.9e-9, 1 % of the energy damped.
--
-- Also: bad damping values are refused by name, in lamina.sim{} and live.
local L, E, rho, t, eps0 = 1, 5e4, 100, 0.01, 0.01
local h = 1 / 16
local A = 2e-4 * L

local mass = lamina.param("mass", "lumped")
local function ring(c)
  local c_long = math.sqrt(E / rho) / 0.75        -- the Courant check's segment speed
  local sim = lamina.sim{ domain = {0, 0, L, 0.5}, cell = h, dt = 0.4 * h / c_long,
                          boundary = "fixed", damping = c, mass = mass }
  local wire = lamina.membrane{ rho = rho, E = E, nu = 0, thickness = t, law = "uniaxial" }
  local count = math.floor(2 * L / h + 0.5) + 1
  local s = sim:membrane{ material = wire, count = count, initial_strain = eps0, name = "string",
    curve = function(u) return L * u, 0.25 + A * math.sin(math.pi * u) end }
  local p = s:particles()
  local mu = p.mass[2] / (L / (count - 1))
  local P = 2 * L / math.sqrt(E * eps0 * t / mu)
  local k = (count + 1) // 2                        -- the middle point: the antinode
  local rec = sim:record{ every = sim.dt, energy = true, values = { w = function()
    return s:particles().y[k] - 0.25 end } }
  sim:run{ t_end = 4 * P }
  -- the peaks of |w| (each half period) and the least-squares slope of ln|w|
  local tt, w = rec:column("t"), rec:column("w")
  local n, sx, sy, sxx, sxy = 0, 0, 0, 0, 0
  for i = 2, #w - 1 do
    local a = math.abs(w[i])
    if a >= math.abs(w[i - 1]) and a > math.abs(w[i + 1]) then
      n, sx, sy = n + 1, sx + tt[i], sy + math.log(a)
      sxx, sxy = sxx + tt[i] ^ 2, sxy + tt[i] * math.log(a)
    end
  end
  assert(n >= 6, "too few peaks: " .. n)
  local slope = (n * sxy - sx * sy) / (n * sxx - sx * sx)
  local tot = rec:column("total")
  local damped = c > 0 and rec:column("damped")[#tt] or 0
  assert(damped == sim:energy().damped, "the recorder's damped column is sim:energy().damped")
  assert(sim.mass == mass, "sim.mass reads " .. sim.mass)
  return { slope = slope, P = P, dt = sim.dt, e0 = tot[1], e1 = tot[#tot], damped = damped,
           peaks = n }
end

local c = 1
local r0, r1 = ring(0), ring(c)
local k = math.pi / L
local x = k * h / 2
local S = (math.sin(x) / x) ^ 6
if mass ~= "lumped" then S = S * (2 - S) end   -- the Neumann step (header)
local rate0 = -r0.slope                                -- the undamped run's own decay
local tol = c * r1.dt / 2 + math.abs(rate0) / (c / 2) + 1e-3
local err_S = -r1.slope / (c * S / 2) - 1
local err_c = -r1.slope / (c / 2) - 1
print(string.format("mass %s: P = %.5f s, dt = %.4g, %d peaks; undamped slope %.6f; damped slope %.6f: "
  .. "against c S / 2 = %.6f (S = %.5f) %+.3f %% (tolerance %.2f %%), against c / 2 %+.3f %% "
  .. "(tolerance %.2f %%)", mass, r1.P, r1.dt, r1.peaks, r0.slope, r1.slope, c * S / 2, S,
  100 * err_S, 100 * tol, 100 * err_c, 100 * (tol + 1 - S)))
assert(math.abs(err_S) <= tol, "decay rate against c S / 2")
assert(math.abs(err_c) <= tol + 1 - S, "decay rate against c / 2")

-- energy: total + damped kept
assert(r0.damped == 0, "an undamped run reports damped = 0")
local drift = r1.e1 + r1.damped - r1.e0
print(string.format("energy: total %.12g -> %.12g, damped %.6g: total + damped drifts %.3g "
  .. "(%.2g of the damped; undamped run %.3g)", r1.e0, r1.e1, r1.damped, drift,
  drift / r1.damped, r0.e1 - r0.e0))
assert(r1.damped > 0.5 * (r1.e0 - r1.e1), "damped energy reported")
assert(math.abs(drift) <= math.abs(r0.e1 - r0.e0), "total + damped not conserved: " .. drift)

-- a free body: the closed form of the implicit update
do
  local cf, dt, steps = 7, 1e-3, 50
  local sim = lamina.sim{ domain = {0, 0, 2, 1}, cell = 0.1, dt = dt, damping = cf }
  local b = sim:body{ material = lamina.elastic{ rho = 10, E = 1e4, nu = 0.3 }, ppc = 4,
                      velocity = {0.3, -0.2}, region = function(x, y)
                        return x > 0.6 and x < 1.0 and y > 0.3 and y < 0.7 end }
  local k0 = sim:energy().kinetic
  sim:step(steps)
  local v = b:particles()
  local exact = 1 / (1 + cf * dt) ^ steps
  local worst = 0
  for i = 1, v.n do
    worst = math.max(worst, math.abs(v.vx[i] / 0.3 - exact), math.abs(v.vy[i] / -0.2 - exact))
  end
  local e = sim:energy()
  local gap = (k0 - e.kinetic - e.damped) / (k0 - e.kinetic)
  print(string.format("free body: v / v0 = %.15f (exact %.15f, worst point off by %.2g); "
    .. "kinetic drop %.9g, damped %.9g (%.2g)", v.vx[1] / 0.3, exact, worst, k0 - e.kinetic,
    e.damped, gap))
  assert(worst < 1e-12, "free body: v_n = v_0 / (1 + c dt)^n")
  assert(math.abs(gap) < 1e-12, "free body: damped = the kinetic energy's drop")
end

-- bad values, refused by name (the setting kept)
for _, v in ipairs{ -1, 0 / 0, math.huge } do
  local ok, err = pcall(lamina.sim, { domain = {0, 0, 1, 1}, cell = 0.1, dt = 1e-3, damping = v })
  assert(not ok and err:find("damping must be a finite number >= 0", 1, true), tostring(err))
  local sim = lamina.sim{ domain = {0, 0, 1, 1}, cell = 0.1, dt = 1e-3, damping = 2 }
  ok, err = pcall(function() sim.damping = v end)
  assert(not ok and err:find("sim.damping must be a finite number >= 0", 1, true), tostring(err))
  assert(sim.damping == 2, "a refused damping leaves the setting")
end
local sim = lamina.sim{ domain = {0, 0, 1, 1}, cell = 0.1, dt = 1e-3 }
assert(sim.damping == 0, "damping defaults to 0")
sim.damping = 3
assert(sim.damping == 3, "sim.damping is live")
