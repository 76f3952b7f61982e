-- expect: 2
-- stderr: damping_negative\.lua:5: lamina\.sim:
-- stderr: damping must be a finite number >= 0 \(1/s\) \(got -1\.0
-- issue 35 item 2: a negative grid damping (it would feed the motion)
local sim = lamina.sim{ domain = {0, 0, 1, 1}, cell = 0.1, dt = 1e-3,
                        damping = -1 }
