-- expect: 2
-- stderr: bad_option\.lua:4: lamina\.sim: scheme = "flip" is not one of "musl" \| "usl"
-- An option outside its list names the choices.
local sim = lamina.sim{ dt = 1e-3, scheme = "flip" }
