-- expect: 2
-- stderr: record_mean_nan\.lua:8: rec:mean: the times must be numbers, not NaN
-- Issue 31 item 7: rec:mean(name, NaN, t1) compared false everywhere and
-- averaged the whole record, silently.
local sim = lamina.sim{ dt = 1e-3, domain = {0, 0, 1, 1}, cell = 0.1 }
local rec = sim:record{ every = 1e-3 }
sim:step(3)
print(rec:mean("t", 0/0, 1))
