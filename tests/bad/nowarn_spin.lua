-- expect: 0
-- stderr-not: spins
-- What is not warned of as spinning (issue 30 item 2; l_option_warn.c): the
-- case's disk spinning on transfer = "apic"; the disk translating at 3
-- with a slow spin of 0.1 rad/s (the rotation carries 1e-4 of its kinetic
-- energy: the criterion is half); a gas swirling (the suite has no
-- rotating gas).
local function disk(sim, v)
  local mat = lamina.elastic{ rho = 1, E = 1e4, nu = 0.3, plane = "strain" }
  sim:body{ material = mat, ppc = 4, name = "wheel", region = lamina.disk{ center = {0.8, 0.8}, radius = 0.4 },
            velocity = v }
end
local spin = function(x, y) return -10 * (y - 0.8), 10 * (x - 0.8) end
local s1 = lamina.sim{ domain = {0, 0, 1.6, 1.6}, cell = 0.2, dt = 1e-4, transfer = "apic" }
disk(s1, spin)
s1:run{ t_end = 5e-4 }
local s2 = lamina.sim{ domain = {0, 0, 1.6, 1.6}, cell = 0.2, dt = 1e-4 }
-- rotation 0.1 rad/s against 3 units/s of translation: far under half
disk(s2, function(x, y) return 3 - 0.1 * (y - 0.8), 0.1 * (x - 0.8) end)
s2:run{ t_end = 5e-4 }
local s3 = lamina.sim{ domain = {0, 0, 1.6, 1.6}, cell = 0.2, dt = 1e-4 }
s3:body{ material = lamina.gas{ rho = 1, p = 100, gamma = 1.4 }, ppc = 4, name = "swirl",
         region = lamina.disk{ center = {0.8, 0.8}, radius = 0.4 }, velocity = spin }
s3:run{ t_end = 5e-4 }
