-- expect: 0
-- Issue 31, item 4: a backtracking pattern ran in C for hours, and neither
-- Ctrl-C nor SIGTERM stopped it (they stop a script through an instruction
-- hook, which C code never reaches). string.find/match/gmatch/gsub now bound
-- the matcher's worst case, (n + 1) m prod(r_i + 1) steps for the items that
-- may backtrack (r_i: the longest run of the subject they can take), and
-- refuse a call past 1e8 steps (under a second; l_pattern.c).
local s = string.rep("a", 30000)
for _, call in ipairs{
  function() return s:find("a*a*a*b") end,
  function() return s:match("(a-)(a-)b") end,
  function() for _ in s:gmatch("a*a*b") do end end,
  function() return s:gsub("%ba" .. "a" .. "a*b", "") end,
  function() return string.find(s, "(a*)%1b") end,
} do
  local ok, err = pcall(call)
  assert(not ok and err:find("could take up to", 1, true) and err:find("cannot be interrupted", 1, true),
         tostring(err))
end
-- what scripts do stays allowed, linear patterns on long texts included
local csv = string.rep("12.5,", 20000)
local n = 0
for v in csv:gmatch("[^,]+") do n = n + 1 end
assert(n == 20000, n)
assert(select(2, csv:gsub("(%d+)%.(%d+)", "%2.%1")) == 20000)
assert(("t = 1.25 s"):match("t = ([%d.]+)") == "1.25")
assert(s:find("b", 1, true) == nil)                 -- plain: not a pattern
assert(s:find("^a*$") == 1)                        -- anchored, one item at the end
assert(("x = 3"):gsub("%s", "") == "x=3")
print("patterns bounded")
