-- expect: 2
-- stderr: syntax_error\.lua:5:
-- A Lua syntax error names the file and line.
local sim = lamina.sim{ dt = 1e-3 }
local x = = 3
