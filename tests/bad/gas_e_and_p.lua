-- expect: 2
-- stderr: gas_e_and_p\.lua:3: lamina\.gas: give exactly one of 'e' \(specific internal energy\) and 'p' \(pressure\)
local air = lamina.gas{ rho = 1, e = 250, p = 100 }
