-- A pre-tensioned square sheet pinned by the walls, under gravity, on the
-- default MUSL at 0.34 of its Courant limit, holds its tension (issue 34
-- item 2: "tension within 0.5 % over 1 s"; here over 2 s).
-- The unit square at z = 0.25 (E = 1 MPa, nu = 0.3, t = 1 mm, rho = 100,
-- initial strain 0.02: T0 = E t e0 / (1 - nu) = 28.571 N/m, plane stress),
-- points h/2 apart on h = 1/16, quadratic B-spline, walls fixed, gravity
-- 9.81, a damping load 30 /s, dt = 2e-4 (the membrane3d_trampoline page's
-- sheet at twice the page's step). Gravity's own change of the tension is
-- below 1e-4 of T0 (the sag w ~ rho t g L^2 / (8 T0) = 4.3e-3, its strain
-- ~ (8/3)(w/L)^2 = 5e-5; ours), so every point's tension must stay within
-- 0.5 % of T0 at every sample (each 0.25 s).
-- Before 3D MUSL moved the points with the re-mapped velocity their strain
-- is taken from (docs/3d.md), this sheet grew an in-plane ripple after
-- about 1 s: tensions 28.308 .. 28.856 at 1.5 s, 20.854 .. 35.583 at 2 s.
-- Measured after: 28.571 .. 28.599 at 2 s (+0.10 %).
local L, h, zm, g = 1.0, 1 / 16, 0.25, 9.81
local dt = 2e-4
local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, L, L, 0.5}, cell = h, dt = dt,
                        basis = "bspline2", scheme = "musl", gravity = {0, 0, -g},
                        boundary = { x0 = "fixed", x1 = "fixed", y0 = "fixed", y1 = "fixed",
                                     z0 = "fixed", z1 = "free" } }
local E, nu, t, e0 = 1e6, 0.3, 1e-3, 0.02
local skin = lamina.membrane{ rho = 100, E = E, nu = nu, thickness = t, law = "plane_stress" }
local sheet = sim:membrane{ material = skin, spacing = h / 2, initial_strain = e0, damping = 30,
                            surface = lamina.rect3{ origin = {0, 0, zm}, u = {L, 0, 0}, v = {0, L, 0} } }
local T0 = E * t * e0 / (1 - nu)
local every = math.floor(0.25 / dt + 0.5)
local worst = 0
for k = 1, math.floor(2.0 / dt + 0.5) do
  sim:step(1)
  if k % every == 0 then
    local p = sheet:particles()
    local lo, hi = math.huge, -math.huge
    for i = 1, #p.tension do
      lo, hi = math.min(lo, p.tension[i]), math.max(hi, p.tension[i])
    end
    worst = math.max(worst, math.abs(lo / T0 - 1), math.abs(hi / T0 - 1))
    print(string.format("t = %.2f  tension %.4f .. %.4f N/m (T0 %.4f)", sim.t, lo, hi, T0))
  end
end
print(string.format("worst point off T0: %.3g %%", 100 * worst))
assert(worst <= 0.005, string.format("a point's tension %.3g %% off T0, above 0.5 %%", 100 * worst))
