-- expect: 2
-- stderr: lamina.sim: viscous_limit must be a finite number >= 0 \(got -0.1
-- The viscosity limit kappa rho h^2 / dt (lamina.sim{viscous_limit}) is
-- a bound: a negative one is refused by name, with the value.
lamina.sim{ domain = {0, 0, 1, 1}, cell = 0.1, dt = 1e-4, viscous_limit = -0.1 }
