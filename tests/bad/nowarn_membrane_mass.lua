-- expect: 0
-- stderr-not: warning
-- mass = "membrane" (the consistent-mass correction on the membranes'
-- points only; issue 30 item 2, l_option_warn.c) is not warned of, with
-- pins or without: like "corrected" (nowarn_corrected_pins.lua) it solves
-- the pins' constraint inside its Neumann step, and the pinned strings
-- (string_pin_*) and the pinned membrane at rest (pinned_rest) pass with
-- it (verify.*.membrane). The verification case pinned_rest's string at
-- cell 1/16, pinned and not.
for _, pin in ipairs{ true, false } do
  local h = 1 / 16
  local sim = lamina.sim{ domain = {0, 0, 1.5, 1}, cell = h, dt = 0.4 * h / (math.sqrt(5e4 / 100) / 0.75),
                          mass = "membrane" }
  local wire = lamina.membrane{ rho = 100, E = 5e4, nu = 0, thickness = 0.01, law = "uniaxial" }
  local s = sim:membrane{ material = wire, count = 33, initial_strain = pin and 0.01 or 0, name = "string",
                          curve = lamina.segment{ from = {0.25, 0.3}, to = {1.25, 0.3} } }
  if pin then
    s:pin{ points = {1} }
    s:pin{ points = {33} }
  end
  sim:run{ t_end = 0.002 }
end
