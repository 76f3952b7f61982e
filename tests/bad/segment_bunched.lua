-- expect: 0
-- stderr: lamina: warning: at t = 0\.24[0-9]* \(step [0-9]+\): [0-9]+ of the 100 points of membrane 'membrane' \(body 2\) are slack by more than 1 % while [0-9]+ carry tension: with force = "segment" points closer than the grid resolves stay bunched
-- The slack dog-bone with segment forces and points a tenth of a cell
-- apart: the grid cannot unfold the bunches, and the run says so (once)
-- rather than reading its tension 67 % low in silence (docs/robustness.md).
local dog = require("dogbone")
local sim = dog.setup(0.2, { force = "segment" })
sim:run{ t_end = 0.25 }
sim:run{ t_end = 0.3 }
