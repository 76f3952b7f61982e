-- expect: 2
-- stderr: transfer = "apic" works with mass = "lumped" only \(got mass = "membrane"
-- APIC with the membranes' consistent mass does not conserve momentum (a
-- shearing gas in a ring drifts 6.3e-2 of it, physics.apic_membrane_momentum's
-- scene): refused by name before anything runs.
lamina.sim{ domain = {0, 0, 1, 1}, cell = 0.1, dt = 1e-4, transfer = "apic", mass = "membrane" }
