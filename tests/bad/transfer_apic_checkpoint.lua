-- expect: 2
-- stderr: transfer_apic_checkpoint\.lua:7: sim:checkpoint: a sim with transfer = "apic" cannot be checkpointed \(its points' affine velocities are not in the state\)
-- A sim on the affine transfer refuses sim:checkpoint (src/mpm/apic.c: the
-- points' C is not in the state, so a restart would not continue the run).
local sim = lamina.sim{ dt = 1e-3, transfer = "apic" }
sim:body{ material = lamina.elastic{ rho = 1, E = 1e4, nu = 0.3 }, region = lamina.rect{ x0 = 0.3, y0 = 0.3, x1 = 0.6, y1 = 0.6 } }
sim:checkpoint{ file = "out/apic.ck", every = 0.01 }
