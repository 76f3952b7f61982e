-- For restart3_membrane.sh (issue 34 item 2): a 3D run with membranes
-- checkpointed and restarted. A block falls onto a pre-tensioned sheet
-- pinned at its edges (pressure on it too), beside a balloon under pressure
-- whose normals come from the construction ([N] Fig 11, so its count of
-- undefined normals is state); recorded every 0.005 s (energies, the sheet's
-- and the balloon's mean tension, the sheet's lowest point, the pin's reaction),
-- checkpointed every 0.01; prints "RESULT t ... hash H" at the end.
-- --set membrane=false builds no membrane (a checkpoint the membrane script
-- must refuse), --set spacing=... another sheet (likewise).
local out = lamina.param("out", "out/restart3_membrane/a")
local t_end = lamina.param("t_end", 0.06)
local spacing = lamina.param("spacing", 0.05)
local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, 1, 1, 1}, cell = 0.1, dt = 1e-3,
                        basis = "bspline2", gravity = {0, 0, -9.81} }
sim:body{ material = lamina.elastic{ rho = 1000, E = 1e6 }, velocity = {0, 0, -1},
          region = lamina.box{ min = {0.4, 0.4, 0.43}, max = {0.6, 0.6, 0.58} } }
local values = {}
if lamina.param("membrane", true) then
  local skin = lamina.membrane{ rho = 1000, E = 1e6, nu = 0.3, thickness = 1e-3, law = "plane_stress" }
  local sheet = sim:membrane{ material = skin, spacing = spacing, initial_strain = 0.01, pin = "edges",
                              pressure = -20, damping = 5,
                              surface = lamina.rect3{ origin = {0.2, 0.2, 0.4}, u = {0.6, 0, 0}, v = {0, 0.6, 0} } }
  local balloon = sim:membrane{ material = skin, spacing = 0.04, pressure = 50, normals = "quadratic",
                                surface = lamina.sphere{ center = {0.5, 0.5, 0.75}, radius = 0.15 } }
  values.sheet_T = function() return sheet:tension() end
  values.balloon_T = function() return balloon:tension() end
  values.z_min = function()
    local p, z = sheet:particles(), math.huge
    for i = 1, p.n do z = math.min(z, p.z[i]) end
    return z
  end
  values.Rz = function() return sheet:reaction()[3] end
end
sim:record{ file = out .. ".csv", every = 0.005, energy = true, values = values }
sim:checkpoint{ file = out .. ".ckpt", every = 0.01 }
sim:run{ t_end = t_end }
print(string.format("RESULT t %.6f step %d hash %s", sim.t, sim.nstep, sim:hash()))
