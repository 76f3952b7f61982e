-- string_modes.lua - a taut string ringing in one of its modes, held at its
-- ends by fixed walls or by two pins (issue 30 item 3); shared by
-- tests/physics/string_*.lua.
--
-- The string: length L = 1, E = 1e4, rho = 1, thickness t = 0.01, nu = 0,
-- uniaxial, initial (logarithmic) strain 0.05, so the tension is
-- T = E t 0.05 = 5 (segment forces: sigma = E ln(l/L0)); points half a cell
-- apart. Each point weighs rho t ds e^-0.05 (membrane_create.c), so the
-- mass per length of the stretched string is mu = m / ds, read from the
-- points themselves. Exact small-amplitude frequency of mode n:
-- f_n = n / (2 L) sqrt(T / mu). Started with the mode's shape in velocity,
-- v_y = 0.01 sin(n pi s / L) (amplitude ~1e-4 of a cell: linear), and run
-- 10 periods at dt = 0.4 h / sqrt(E / rho).
--
-- M.run{basis, ends = "walls" | "pins", mode, n (cells per L), periods, substeps, multirate, mass}
-- returns {err = f_measured / f_exact - 1, de = the largest change of the
-- total energy over the largest kinetic energy, kr = the largest kinetic
-- energy of the last period over the first's}.
local M = {}

function M.run(o)
  local E, t, rho, e0, L = 1e4, 0.01, 1, 0.05, 1
  local h = 1 / (o.n or 32)
  local mode, periods = o.mode or 1, o.periods or 10
  local pins = o.ends == "pins"
  local x0 = pins and 0.2 or 0             -- pins: off the node lines
  local y0 = 0.5 + 0.3 * h
  -- o.substeps = k: multi-rate stepping (docs/api.md), k sub-steps of the
  -- same 0.4 h / c in each step
  local sim = lamina.sim{ basis = o.basis, dt = 0.4 * h / math.sqrt(E / rho) * (o.substeps or 1),
    cell = h, substeps = o.substeps, multirate = o.multirate, mass = o.mass, scheme = o.scheme,
    domain = {0, 0, pins and 1.4 or 1, 1},
    boundary = pins and "free" or {left = "fixed", right = "fixed", top = "free", bottom = "free"} }
  local mat = lamina.membrane{ rho = rho, E = E, nu = 0, thickness = t, law = "uniaxial" }
  local s = sim:membrane{ material = mat, initial_strain = e0, spacing = 0.5 * h,
    curve = lamina.segment{ from = {x0, y0}, to = {x0 + L, y0} },
    velocity = function(u) return 0, 0.01 * math.sin(mode * math.pi * u) end }
  if pins then s:pin{points = {1}}; s:pin{points = {#s}} end
  local P = s:particles()
  local mu = P.mass[2] / math.sqrt((P.x[3] - P.x[2]) ^ 2 + (P.y[3] - P.y[2]) ^ 2)
  local T = s:hoop_stress() * t
  local f = mode / (2 * L) * math.sqrt(T / mu)
  local per = 1 / f
  -- the probe: the point nearest the first antinode
  local probe, best = 1, math.huge
  for i = 1, #P.x do
    local d = math.abs(P.x[i] - (x0 + L / (2 * mode)))
    if d < best then best, probe = d, i end
  end
  local ts, ys, ke, tot = {}, {}, {}, {}
  sim:every(per / 200, function()
    ts[#ts + 1], ys[#ys + 1] = sim.t, s:particles().y[probe] - y0
    local e = sim:energy()
    ke[#ke + 1], tot[#tot + 1] = e.kinetic, e.total
  end)
  sim:run{ t_end = periods * per }
  local up = {}
  for i = 2, #ts do
    if ys[i - 1] < 0 and ys[i] >= 0 then
      up[#up + 1] = ts[i - 1] + (ts[i] - ts[i - 1]) * (-ys[i - 1]) / (ys[i] - ys[i - 1])
    end
  end
  assert(#up >= 3, "the string did not ring: " .. #up .. " upward crossings")
  local measured = (up[#up] - up[1]) / (#up - 1)
  local kmax, k1, klast, de = 0, 0, 0, 0
  for i = 1, #ts do
    kmax = math.max(kmax, ke[i])
    if ts[i] < per then k1 = math.max(k1, ke[i]) end
    if ts[i] > (periods - 1) * per then klast = math.max(klast, ke[i]) end
    de = math.max(de, math.abs(tot[i] - tot[1]))
  end
  local r = { err = per / measured - 1, de = de / kmax, kr = klast / k1 }
  print(string.format("%-8s %-5s mode %d, cell 1/%d: frequency %+.3f %%, energy within %.3f %% of "
    .. "the largest KE, last period's KE peak / first's %.4f", sim.basis, o.ends, mode,
    o.n or 32, 100 * r.err, 100 * r.de, r.kr))
  return r
end

return M
