-- expect: 2
-- stderr: gas_density_option\.lua:3: lamina\.gas: density = "grid" is not one of "continuity" \| "cell" \| "quadratic"
local air = lamina.gas{ rho = 1, p = 1, density = "grid" }
