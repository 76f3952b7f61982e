-- expect: 2
-- stderr: courant_inf\.lua:4: lamina\.sim: courant must be positive and finite \(got inf\)
-- Issue 31 item 7: courant = inf turned the stability check off silently.
lamina.sim{ dt = 1e-3, domain = {0, 0, 1, 1}, cell = 0.1, courant = 1/0 }
