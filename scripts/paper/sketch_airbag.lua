-- title: Airbag impact problem: the probe, the airbag on its support, and the two probes of Table 7
-- source: York's dissertation §6.3.1, Fig 57
-- look: a cross-section: the airbag (the membrane line of the input deck,
--   Box 10, mirrored about the axis) on its support, the support on a spring,
--   the cylindrical probe above it moving down at v_0; the Cyl-200 probe
--   solid, the Cyl-500 one dashed; Table 7 beside. Drawn to scale in mm
-- checks: the bag's extent in the deck the pages run (Box 10) against the
--   figure's label "580 x 315 mm major axes" (to the millimetre the label
--   gives): the deck's bag is 560 mm across (its widest point at r = 0.28 m)
--   and 316 mm high, so both miss - shown, with this reason (the label is the
--   experiment's bag, de Coo's; [T] ran the deck's)
-- assumed: the support and spring are drawn as the figure has them; no
--   simulation here models them (airbag_impact holds the bag's lower pole on
--   the grid's fixed bottom)
-- thumb: sketch_airbag.png
local sk = require("sketch")
local airbag = require("airbag")
local out = lamina.param("out", "out/sketch_airbag")

local curve = airbag.bag_curve
local rmax, zmin, zmax = 0, math.huge, -math.huge
local line = {}
for i = #curve, 1, -1 do line[#line + 1] = {-1e3 * curve[i][1], 1e3 * curve[i][2]} end
for i = 1, #curve do
  line[#line + 1] = {1e3 * curve[i][1], 1e3 * curve[i][2]}
  rmax = math.max(rmax, curve[i][1])
  zmin, zmax = math.min(zmin, curve[i][2]), math.max(zmax, curve[i][2])
end
local width, height = 2e3 * rmax, 1e3 * (zmax - zmin)

local fig = lamina.figure{ width = 1100, height = 640, panels = {1, 1},
  title = "[T] Fig 57: airbag impact problem" }
fig:panel{ index = 1, window = {-420, -200, 880, 520},
           caption = string.format("the deck's bag (Box 10): %.0f x %.0f mm; the figure's label: 580 x 315 mm",
                                   width, height) }
-- support, spring, ground
sk.box(fig, -330, -25, 330, 0, { width = 2 })
fig:text{ text = "support", at = {-340, -20}, align = "right" }
sk.spring(fig, {0, -25}, {0, -150}, { coils = 5, width = 30 })
fig:text{ text = "spring", at = {40, -95} }
sk.wall(fig, {-120, -150}, {120, -150}, { side = -1, hatch = 20, strokes = 10 })
-- the bag
fig:polyline{ points = line, colour = "black", width = 2.5 }
fig:polyline{ points = {{0, -30}, {0, 500}}, colour = "grey", dashed = true }
fig:text{ text = "airbag", at = {0, 240}, align = "center" }
fig:text{ text = "(580 x 315 mm major axes)", at = {0, 210}, align = "center" }
sk.dim(fig, {-1e3 * rmax, 139}, {1e3 * rmax, 139}, string.format("%.0f mm (deck)", width), { gap = -25 })
-- the probes (Table 7), 11 mm over the bag's top as Box 10
local z0 = 1e3 * zmax + 11
sk.box(fig, -100, z0, 100, z0 + 80, { width = 2.5 })
sk.box(fig, -250, z0, 250, z0 + 80, { width = 1.2, dashed = true })
fig:text{ text = "probe (Cyl-200; Cyl-500 dashed)", at = {0, z0 + 95}, align = "center" }
sk.arrow(fig, {170, z0 + 150}, {170, z0 + 85}, "v_0")
-- Table 7
local rows = { {"", "diameter", "mass", "v_0"}, {"Cyl-200", "200 mm", "6.03 kg", "3.90 m/s"},
               {"Cyl-500", "500 mm", "8.05 kg", "4.70 m/s"} }
fig:text{ text = "[T] Table 7", at = {380, 470} }
for i, r in ipairs(rows) do
  for j, c in ipairs(r) do fig:text{ text = c, at = {380 + (j - 1) * 120, 470 - 40 * i} } end
end
fig:text{ text = "Table 8: bag t 0.5 mm, rho 662, E 6e7, nu 0.4;", at = {380, 290} }
fig:text{ text = "air gamma 1.4, rho 1.2156, p0 4000 Pa", at = {380, 260} }
fig:write(out .. "/sketch_airbag.png")

print(string.format("deck bag: %.1f mm across, %.1f mm high (figure: 580 x 315)", width, height))
lamina.report{
  bag_width = { width, paper = 580, tol = 0.5, unit = "mm (the deck's, Box 10; [T] Fig 57's label)" },
  bag_height = { height, paper = 315, tol = 0.5, unit = "mm (the deck's, Box 10; [T] Fig 57's label)" },
  bag_note = airbag.bag_note,
}
