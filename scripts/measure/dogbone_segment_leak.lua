-- dogbone_segment_leak.lua - where physics.dogbone_segment's gas leaks
-- (issue 30 item 2; docs/robustness.md "The membranes' consistent mass",
-- "Why the segment dog-bone leaks"): the same scene (assets/lua/dogbone.lua,
-- linear basis, segment forces, cell 0.1, t = 2.5) at several point counts,
-- on the lumped mass and on lamina.sim{mass = "membrane"}, with the
-- papers' pure FLIP (pic = 0) or a blend. For each run: membrane:escaped's
-- largest count beyond a quarter cell over samples every 0.01, the first
-- time one was out, the deepest distance of any outside particle (cells)
-- and the most skin-grazers (outside by less than a quarter cell).
--   lamina run scripts/measure/dogbone_segment_leak.lua [--set mass=membrane]
--     [--set counts="56 58 60 62 64"] [--set pic=0] [--set t_end=2.5]
local dog = require("dogbone")
local mass = lamina.param("mass", "lumped")
local counts = lamina.param("counts", "56 58 60 62 64")
local pic = lamina.param("pic", 0)
local t_end = lamina.param("t_end", 2.5)
local h = 0.1
print(string.format("dog-bone, segments, cell %.2f, t_end %.2f, mass %s, pic %g", h, t_end, mass, pic))
print("points  escaped  first_t  deepest_cells  grazers")
for c in counts:gmatch("%d+") do
  local sim, gas, mem = dog.setup(h, { force = "segment", count = tonumber(c), mass = mass, pic = pic })
  local most, first, deepest, grazing = 0, nil, 0, 0
  sim:every(0.01, function()
    local n, depth, graz = mem:escaped(gas)
    most, deepest, grazing = math.max(most, n), math.max(deepest, depth / h), math.max(grazing, graz)
    if n > 0 and not first then first = sim.t end
  end)
  sim:run{ t_end = t_end }
  print(string.format("%6s  %7d  %7s  %13.3f  %7d", c, most, first and string.format("%.2f", first) or "-",
                      deepest, grazing))
end
