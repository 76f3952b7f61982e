-- expect: 2
-- stderr: gas_gamma\.lua:4: lamina\.gas: gamma must be greater than 1 \(got 1\.0\)
-- A gamma-law gas needs gamma > 1 ([F] eq 22).
local air = lamina.gas{ rho = 1, p = 100, gamma = 1.0 }
