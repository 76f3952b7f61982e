-- expect: 2
-- args: --set cell=abc
-- stderr: set_not_number\.lua:5: --set cell=abc: a number is expected
-- A --set value of the wrong type is rejected.
local h = lamina.param("cell", 0.1)
