-- expect: 0
-- Issue 31, item 1: "out/nosuch/../link/x.png" wrote through out/link (a link
-- to a folder outside the root) where "out/link/x.png" was refused: the path
-- check stopped at the first missing folder and took the later ".." as text,
-- while the writer made the folder and the kernel then resolved ".." and the
-- link. Now a ".." after a folder that does not exist is refused, for every
-- writer a script has. tests/CMakeLists.txt makes out/security/to_slash -> /.
local sim = lamina.sim{ dt = 1e-3, domain = {0, 0, 1, 1}, cell = 0.1 }
local el = lamina.elastic{ rho = 1000, E = 1000, nu = 0.3 }
sim:body{ material = el, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 } }
local bad = "out/security/nosuch31/../to_slash/tmp/lamina31"
local writers = {
  frame = function() sim:frame{ file = bad .. ".png", width = 16, height = 16 } end,
  record = function() sim:record{ file = bad .. ".csv", energy = true } end,
  vtk = function() sim:vtk{ file = bad } end,
  checkpoint = function() sim:checkpoint{ file = bad .. ".ck", at = 1 } end,
  plot = function()
    lamina.plot{ file = bad .. ".png", series = { { x = {0, 1}, y = {0, 1} } } }
  end,
  plot_csv = function()
    lamina.plot{ file = "out/security/plot31.png", csv = bad .. ".csv",
                 series = { { x = {0, 1}, y = {0, 1} } } }
  end,
  figure = function() lamina.figure{ width = 16, height = 16 }:write(bad .. ".png") end,
  read_csv = function() lamina.read_csv(bad .. ".csv") end,
}
local names = {}
for name in pairs(writers) do names[#names + 1] = name end
table.sort(names)
for _, name in ipairs(names) do
  local ok, err = pcall(writers[name])
  assert(not ok, name .. ": wrote through the link")
  assert(err:find("'..' after a folder that does not exist", 1, true), name .. ": " .. err)
end
-- the same path without the detour is refused as outside the root
local ok, err = pcall(sim.frame, sim, { file = "out/security/to_slash/tmp/x.png", width = 16, height = 16 })
assert(not ok and err:find("outside the output root", 1, true), tostring(err))
print("all " .. #names .. " writers refused")
