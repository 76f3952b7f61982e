-- expect: 2
-- stderr: sim_basis\.lua:4: lamina\.sim: basis = "cubic" is not one of "linear" \| "gimp" \| "bspline2"
-- An unknown basis names the key and the known values.
lamina.sim{ domain = {0, 0, 1, 1}, cell = 0.1, dt = 1e-3, basis = "cubic" }
