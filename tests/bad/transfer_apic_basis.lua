-- expect: 2
-- stderr: transfer_apic_basis\.lua:5: lamina\.sim: transfer = "apic" works with basis = "bspline2" only \(got basis = "linear"\)
-- lamina.sim{transfer = "apic"} needs the quadratic B-spline (src/mpm/apic.c:
-- its D = h^2/4 holds for that basis only); other bases are refused by name.
local sim = lamina.sim{ dt = 1e-3, basis = "linear", transfer = "apic" }
