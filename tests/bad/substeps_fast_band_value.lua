-- expect: 2
-- stderr: substeps_fast_band_value\.lua:5: lamina\.sim: fast_band must be a whole number of cells from 0 to 8 \(got 1\.5
-- fast_band is a width in whole cells (src/mpm/subcycle_gasband.c); a
-- fraction or a negative width is refused naming the value.
lamina.sim{ dt = 1e-4, substeps = 4, fast_band = 1.5 }
