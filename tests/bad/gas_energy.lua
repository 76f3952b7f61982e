-- expect: 2
-- stderr: gas_energy\.lua:3: lamina\.gas: the internal energy e must be >= 0 \(got -5\)
local air = lamina.gas{ rho = 1, e = -5 }
