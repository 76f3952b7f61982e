-- expect: 2
-- stderr: frame_scale_nan\.lua:7: sim:frame: 'scale' must be a finite number > 0 \(got -?nan\)
-- scale = k draws displacements k times about the reference positions: NaN is no k.
local sim = lamina.sim{ dt = 1e-3 }
local m = lamina.membrane{ rho = 1, E = 1, thickness = 0.01 }
sim:membrane{ material = m, spacing = 0.02, curve = lamina.segment{ from = {0.2, 0.5}, to = {0.8, 0.5} } }
sim:frame{ file = "out/frame_scale_nan.png", scale = 0 / 0 }
