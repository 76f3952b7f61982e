-- membrane_rest_basis.lua - issue 13's first measurement with each basis
-- (lamina.sim{basis}; docs/decisions.md "Shape functions"): a pre-tensioned
-- straight membrane at rest between the fixed side walls (no gravity,
-- E 1e7, rho 1000, thickness 0.01, prestrain 0.01, cell 0.02), its points
-- 0.25 / 0.34 / 0.5 / 1.0 cell apart; the mean tension's change after
-- 0.01 s and 0.2 s, and the kinetic energy then (nothing should move).
--   lamina run scripts/measure/membrane_rest_basis.lua [--set t_end=0.2]
local h = 0.02
local t_end = lamina.param("t_end", 0.2)
print("| basis | spacing (cells) | tension after 0.01 s | after " .. t_end .. " s | kinetic energy |")
print("|---|---:|---:|---:|---:|")
for _, basis in ipairs{ "linear", "gimp", "bspline2" } do
  for _, sp in ipairs{ 0.25, 0.34, 0.5, 1.0 } do
    local sim = lamina.sim{ domain = {0, 0, 1, 0.5}, cell = h, dt = 0.5 * h / 100, basis = basis }
    local skin = lamina.membrane{ rho = 1000, E = 1e7, nu = 0, thickness = 0.01, law = "uniaxial" }
    local n = math.floor(1 / (sp * h) + 0.5) + 1
    local mem = sim:membrane{ material = skin, count = n, initial_strain = 0.01,
                              curve = lamina.segment{ from = {0, 0.25}, to = {1, 0.25} } }
    local s0 = mem:hoop_stress()
    sim:run{ t_end = 0.01 }
    local s1 = mem:hoop_stress()
    sim:run{ t_end = t_end }
    print(string.format("| %s | %.2f | %+.2f %% | %+.2f %% | %.3g |", basis, sp,
                        100 * (s1 / s0 - 1), 100 * (mem:hoop_stress() / s0 - 1),
                        sim:energy().kinetic))
  end
end
