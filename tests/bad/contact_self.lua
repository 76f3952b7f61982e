-- expect: 2
-- stderr: contact_self\.lua:8: sim:contact: a and b are the same body \(body 'left'
-- Contact is between two bodies: a body with itself is refused by name.
local sim = lamina.sim{ domain = {0, 0, 5, 5}, cell = 0.25, dt = 7e-4 }
local mat = lamina.elastic{ rho = 1, E = 1e5, nu = 0.3, plane = "stress" }
local l = sim:body{ material = mat, ppc = 4, name = "left",
                    region = lamina.rect{ min = {1, 0.25}, max = {2.25, 4.75} } }
sim:contact{ l, l, law = "release" }
