-- expect: 2
-- stderr: grid_unequal_cells\.lua:5: lamina\.sim: grid of 1000000000 x 1 = 1e\+09 cells is too large \(limit 1e8\)
-- Issue 18, memory: the 1e8-cell limit was checked before rounding, so
-- unequal cells (domain 1e7 x 1, cell 0.01 x 1e8: "10 cells") made 2e9 nodes.
lamina.sim{ dt = 1e-3, domain = {0, 0, 1e7, 1}, cell = {0.01, 1e8} }
