-- expect: 2
-- stderr: sim3_2d_key\.lua:4: lamina\.sim: 'axisymmetric' is not available with dim = 3 in this build
-- A 2D-only key of lamina.sim with dim = 3, refused by name.
lamina.sim{ dim = 3, domain = {0, 0, 0, 1, 1, 1}, cell = 0.1, dt = 1e-3, axisymmetric = true }
