-- expect: 2
-- stderr: axisym_domain\.lua:5: lamina\.sim: axisymmetric: the domain reaches r = -0\.5 < 0
-- Axisymmetric: x is the radius; a domain reaching r < 0 is refused
-- (issue 15 item 6).
local sim = lamina.sim{ domain = {-0.5, 0, 1, 1}, dt = 1e-3, axisymmetric = true,
                        boundary = { left = "symmetry" } }
