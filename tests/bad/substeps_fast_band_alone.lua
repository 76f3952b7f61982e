-- expect: 2
-- stderr: substeps_fast_band_alone\.lua:5: lamina\.sim: fast_band = 1 needs substeps \("auto" or a number\)
-- fast_band puts the gas beside the membranes into the sub-steps' fast group
-- (src/mpm/subcycle_gasband.c): without substeps there are none, so it is refused.
lamina.sim{ dt = 1e-4, fast_band = 1 }
