-- lamina.analysis.circle_fit (issue 35 item 3) against known circles:
-- exact points (a full circle and a 70-degree arc, where the algebraic fit
-- alone is still exact), a membrane's own points, and noisy points whose
-- fit must be the least-squares minimum (every small change of cx, cy or r
-- raises the sum of squared distances, computed here) and near the circle
-- within the noise's reach.
local A = lamina.analysis

local function near(name, got, want, tol)
  print(string.format("%-36s %.15g (exact %.15g), error %.1e, bound %.0e", name, got, want,
                      math.abs(got - want), tol))
  assert(math.abs(got - want) <= tol, name .. ": " .. got .. " vs " .. want)
end

local function on_circle(cx, cy, r, from, to, n, noise)
  local xs, ys = {}, {}
  for i = 0, n - 1 do
    local a = math.rad(from + (to - from) * i / (n - 1))
    local rr = r + (noise and noise(i) or 0)
    xs[#xs + 1], ys[#ys + 1] = cx + rr * math.cos(a), cy + rr * math.sin(a)
  end
  return xs, ys
end

-- exact points
local cx, cy, r, rms = A.circle_fit(on_circle(0.3, -1.2, 2.7, 0, 359, 60))
near("full circle: cx", cx, 0.3, 1e-12)
near("full circle: cy", cy, -1.2, 1e-12)
near("full circle: r", r, 2.7, 1e-12)
near("full circle: rms", rms, 0, 1e-12)
cx, cy, r, rms = A.circle_fit(on_circle(0.3, -1.2, 2.7, 40, 110, 12))
near("70-degree arc: cx", cx, 0.3, 1e-10)
near("70-degree arc: cy", cy, -1.2, 1e-10)
near("70-degree arc: r", r, 2.7, 1e-10)
cx, cy, r = A.circle_fit({1, 0, -1}, {0, 1, 0})   -- three points: the circle through them
near("three points: r", r, 1, 1e-14)

-- a closed membrane's points (placed on an arc of radius 0.3)
local sim = lamina.sim{basis = "linear", domain = {0, 0, 1, 1}, cell = 0.1, dt = 1e-4}
local skin = lamina.membrane{rho = 1, E = 1e4, thickness = 0.01}
local ring = sim:membrane{material = skin, count = 40,
                          curve = lamina.arc{center = {0.5, 0.45}, radius = 0.3}}
cx, cy, r = A.circle_fit(ring)
near("membrane ring: cx", cx, 0.5, 1e-13)
near("membrane ring: cy", cy, 0.45, 1e-13)
near("membrane ring: r", r, 0.3, 1e-13)

-- noisy points: radial noise uniform in +-0.01 (a fixed LCG), a half circle
local seed = 2026
local function noise()
  seed = (1103515245 * seed + 12345) % 2147483648
  return 0.02 * (seed / 2147483648 - 0.5)
end
local xs, ys = on_circle(0.3, -1.2, 2.7, 10, 190, 400, noise)
cx, cy, r, rms = A.circle_fit(xs, ys)
local function ss(a, b, c)   -- the sum of squared distances, computed here
  local s = 0
  for i = 1, #xs do
    local d = math.sqrt((xs[i] - a) ^ 2 + (ys[i] - b) ^ 2) - c
    s = s + d * d
  end
  return s
end
local s0 = ss(cx, cy, r)
for _, d in ipairs{{1e-5, 0, 0}, {-1e-5, 0, 0}, {0, 1e-5, 0}, {0, -1e-5, 0}, {0, 0, 1e-5},
                   {0, 0, -1e-5}} do
  assert(ss(cx + d[1], cy + d[2], r + d[3]) > s0, "not the least-squares minimum")
end
near("noisy: rms = sqrt(sum / n)", rms, math.sqrt(s0 / #xs), 1e-15)
-- the noise's standard deviation is 0.01/sqrt(3) = 0.00577; 400 points:
-- the radius to a few times 0.00577/sqrt(400) = 2.9e-4
near("noisy: r", r, 2.7, 2e-3)
near("noisy: cx", cx, 0.3, 3e-3)
near("noisy: cy", cy, -1.2, 3e-3)
near("noisy: rms (noise 0.00577)", rms, 0.01 / math.sqrt(3), 6e-4)

local function refuses(pattern, ...)
  local ok, err = pcall(...)
  assert(not ok and tostring(err):find(pattern), "expected /" .. pattern .. "/, got " .. tostring(err))
end
refuses("on a line", A.circle_fit, {0, 1, 2, 3}, {0, 1, 2, 3})
refuses("at least 3 points", A.circle_fit, {0, 1}, {0, 1})
refuses("xs has 3 values, ys 2", A.circle_fit, {0, 1, 2}, {0, 1})
refuses("ys%[2%] is not a finite number", A.circle_fit, {0, 1, 2}, {0, 1 / 0, 1})
print("analysis circle_fit: all checks passed")
