-- expect: 2
-- stderr: runtime_error\.lua:7: attempt to perform arithmetic
-- stderr: stack traceback
-- A runtime error names file and line and prints a traceback.
local function f(t)
  local nothing
  return t + nothing
end
f(1)
