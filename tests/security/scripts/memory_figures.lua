-- Run by security.memory_cap (issue 31 item 5): n figures of size x size
-- pixels (16384^2: 1 GiB each), kept in a table or dropped as they are made.
local n = lamina.param("n", 100)
local size = lamina.param("size", 16384)
local keep = lamina.param("keep", 1)
local kept = {}
for i = 1, n do
  local f = lamina.figure{ width = size, height = size }
  if keep == 1 then kept[i] = f end
end
print("made " .. n)
