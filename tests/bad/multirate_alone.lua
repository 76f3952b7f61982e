-- expect: 2
-- stderr: multirate_alone\.lua:4: lamina\.sim: multirate = "impulse" needs substeps \("auto" or a number\)
-- multirate without substeps means nothing: refused, naming what it needs.
lamina.sim{ dt = 1e-4, multirate = "impulse" }
