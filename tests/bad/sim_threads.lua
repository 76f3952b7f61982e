-- expect: 2
-- stderr: sim_threads\.lua:4: lamina\.sim:
-- stderr: threads must be a whole number from 1 to 256 \(got 0\.5
local sim = lamina.sim{ domain = {0, 0, 1, 1}, cell = 0.1, dt = 1e-3,
                        threads = 0.5 }
