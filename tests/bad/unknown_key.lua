-- expect: 2
-- stderr: unknown_key\.lua:5: lamina\.elastic: unknown key 'Ee'
-- stderr: known keys: rho, E, nu, plane
-- A misspelt constructor key is rejected by name at the script's line.
local m = lamina.elastic{ rho = 1, Ee = 1000, nu = 0.3 }
