-- expect: 0
-- stderr: warning: membrane 'string' \(body 1\) is pinned under mass = "corrected": .*22\.6 / 2\.7 %.*0\.64 % of a cell.*string_pin_\*, pinned_rest\); mass = "lumped" \(the default\) passes them
-- stderr-once: lamina: warning:
-- A pinned membrane under the corrected mass is warned of once (issue 30
-- item 2; l_option_warn.c): the verification case pinned_rest's string at
-- cell 1/16, two sims, one warning.
for k = 1, 2 do
  local h = 1 / 16
  local sim = lamina.sim{ domain = {0, 0, 1.5, 1}, cell = h, dt = 0.4 * h / (math.sqrt(5e4 / 100) / 0.75),
                          mass = "corrected" }
  local wire = lamina.membrane{ rho = 100, E = 5e4, nu = 0, thickness = 0.01, law = "uniaxial" }
  local s = sim:membrane{ material = wire, count = 33, initial_strain = 0.01, name = "string",
                          curve = lamina.segment{ from = {0.25, 0.3}, to = {1.25, 0.3} } }
  s:pin{ points = {1} }
  s:pin{ points = {33} }
  sim:run{ t_end = 0.002 }
end
