-- expect: 2
-- stderr: body:pin: points\[2\] must be a whole number from 1 to 
local sim = lamina.sim{domain = {0, 0, 2, 1}, cell = 0.05, dt = 1e-5}
local mat = lamina.membrane{rho = 1000, E = 1e7, nu = 0, thickness = 0.005, law = "uniaxial"}
local m = sim:membrane{material = mat, force = "segment", spacing = 0.05 / 3,
                       curve = lamina.segment{from = {0.2, 0.5}, to = {1.8, 0.5}}}
m:pin{points = {1}}
local ok, err = pcall(m.pin, m, {points = {1}})
assert(not ok and err:find("point 1 of membrane 1 is pinned already"), err)
ok, err = pcall(m.pin, m, {points = {1}, speed = 3})
assert(not ok and err:find("unknown key 'speed'"), err)
m:pin{points = {2, 1e9}}
