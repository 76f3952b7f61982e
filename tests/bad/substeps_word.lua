-- expect: 2
-- stderr: substeps_word\.lua:4: lamina\.sim: substeps must be "auto" or a whole number from 1 to 100000 \(got "fast"\)
-- substeps: a word other than "auto" is refused naming it.
lamina.sim{ dt = 1e-4, substeps = "fast" }
