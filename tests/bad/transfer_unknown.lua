-- expect: 2
-- stderr: transfer_unknown\.lua:4: lamina\.sim: transfer = "pic" is not one of "flip" \| "apic"
-- lamina.sim{transfer} names its choices (docs/api.md).
local sim = lamina.sim{ dt = 1e-3, transfer = "pic" }
