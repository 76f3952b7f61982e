-- expect: 2
-- stderr: frame_panel_unknown_key\.lua:8: sim:frame: panels\[2\]: unknown key 'windw' \(known keys: sim, title, window
-- Each panel table is checked like a constructor: a misspelt key is named
-- with the panel's position and the known keys.
local sim = lamina.sim{ dt = 1e-3 }
local m = lamina.elastic{ rho = 1, E = 1, nu = 0.3 }
sim:body{ material = m, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 } }
sim:frame{ file = "out/frame_panel_unknown_key.png", panels = { {}, { windw = {0, 0, 1, 1} } } }
