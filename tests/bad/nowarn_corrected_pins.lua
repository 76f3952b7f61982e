-- expect: 0
-- stderr-not: warning
-- The pinned string on the default (lumped) mass, and the corrected mass on
-- a string with no pins, are not warned of (issue 30 item 2;
-- l_option_warn.c: only pins under the corrected mass miss string_pin_*
-- and pinned_rest).
for _, c in ipairs{ { mass = "lumped", pin = true }, { mass = "corrected", pin = false } } do
  local h = 1 / 16
  local sim = lamina.sim{ domain = {0, 0, 1.5, 1}, cell = h, dt = 0.4 * h / (math.sqrt(5e4 / 100) / 0.75),
                          mass = c.mass }
  local wire = lamina.membrane{ rho = 100, E = 5e4, nu = 0, thickness = 0.01, law = "uniaxial" }
  local s = sim:membrane{ material = wire, count = 33, initial_strain = c.pin and 0.01 or 0, name = "string",
                          curve = lamina.segment{ from = {0.25, 0.3}, to = {1.25, 0.3} } }
  if c.pin then
    s:pin{ points = {1} }
    s:pin{ points = {33} }
  end
  sim:run{ t_end = 0.002 }
end
