-- expect: 2
-- stderr: substeps_value\.lua:5: lamina\.sim: substeps must be "auto" or a whole number from 1 to 100000 \(got 2\.5
-- substeps (multi-rate stepping) takes "auto" or a whole count of sub-steps;
-- a fraction, zero or another word is refused naming the value.
lamina.sim{ dt = 1e-4, substeps = 2.5 }
