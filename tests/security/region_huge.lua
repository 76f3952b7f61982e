-- expect: 0
-- Found by fuzzing (tests/fuzz, fuzz_lua): a region far larger than the
-- domain (a disk of radius 1e12, a rect of 1e308) converted its bounding box
-- to grid indices through an int (undefined behaviour, UBSan). The box is
-- clamped to the grid first: the body fills the domain.
local sim = lamina.sim{ dt = 1e-3 }
local el = lamina.elastic{ rho = 1000, E = 1000, nu = 0.3 }
local b = sim:body{ material = el, region = lamina.disk{ center = {0.5, 0.5}, radius = 1e12 } }
assert(sim.n == 400, sim.n)   -- 10 x 10 cells, ppc 4
local s2 = lamina.sim{ dt = 1e-3 }
s2:body{ material = el, region = lamina.rect{ min = {-1e308, -1e308}, max = {1e308, 1e308} } }
assert(s2.n == 400, s2.n)
print("huge regions fill the domain")
