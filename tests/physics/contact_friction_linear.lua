-- EXPECTED FAILURE (tests/CMakeLists.txt: WILL_FAIL): the inclined plane of
-- contact_friction.lua where lamina's friction is too strong. Measured:
-- linear basis, theta 30, mu 0.3: a = 2.262 against 2.402 (-5.8 %); uGIMP,
-- theta 45, mu 0.6: a = 2.391 against 2.828 (-15.5 %). The excess (an
-- effective mu 6-10 % above the given one) is not explained yet; a likely
-- part: the normal impulse at each contact node is counted per node, and
-- where friction's torque pulls the trailing edge up the correction still
-- holds it down, a tensile impulse that more pressure at the leading edge,
-- with more friction, must balance. This script asserts the issue's 2 %.
local function slide(theta, mu, basis)
  local g, th = 10, math.rad(theta)
  local sim = lamina.sim{ domain = {0, 0, 4, 1.5}, cell = 0.1, dt = 2e-4, basis = basis,
                          gravity = {g * math.sin(th), -g * math.cos(th)} }
  local mat = lamina.elastic{ rho = 1, E = 1e4, nu = 0.3, plane = "strain" }
  local plane = sim:body{ material = mat, ppc = 4,
                          region = lamina.rect{ min = {0.2, 0.2}, max = {3.8, 0.6} } }
  plane:pin{ points = "all" }
  local block = sim:body{ material = mat, ppc = 4,
                          region = lamina.rect{ min = {0.5, 0.6}, max = {1.0, 0.9} } }
  sim:contact{ block, plane, law = "friction", mu = mu }
  local n, st, sv, stt, stv = 0, 0, 0, 0, 0
  sim:every(0.01, function(s)
    if s.t >= 0.2 - 1e-9 then
      local v = block:velocity()
      n, st, sv, stt, stv = n + 1, st + s.t, sv + v, stt + s.t * s.t, stv + s.t * v
    end
  end)
  sim:run{ t_end = 0.6 }
  local a = (n * stv - st * sv) / (n * stt - st * st)
  local exact = g * (math.sin(th) - mu * math.cos(th))
  print(string.format("%s theta %g mu %g: a = %.4f, exact %.4f (%.2f %%)", basis, theta, mu,
                      a, exact, 100 * (a - exact) / exact))
  return a, exact
end
local ok = true
for _, c in ipairs{ {30, 0.3, "linear"}, {45, 0.6, "gimp"} } do
  local a, exact = slide(c[1], c[2], c[3])
  ok = ok and math.abs(a - exact) <= 0.02 * exact
end
assert(ok, "friction block not within 2 % of g (sin theta - mu cos theta)")
