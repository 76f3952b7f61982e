-- title: A 3D balloon inflated by the gas it holds: the gas-filled sphere in three dimensions
-- source: normals paper §8, Fig 12 (its gas-filled circle, here a sphere in 3D, issue 34)
-- look: an unstretched spherical skin (radius 0.3) around gas at 2 kPa; the
--   gas pushes it out through the grid the two share, it overshoots to a
--   radius of 0.35, rings a few times and settles at 0.343 by t = 0.2
--   (14 % wider), where it stays;
--   the membrane's points (blue) and their normals (red) stay on a sphere,
--   the normals radial; the slice through the centre (y = 0) shows the gas
--   pressure falling as it expands and the pressure waves inside dying out,
--   one colour range (800 to 2100 Pa) for every time; no gas outside the
--   skin; the plot: the tension against p r / 2 of the moment (dashed), which
--   it meets once the ringing has gone
-- checks: the time mean over the last 0.1 s of the points' mean tension
--   against p r / 2 (ours: Laplace's law for a thin sphere, p the gas's over
--   the volume the skin encloses, gas:pressure(membrane), r the radius of
--   that volume's sphere; 2 %, issue 34's); the gas's pressure at the end
--   against the adiabatic p0 (V0 / V)^gamma (ours; the viscosity mu = 0.05
--   heats it a little; 2 %); the radius against the closed form of a
--   plane-stress skin (logarithmic strain) around an adiabatic gas, ln(r /
--   r0) E t / (1 - nu) = p0 (r0 / r)^(3 gamma) r / 2 (ours; 2 %); no gas point more
--   than a quarter cell outside (membrane:escaped); printed only: the normals'
--   worst angle from radial, the energy's change (kinetic + strain + the
--   gas's internal + the damping's work)
-- assumed: ours, not the paper's (its §8 circle has r = 0.5, E = 1e6, t =
--   0.1, p0 = 1000: a strain of 1.75e-3, which does not show; the same check
--   in 3D at those values is tests/physics/sim3_gas_balloon.lua): a softer
--   skin, E = 1e5, nu = 0.3, t = 0.01, rho = 100, plane stress, laid
--   unstretched on the sphere r0 = 0.3; gas p0 = 2000, rho = 1.2, gamma =
--   1.4, mu = 0.05, 27 points a cell in the ball; cell 0.05 (the box
--   [-0.5, 0.5]^3), B-spline, MUSL (the default), dt = 4e-4, membrane
--   points h / 3 apart with connectivity normals (the frame's t1 x t2); a
--   damping load of 60 /s on the membrane's points (lamina's, not the
--   paper's: the gas's shear viscosity hardly resists the breathing, which
--   is dilatation). The page ran USL until MUSL moved a 3D membrane's
--   points with the re-mapped velocity their strain is taken from: moved
--   with v^L they started a motion of their own after about 0.15 s that the
--   damping did not hold (kinetic energy 10 J at 0.4 s, the normals 8
--   degrees off radial; docs/3d.md "MUSL: the skin's points move with the
--   re-mapped velocity"); now it stays settled to 0.4 s as under USL
-- visual: t_end=0.02
-- thumb: balloon_t0.400.png
local out = lamina.param("out", "out/balloon3d_inflating")
local t_end = lamina.param("t_end", 0.4)
local h, r0, p0, gamma = 0.05, 0.3, 2000, 1.4
local E, nu, t = 1e5, 0.3, 0.01
local c = 60
local sim = lamina.sim{ dim = 3, domain = {-0.5, -0.5, -0.5, 0.5, 0.5, 0.5}, cell = h, dt = 4e-4,
                        basis = "bspline2" }
local air = lamina.gas{ rho = 1.2, p = p0, gamma = gamma, mu = 0.05 }
local skin = lamina.membrane{ rho = 100, E = E, nu = nu, thickness = t, law = "plane_stress" }
local gas = sim:body{ material = air, ppc = 27, name = "gas",
                      region = lamina.ball{ center = {0, 0, 0}, radius = r0 } }
local mem = sim:membrane{ material = skin, spacing = h / 3, damping = c, name = "skin",
                          surface = lamina.sphere{ center = {0, 0, 0}, radius = r0 } }

local V0, pstart = mem:enclosed_volume(), gas:pressure(mem)
local e0 = sim:energy()
local function measure()
  local V = mem:enclosed_volume()
  return gas:pressure(mem), (3 * V / (4 * math.pi)) ^ (1 / 3), mem:tension(), V
end
local function worst_normal()
  local m, w = mem:particles(), 0
  for i = 1, m.n do
    local d = math.sqrt(m.x[i] ^ 2 + m.y[i] ^ 2 + m.z[i] ^ 2)
    local ct = (m.x[i] * m.nx[i] + m.y[i] * m.ny[i] + m.z[i] * m.nz[i]) / d
    w = math.max(w, math.deg(math.acos(math.min(1, ct))))
  end
  return w
end

local ts, rs, Ts, prs = {}, {}, {}, {}
local sT, sX, n, escaped, worst, de = 0, 0, 0, 0, 0, 0
sim:every(2e-3, function(s)
  local p, r, T = measure()
  ts[#ts + 1], rs[#rs + 1], Ts[#Ts + 1], prs[#prs + 1] = s.t, r, T, p * r / 2
  if s.t >= t_end - 0.1 - 1e-9 then sT, sX, n = sT + T, sX + p * r / 2, n + 1 end
  local e = sim:energy()
  de = math.max(de, math.abs(e.total + e.damped - e0.total) / e0.total)
  if math.abs(s.t / 0.02 - math.floor(s.t / 0.02 + 0.5)) < 1e-6 then
    escaped = math.max(escaped, (mem:escaped(gas)))
    worst = math.max(worst, worst_normal())
  end
end)

local function frame(tf)
  sim:frame{ file = string.format("%s/balloon_t%.3f.png", out, tf), width = 960, height = 480,
             title = string.format("gas-filled balloon, t = %.3f s", tf),
             panels = {
               { title = "the skin's points and normals", particles = false, azimuth = -60,
                 elevation = 25, target = {0, 0, 0}, distance = 1.6 },
               { title = "gas pressure on the slice y = 0", particles = false, membranes = false,
                 azimuth = -90, elevation = 0, target = {0, 0, 0}, distance = 1.6,
                 slice = { axis = "y", at = 0, field = "pressure", range = {800, 2100},
                           colourmap = "viridis" } } } }
end
for _, tf in ipairs{0, 0.02, 0.1, 0.4} do
  if tf <= t_end + 1e-12 then
    sim:run{ t_end = tf }
    frame(tf)
  end
end
sim:run{ t_end = t_end }

local p, r, T, V = measure()
local lam_closed = 1
for _ = 1, 200 do   -- ln(lam) E t / (1 - nu) = p0 lam^(-3 gamma) r0 lam / 2, by fixed point
  lam_closed = math.exp(p0 * lam_closed ^ (1 - 3 * gamma) * r0 / 2 * (1 - nu) / (E * t))
end
local padiabatic = pstart * (V0 / V) ^ gamma
lamina.plot{ file = out .. "/tension.png", csv = true, width = 640, height = 360,
             title = "the skin's mean tension and p r / 2", xlabel = "t (s)", ylabel = "N/m",
             legend = "bottom right",
             series = { { x = ts, y = Ts, label = "mean tension (t11 + t22) / 2", color = 1 },
                        { x = ts, y = prs, label = "p r / 2 (p over the enclosed volume)", dashed = true,
                          color = 8 } } }
lamina.plot{ file = out .. "/radius.png", csv = true, width = 640, height = 360,
             title = "the radius of the enclosed volume", xlabel = "t (s)", ylabel = "r (m)",
             legend = "bottom right",
             series = { { x = ts, y = rs, label = "MPM", color = 1 },
                        { x = {0, t_end}, y = {r0 * lam_closed, r0 * lam_closed},
                          label = "closed form (adiabatic gas)", dashed = true, color = 8 } } }
local e = sim:energy()
lamina.report{
  tension_balance = { 100 * (sT / sX - 1), ref = 0, tol = 2,
                      unit = "% (time mean over the last 0.1 s against p r / 2; ours, issue 34)" },
  pressure_adiabatic = { p, ref = padiabatic, tol = 0.02 * padiabatic,
                         unit = "Pa at the end (ours: p0 (V0 / V)^gamma; mu heats it)" },
  radius = { r, ref = r0 * lam_closed, tol = 0.02 * r0 * lam_closed,
             unit = "m at the end (ours: plane-stress skin around an adiabatic gas)" },
  gas_outside = { escaped, ref = 0, tol = 0, unit = "gas points beyond a quarter cell (every 0.02 s)" },
  normal_worst = { worst, unit = "deg from radial (connectivity normals, every 0.02 s)" },
  energy_change = { 100 * de, unit = "% of the start, largest |total + damped - start|" },
  energy_end = { 100 * (e.total + e.damped - e0.total) / e0.total, unit = "% at the end" },
  state_hash = sim:hash(),
}
