-- expect: 2
-- stderr: gas_density\.lua:3: lamina\.gas: rho must be positive \(got -1\.0\)
local air = lamina.gas{ rho = -1, e = 250 }
