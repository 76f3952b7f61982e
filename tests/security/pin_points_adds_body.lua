-- expect: 0
-- Issue 31, item 4: a body:pin points function that adds a body was a
-- use-after-free (the bodies array and the particle arrays move when a body
-- is added; l_pin.c read through the old pointer). The function may do it:
-- the body's range is copied and the arrays read afresh (run under ASan in
-- the sanitizer build). Each call adds a body, so the arrays move many times.
local sim = lamina.sim{ dt = 1e-4, domain = {0, 0, 1, 1}, cell = 0.05 }
local el = lamina.elastic{ rho = 1000, E = 1e4, nu = 0.3 }
local bar = sim:body{ material = el, region = lamina.rect{ min = {0.1, 0.1}, max = {0.3, 0.3} } }
local calls = 0
local pin = bar:pin{ points = function(x, y)
  calls = calls + 1
  if calls <= 40 then
    sim:body{ material = el, region = lamina.disk{ center = {0.7, 0.7}, radius = 0.08 + 0.001 * calls } }
  end
  return x < 0.15
end }
assert(calls > 40, "the function ran " .. calls .. " times")
sim:run{ t_end = 5e-4 }
local fx, fy = pin:reaction()
assert(fx == fx and fy == fy, "reaction is NaN")
print(string.format("points function ran %d times; reaction %g %g", calls, fx, fy))
