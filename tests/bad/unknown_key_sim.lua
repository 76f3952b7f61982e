-- expect: 2
-- stderr: unknown_key_sim\.lua:4: lamina\.sim: unknown key 'gravty'
-- Every constructor checks its keys, lamina.sim too.
local sim = lamina.sim{ dt = 1e-3, gravty = {0, -1} }
