-- expect: 2
-- stderr: contact_test_form\.lua:9: sim:contact: test = "eq9" is not one of "lamina" \| "eq26"
-- An unknown release test is refused, naming the key and the forms there
-- are (lamina's, or [M] eq 26 as printed).
local sim = lamina.sim{ basis = "linear", domain = {0, 0, 5, 5}, cell = 0.25, dt = 7e-4 }
local mat = lamina.elastic{ rho = 1, E = 1e5, nu = 0.3, plane = "stress" }
local l = sim:body{ material = mat, ppc = 4, region = lamina.rect{ min = {1, 0.25}, max = {2.25, 4.75} } }
local r = sim:body{ material = mat, ppc = 4, region = lamina.rect{ min = {2.75, 0.25}, max = {4, 4.75} } }
sim:contact{ l, r, law = "release", test = "eq9" }
