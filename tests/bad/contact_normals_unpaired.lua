-- expect: 2
-- stderr: contact_normals_unpaired\.lua:11: sim:contact_normals: the body is in no contact pair
-- sim:contact_normals of a body in no pair is refused, naming why.
local sim = lamina.sim{ basis = "linear", domain = {0, 0, 5, 5}, cell = 0.25, dt = 7e-4 }
local mat = lamina.elastic{ rho = 1, E = 1e5, nu = 0.3, plane = "stress" }
local l = sim:body{ material = mat, ppc = 4, region = lamina.rect{ min = {1, 0.25}, max = {2.25, 4.75} } }
local r = sim:body{ material = mat, ppc = 4, region = lamina.rect{ min = {2.75, 0.25}, max = {4, 4.75} } }
local third = sim:body{ material = mat, ppc = 4, region = lamina.rect{ min = {4.25, 0.25}, max = {4.75, 1} } }
sim:contact{ l, r }
sim:step()
sim:contact_normals(third)
