-- expect: 2
-- stderr: mass_unknown\.lua:4: lamina\.sim: mass = "consistent" is not one of "lumped" \| "corrected"
-- lamina.sim{mass} names its choices (docs/api.md).
local sim = lamina.sim{ dt = 1e-3, mass = "consistent" }
