-- expect: 2
-- stderr: callback_error\.lua:9: boom in a callback
-- An error inside a sim:every callback names the callback's line.
local sim = lamina.sim{ dt = 1e-3 }
local m = lamina.elastic{ rho = 1, E = 1, nu = 0.3 }
sim:body{ material = m, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 } }
sim:every(0.01, function(s)
  if s.t > 0.02 then
    error("boom in a callback")
  end
end)
sim:run{ t_end = 0.1 }
