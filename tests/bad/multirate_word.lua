-- expect: 2
-- stderr: multirate_word\.lua:4: lamina\.sim: multirate = "verlet" is not one of "held" \| "impulse" \| "impulse_lumped" \| "half" \| "half_lumped" \| "held_consistent" \| "split" \| "hybrid"
-- multirate: a form not known is refused naming it and the forms there are.
lamina.sim{ dt = 1e-4, substeps = 4, multirate = "verlet" }
