-- expect: 2
-- stderr: membrane_law_unknown\.lua:6: lamina\.membrane: law = "mooney" is not one of "uniaxial" \| "plane_stress" \| "neo_hookean"
-- An unknown membrane law is refused, naming the key and every law of the
-- engine's registry (src/mpm/membrane_law.c), the neo-Hookean one
-- included.
lamina.membrane{rho = 1000, E = 1e7, thickness = 0.005, law = "mooney"}
