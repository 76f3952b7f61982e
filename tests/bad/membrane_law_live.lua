-- expect: 2
-- stderr: membrane_law_live\.lua:9: material: law "neo_hookean" is incompressible \(nu = 0\.5\): leave nu out or give 0\.5 \(got 0\.3\)
-- A live change of law is checked as the constructor checks it: a
-- plane-stress sheet with nu = 0.3 cannot become neo-Hookean (the material
-- keeps its law), while one with nu = 0 can.
local ok = lamina.membrane{rho = 1000, E = 3e4, thickness = 0.01, law = "plane_stress"}
ok.law = "neo_hookean"
local sheet = lamina.membrane{rho = 1000, E = 3e4, nu = 0.3, thickness = 0.01, law = "plane_stress"}
sheet.law = "neo_hookean"
