-- expect: 2
-- stderr: contact_mu\.lua:8: sim:contact: mu must be a finite number >= 0 \(got -0.2
-- A negative friction coefficient is refused by name.
local sim = lamina.sim{ domain = {0, 0, 5, 5}, cell = 0.25, dt = 7e-4 }
local mat = lamina.elastic{ rho = 1, E = 1e5, nu = 0.3, plane = "stress" }
local l = sim:body{ material = mat, ppc = 4, region = lamina.rect{ min = {1, 0.25}, max = {2.25, 4.75} } }
local r = sim:body{ material = mat, ppc = 4, region = lamina.rect{ min = {2.75, 0.25}, max = {4, 4.75} } }
sim:contact{ l, r, law = "friction", mu = -0.2 }
