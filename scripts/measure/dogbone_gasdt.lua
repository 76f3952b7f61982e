-- dogbone_gasdt.lua - why the plain MUSL gas step fails at a few times the
-- deck's dt beside a membrane (issue 36 item 1; docs/performance.md "The
-- gas's step beside a membrane"). Box 9's dog-bone at cell 0.05 as in
-- dogbone_multirate.lua, plain step (no sub-steps), with:
--   m        the step as m x the deck's dt (3.5e-5)
--   E_scale  the membrane's E multiplied (1/36 lets m = 6, 1/64 m = 8 pass
--            the membrane's Courant check)
--   mu       the gas's shear viscosity (the deck's 0.1)
--   scheme, pic, threads (default 1), t_end, print_every
--   force    the membrane's force form ("point", the page's, or "segment")
--   mass     lamina.sim{mass} when given ("lumped" with segment forces)
--   one_way  0: the membrane without the wrinkle rule
--   membrane 0: the gas alone
--   entropy  1: every print_every also the heat each point took (e against
--            its adiabat), the kinetic energy near the membrane and away,
--            the membrane's (and its noise along the curve), the gas points
--            outside the membrane
--   substeps, multirate  the multi-rate forms (off: the plain step)
--   viscous_limit  lamina.sim{viscous_limit} (0: off)
--   trace    a gas point's index (1-based, as in gas:particles()): from
--            t = trace_from on, step by step, its position, velocity,
--            density, energy, its gas neighbours within h and its stencil's
--            nodal masses (summed here from the points, quadratic B-spline,
--            lumped m_i = sum_p m_p N_ip) with its own weights N_i
-- It prints where the run stopped (the run's own report names the point),
-- the energy every print_every, and the means of the page's numbers over
-- the last time unit.
--   lamina run scripts/measure/dogbone_gasdt.lua --set m=8 --set E_scale=0.015625 --set t_end=1
local b = require("dogbone_box9")
local m = lamina.param("m", 6)
local E_scale = lamina.param("E_scale", 1 / 36)
local mu = lamina.param("mu", b.deck.mu)
local scheme = lamina.param("scheme", "musl")
local t_end = lamina.param("t_end", 0.5)
local threads = lamina.param("threads", 1)
local trace = lamina.param("trace", 0)
local trace_from = lamina.param("trace_from", 0)
local h, d = 0.05, b.deck
local dt = b.dt(h) * m
local simdef = { domain = {0, 0, d.width, d.width}, cell = h, dt = dt,
                 courant = lamina.param("courant", 1.05),
                 boundary = { left = "symmetry", bottom = "symmetry",
                              right = "symmetry", top = "symmetry" },
                 pic = lamina.param("pic", 0), threads = threads, basis = "bspline2", scheme = scheme,
                 viscous_limit = lamina.param("viscous_limit", 0) }
if lamina.param("mass", "") ~= "" then simdef.mass = lamina.param("mass", "") end
-- substeps > 0 (or "auto"), multirate: the multi-rate forms, for tracing a
-- point in them (the rest of the script is the plain step's)
local substeps = lamina.param("substeps", "0")
substeps = substeps == "auto" and "auto" or tonumber(substeps)
if substeps ~= 0 then simdef.substeps, simdef.multirate = substeps, lamina.param("multirate", "held") end
local sim = lamina.sim(simdef)
local air = lamina.gas{ rho = d.rho_gas, e = d.e, gamma = d.gamma, mu = mu }
local skin = lamina.membrane{ rho = d.rho_membrane, E = d.E * E_scale, nu = d.nu, thickness = d.thickness,
                              law = "plane_stress", one_way = lamina.param("one_way", 1) > 0 }
local gas = sim:body{ material = air, ppc = d.nprg, region = b.contains, name = "gas" }
-- membrane = 0: the gas alone (it expands into the empty box and fills it;
-- item 2's check of the gas's step without a membrane)
local with_membrane = lamina.param("membrane", 1) > 0
local mem = with_membrane and sim:membrane{ material = skin, name = "membrane", count = d.points, normals = "connectivity",
                          orient = {0, 0}, force = lamina.param("force", "point"), curve = lamina.polyline(b.polyline()) }
local mass = b.total_mass(mem and {gas, mem} or {gas})
local function vmax() return b.max_speed(gas) end

-- quadratic B-spline weight of a point at x for the node at x_i (cell h)
local function n1(x, xi)
  local r = math.abs(x - xi) / h
  if r < 0.5 then return 0.75 - r * r end
  if r < 1.5 then return 0.5 * (1.5 - r) ^ 2 end
  return 0
end

-- one line per step for gas point q: its state, its neighbours, and its
-- stencil's nodes (nodal mass from every point, the point's weight N_i and
-- its share m_q N_i / m_i of the node)
local function trace_line(s, q)
  local g, mp = gas:particles(), mem:particles()
  local x, y = g.x[q], g.y[q]
  local near = 0
  for r = 1, #gas do
    if r ~= q and (g.x[r] - x) ^ 2 + (g.y[r] - y) ^ 2 < h * h then near = near + 1 end
  end
  local mnear = 0
  for r = 1, #mem do
    if (mp.x[r] - x) ^ 2 + (mp.y[r] - y) ^ 2 < (1.5 * h) ^ 2 then mnear = mnear + 1 end
  end
  local ic, jc = math.floor(x / h + 0.5), math.floor(y / h + 0.5)
  local nodes = {}
  for jj = jc - 1, jc + 1 do
    for ii = ic - 1, ic + 1 do
      local xi, yi = ii * h, jj * h
      local mi = 0
      for _, set in ipairs{ { g, #gas }, { mp, #mem } } do
        local a, n = set[1], set[2]
        for r = 1, n do
          local w = n1(a.x[r], xi) * n1(a.y[r], yi)
          if w > 0 then mi = mi + a.mass[r] * w end
        end
      end
      local w = n1(x, xi) * n1(y, yi)
      nodes[#nodes + 1] = string.format("%.3f/%.2f", mi / (d.rho_gas * h * h), w > 0 and g.mass[q] * w / mi or 0)
    end
  end
  print(string.format("  t %.5f step %d  x %.4f %.4f  v %.2f %.2f  rho %.4g  e %.4g  V/V0 %.3g  gas nbrs %d  mem pts %d"
    .. "  nodes m_i/(rho h^2) / share: %s", s.t, s.nstep, x, y, g.vx[q], g.vy[q], g.rho[q], g.e[q],
    d.rho_gas / g.rho[q], near, mnear, table.concat(nodes, " ")))
end

-- entropy: a gas point's e against the adiabat through the start,
-- e_s = e0 (rho / rho0)^(gamma - 1): the excess m (e - e_s) is heat the
-- point took (viscous or numerical), summed near the membrane (within 1.5 h
-- of a membrane point) and away from it; the largest ratio e / e_s and where
local entropy = lamina.param("entropy", 0) > 0
local function entropy_line()
  local g, mp = gas:particles(), mem:particles()
  local bins = {}
  for r = 1, #mem do
    local key = math.floor(mp.x[r] / h) * 1000 + math.floor(mp.y[r] / h)
    bins[key] = true
  end
  local function near(x, y)
    local i, j = math.floor(x / h), math.floor(y / h)
    for di = -2, 2 do for dj = -2, 2 do if bins[(i + di) * 1000 + j + dj] then return true end end end
    return false
  end
  local hn, hf, nn, worst, wq = 0, 0, 0, 0, 0
  local kn, kf = 0, 0
  local ratios = {}
  for q = 1, #gas do
    local es = d.e * (g.rho[q] / d.rho_gas) ^ (d.gamma - 1)
    local ex = g.mass[q] * (g.e[q] - es)
    local ke = 0.5 * g.mass[q] * (g.vx[q] ^ 2 + g.vy[q] ^ 2)
    if near(g.x[q], g.y[q]) then hn, kn, nn = hn + ex, kn + ke, nn + 1 else hf, kf = hf + ex, kf + ke end
    local r = g.e[q] / es
    ratios[#ratios + 1] = r
    if r > worst then worst, wq = r, q end
  end
  table.sort(ratios)
  local function pc(f) return ratios[math.max(1, math.floor(f * #ratios))] end
  -- gas points outside the membrane: even-odd rule on the closed polygon
  -- origin - membrane points - origin (a ray towards +x), edges binned by
  -- the rows of height h they span
  local px, py = { 0 }, { 0 }
  for r = 1, #mem do px[#px + 1], py[#py + 1] = mp.x[r], mp.y[r] end
  px[#px + 1], py[#py + 1] = 0, 0
  local rows = {}
  for k = 1, #px - 1 do
    local j0 = math.floor(math.min(py[k], py[k + 1]) / h)
    local j1 = math.floor(math.max(py[k], py[k + 1]) / h)
    for j = j0, j1 do rows[j] = rows[j] or {}; local t = rows[j]; t[#t + 1] = k end
  end
  local nout, kout, iout = 0, 0, 0
  for q = 1, #gas do
    local x, y = g.x[q], g.y[q]
    local inside = false
    for _, k in ipairs(rows[math.floor(y / h)] or {}) do
      local ya, yb = py[k], py[k + 1]
      if (ya > y) ~= (yb > y) then
        local xc = px[k] + (y - ya) / (yb - ya) * (px[k + 1] - px[k])
        if xc > x then inside = not inside end
      end
    end
    if not inside then
      nout = nout + 1
      kout = kout + 0.5 * g.mass[q] * (g.vx[q] ^ 2 + g.vy[q] ^ 2)
      iout = iout + g.mass[q] * g.e[q]
    end
  end
  -- the membrane's kinetic energy, and the part of it in the points'
  -- velocities about their running mean over a cell of curve (13 points):
  -- noise the grid does not carry (FLIP's null space along the curve)
  local km, kmn = 0, 0
  for r = 1, #mem do
    km = km + 0.5 * mp.mass[r] * (mp.vx[r] ^ 2 + mp.vy[r] ^ 2)
    local sx, sy, c = 0, 0, 0
    for k = math.max(1, r - 6), math.min(#mem, r + 6) do sx, sy, c = sx + mp.vx[k], sy + mp.vy[k], c + 1 end
    kmn = kmn + 0.5 * mp.mass[r] * ((mp.vx[r] - sx / c) ^ 2 + (mp.vy[r] - sy / c) ^ 2)
  end
  return string.format("outside the membrane: %d gas points (kinetic %.3f, internal %.3f); ", nout, kout, iout)
         .. string.format("kinetic: gas near %.3f far %.3f membrane %.3f (about its running mean %.3f); ", kn, kf, km, kmn) .. string.format("heat near %.3f (%d pts) far %.3f; e/e_s median %.3f 99%% %.3f max %.3g (point %d at %.3f %.3f rho %.3g)",
                       hn, nn, hf, pc(0.5), pc(0.99), worst, wq, g.x[wq], g.y[wq], g.rho[wq])
end

local rec = sim:record{ every = 0.01, energy = true, values = mem and b.history_values(gas, mem) or
                                                              { p = function() return gas:pressure() end,
                                                                hoop = function() return 0 end,
                                                                r0 = function() return 0 end,
                                                                r90 = function() return 0 end } }
if trace == 0 then
  sim:every(lamina.param("print_every", 0.05), function(s)
    local en = s:energy()
    print(string.format("  t %.3f  steps %d  gas v_max %.1f  energy %.3f (kinetic %.3f, gas internal %.3f, "
                        .. "membrane strain %.3f)  pressure %.2f", s.t, s.nstep, vmax(), en.total, en.kinetic,
                        en.internal, en.strain, mem and gas:pressure(mem) or gas:pressure()))
    if entropy and mem then print("    " .. entropy_line()) end
  end)
end
local cpu = os.clock()
local ok, err = pcall(function()
  if trace > 0 then
    sim:run{ t_end = trace_from }
    while sim.t < t_end - 0.5 * dt do
      trace_line(sim, trace)
      sim:step(1)
    end
  else
    sim:run{ t_end = t_end }
  end
end)
cpu = os.clock() - cpu
print(string.format("dog-bone cell 0.05, plain %s, dt %g x 3.5e-5, E x %.4g, mu %g%s: %s at t = %.4f, %d steps, %.2f CPU s",
  scheme, m, E_scale, mu, substeps ~= 0 and string.format(", substeps %s %s", substeps, simdef.multirate) or "",
  ok and "reached" or "STOPPED", sim.t, sim.nstep, cpu))
if not ok then print("  " .. tostring(err)) end
b.last_unit(rec, sim.t, mass)
