-- expect: 2
-- stderr: gas_split\.lua:4: lamina\.gas: split must be >= 0 and at most 4096.* \(got -1
-- A negative splitting threshold is refused.
local air = lamina.gas{ rho = 1, e = 250, gamma = 1.4, split = -1 }
