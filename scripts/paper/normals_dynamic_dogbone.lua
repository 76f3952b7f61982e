-- title: Dog-bone expansion: isosurface normals (left) against connectivity (right)
-- source: normals paper §8, Figs 14, 15 and 16
-- look: the slack dog-bone membrane is pushed out to a circle in both runs;
--   left half with normals from the isosurface construction (lamina's
--   centred elements), right half with connectivity; the pressure histories
--   (Fig 15) coincide through the first oscillations, as in the paper, and
--   stay within a few per cent to t = 2 (the isosurface run ~3 % lower at
--   the end); both end near the taut radius 1.39. Kept visible: a few
--   wrinkles on the isosurface side. With the paper's per-cell hybrid rule
--   the wrinkles grow unresisted after t ~ 0.6, the radius reaches 1.50 and
--   the pressure ends 16 % lower (docs/normals.md). Fig 16's close-ups after
--   4 and 7 steps draw the construction's phi (phi = 1 bold through the
--   points) with the normals
-- checks: the largest difference of the two pressure histories after the
--   first oscillation; final radii at 0 and 90 degrees of both runs
-- assumed: the dog-bone of gas_dogbone_superellipse (assets/lua/dogbone.lua) at cell 0.1,
--   200 membrane points, pure FLIP, to t = 2 (the paper's figures stop at
--   the early oscillations and the final shape); normals = "isosurface"
--   (docs/normals.md "Centred elements"); quarter model mirrored
-- visual: cell=0.2 t_end=0.2
-- thumb: fig14_t0.20.png
local out = lamina.param("out", "out/normals_dynamic_dogbone")
local h = lamina.param("cell", 0.1)
local t_end = lamina.param("t_end", 2)
local dog = require("dogbone")

local function build(method)
  local sim, gas, mem = dog.setup(h, { normals = method })
  local rec = sim:record{ every = 0.005, values = {
    p = function() return gas:pressure("particles") end,
    r0 = function() return mem:radius_at(0) end,
    r90 = function() return mem:radius_at(90) end } }
  return sim, rec
end

local iso, rec_i = build("isosurface")
local con, rec_c = build("connectivity")
for _, tf in ipairs{0, 0.05, 0.1, 0.2, 0.4, 1, 2} do
  if tf > t_end + 1e-12 then break end
  iso:run{ t_end = tf }
  con:run{ t_end = tf }
  iso:frame{ file = string.format("%s/fig14_t%.2f.png", out, tf), width = 720, height = 420,
             mirror = "x", split = con, names = {"isosurface", "connectivity"}, normals = 4,
             discs = "spacing", window = {-1.6, 0, 1.6, 1.6}, title = string.format("Figs 14/16: t = %.2f", tf) }
  if tf == 0 then
    -- Fig 16: the first steps close up, as the paper shows them: the
    -- membrane points, their normals and the phi of the construction that
    -- gave them (phi = 1 bold through the points, 0.5 and 1.5 thin, 0
    -- dashed; the connectivity half shows the isosurface construction on
    -- its own points)
    for _, n in ipairs{4, 7} do
      iso:step(n - iso.nstep)
      con:step(n - con.nstep)
      iso:frame{ file = string.format("%s/fig16_step%d.png", out, n), width = 760, height = 380,
                 mirror = "x", split = con, names = {"isosurface", "connectivity"},
                 normals = true, phi = true, particles = "membranes", discs = "spacing",
                 window = {-0.4, 0.8, 0.4, 1.15},
                 title = string.format("Fig 16: after %d steps, phi contours and normals", n) }
    end
  end
end
iso:run{ t_end = t_end }
con:run{ t_end = t_end }

local ti, pi, pc = rec_i:column("t"), rec_i:column("p"), rec_c:column("p")
local dev = 0
for j = 1, math.min(#pi, #pc) do
  if ti[j] > 0.5 then dev = math.max(dev, math.abs(pi[j] - pc[j]) / pc[j]) end
end
lamina.plot{ file = out .. "/fig15_pressure.png", csv = true, width = 640, height = 360,
             title = "Fig 15: mean gas pressure", xlabel = "t", ylabel = "p",
             series = { { x = ti, y = pi, label = "isosurface normals" },
                        { x = rec_c:column("t"), y = pc, label = "connectivity normals", dashed = true } } }
local t0 = math.max(0, t_end - 0.5)
lamina.report{
  pressure_difference_after_0_5 = { 100 * dev, unit = "% (largest)" },
  radius_0_isosurface = rec_i:mean("r0", t0, t_end), radius_90_isosurface = rec_i:mean("r90", t0, t_end),
  radius_0_connectivity = rec_c:mean("r0", t0, t_end), radius_90_connectivity = rec_c:mean("r90", t0, t_end),
  state_hash = iso:hash(),
}
