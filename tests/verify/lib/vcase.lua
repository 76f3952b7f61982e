-- vcase.lua - what every verification case (tests/verify/*.lua, issue 30
-- item 1) shares: the options it is run with and the one line it prints per
-- measured quantity, which scripts/verify/run.sh collects into
-- docs/verification.md.
--
-- Options, each a `lamina run --set name=value` (every case reads all seven,
-- so a --set is never left unread):
--   basis  "linear" | "gimp" | "bspline2" | "default" (lamina.sim{basis})
--   force  "point" | "segment" | "default" (sim:membrane{force}; membranes)
--   scheme "musl" | "usl" | "default" (lamina.sim{scheme})
--   mass   "lumped" | "corrected" | "default" (lamina.sim{mass}; the
--          matrix runs "default" unless run.sh -m says otherwise)
--   transfer "flip" | "apic" | "default" (lamina.sim{transfer}; the matrix
--          runs "default" unless run.sh -t says otherwise)
--   level  1 (coarse), 2 (fine), 3 (finer): the case's resolution
--   tol    a tolerance in per cent; > 0 makes every result an assertion
--          (the ctest `verify` label), 0 (default) only prints
-- "default" passes nothing, so the engine's own default is what runs: a
-- script that names neither basis nor force is one row of the matrix.
--
-- Each result prints
--   verify case=C quantity=Q basis=B force=F scheme=S level=L h=H value=V exact=X err=E
-- with B, F, S read back from the simulation (sim.basis, membrane.force),
-- E = 100 |V - X| / scale per cent, scale = |X| unless the case gives one
-- (a quantity whose exact value is 0: creep, spurious stress, a gap).
local M = {}

local function opt(name, default)
  local v = lamina.param(name, default)
  if v == "default" then return nil end
  return v
end

M.basis = opt("basis", "default")
M.force = opt("force", "default")
M.scheme = opt("scheme", "default")
M.mass = opt("mass", "default")
M.transfer = opt("transfer", "default")
M.level = lamina.param("level", 1)
M.tol = lamina.param("tol", 0)
assert(M.level == 1 or M.level == 2 or M.level == 3, "level must be 1, 2 or 3")
M.case = (SCRIPT:match("([^/]+)%.lua$")) or SCRIPT
M.explicit = M.basis ~= nil or M.force ~= nil or M.scheme ~= nil or M.mass ~= nil or M.transfer ~= nil

-- lamina.sim with the case's basis and scheme added to `t`.
function M.sim(t)
  t.basis, t.scheme, t.mass, t.transfer = M.basis, M.scheme, M.mass, M.transfer
  M.the_sim = lamina.sim(t)
  return M.the_sim
end

-- sim:membrane with the case's force added to `t`.
function M.membrane(sim, t)
  t.force = M.force
  local m = sim:membrane(t)
  M.the_membrane = M.the_membrane or m
  return m
end

-- One result line; with tol > 0 an assertion that err <= tol.
function M.result(o)
  local sim, mem = M.the_sim, M.the_membrane
  local scale = o.scale or math.abs(o.exact)
  local err = 100 * math.abs(o.value - o.exact) / scale
  print(string.format("verify case=%s quantity=%s basis=%s force=%s scheme=%s level=%d h=%.6g "
    .. "value=%.9g exact=%.9g err=%.6g default=%s", M.case, o.quantity, sim.basis,
    mem and mem.force or "-", sim.scheme, M.level, o.h, o.value, o.exact, err,
    M.explicit and "no" or "yes"))
  if M.tol > 0 then
    assert(err <= M.tol, string.format("%s %s: error %.3f %% exceeds %.3g %% (value %.6g, exact %.6g)",
                                       M.case, o.quantity, err, M.tol, o.value, o.exact))
  end
  return err
end

-- A configuration the engine refuses (sim:contact with the quadratic
-- B-spline): one line per quantity with status=refused and the reason; with
-- tol > 0 an error.
function M.refused(quantities, err)
  local why = tostring(err):gsub("%s+", " "):sub(1, 160)
  for _, q in ipairs(quantities) do
    print(string.format("verify case=%s quantity=%s basis=%s force=- scheme=%s level=%d status=refused "
      .. "default=%s why=%s", M.case, q, M.basis or "default", M.scheme or "default", M.level,
      M.explicit and "no" or "yes", why))
  end
  if M.tol > 0 then error(M.case .. ": refused: " .. why) end
end

-- The period of a sampled signal from its upward zero crossings about
-- `mean` (linear interpolation), skipping crossings before t_skip.
function M.period(t, y, mean, t_skip)
  local up = {}
  for i = 2, #t do
    local a, b = y[i - 1] - mean, y[i] - mean
    if t[i] > (t_skip or 0) and a < 0 and b >= 0 then
      up[#up + 1] = t[i - 1] + (t[i] - t[i - 1]) * (-a) / (b - a)
    end
  end
  assert(#up >= 2, M.case .. ": fewer than two upward crossings")
  return (up[#up] - up[1]) / (#up - 1), up
end

-- The trapezoidal mean of a sampled y(t) between ta and tb (ta, tb inside
-- the samples; the ends interpolated linearly).
function M.mean_between(t, y, ta, tb)
  local function at(x)
    for i = 2, #t do
      if t[i] >= x then return y[i - 1] + (y[i] - y[i - 1]) * (x - t[i - 1]) / (t[i] - t[i - 1]) end
    end
    return y[#y]
  end
  local s, prev_t, prev_y = 0, ta, at(ta)
  for i = 1, #t do
    if t[i] > ta and t[i] < tb then
      s = s + 0.5 * (prev_y + y[i]) * (t[i] - prev_t)
      prev_t, prev_y = t[i], y[i]
    end
  end
  s = s + 0.5 * (prev_y + at(tb)) * (tb - prev_t)
  return s / (tb - ta)
end

-- The mean of a ringing signal over whole periods within [t0, t1]: a mean
-- over a window that ends part-way through a period carries up to
-- amplitude / periods of the ringing with it, which for a lightly damped
-- body is larger than the drift being measured. The periods' ends are the
-- signal's upward crossings of its own mean (first the window's mean, then,
-- once, the mean between the crossings that gives), linearly interpolated.
-- Returns the mean, the number of whole periods, the first and last crossing.
function M.ringing_mean(t, y, t0, t1)
  local mean = M.mean_between(t, y, t0, t1)
  local up
  for _ = 1, 2 do
    up = {}
    for i = 2, #t do
      local a, b = y[i - 1] - mean, y[i] - mean
      if t[i - 1] >= t0 and t[i] <= t1 and a < 0 and b >= 0 then
        up[#up + 1] = t[i - 1] + (t[i] - t[i - 1]) * (-a) / (b - a)
      end
    end
    assert(#up >= 2, M.case .. ": fewer than two upward crossings in the window, no whole period")
    mean = M.mean_between(t, y, up[1], up[#up])
  end
  return mean, #up - 1, up[1], up[#up]
end

return M
