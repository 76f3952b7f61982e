-- figure_view3d.lua - lamina.figure's 3D panels (src/render/include/view3d.h):
-- drawn through OSMesa when this lamina has it, else EGL, through cairo
-- when asked (backend = "cairo", or `lamina run --backend cairo`) or when
-- it has neither; EGL when asked (backend = "egl", or "gl" where it starts);
-- the PNG's "lamina:view3d" text chunk names what drew them. Writing twice
-- draws the views again (not over the first drawing); a figure without 3D
-- panels has no such chunk; bad values are errors that name them.
-- Run by figure_view3d.sh, which checks the files it writes (the script's
-- sandbox cannot read them):
--   lamina run figure_view3d.lua --set out=DIR [--backend cairo --set expect=cairo]
local out = lamina.param("out", "out/figure_view3d")
local expect = lamina.param("expect", "")

local function figure(backend)
  local fig = lamina.figure{width = 320, height = 200, panels = {2, 1}, backend = backend,
                            title = "3D and 2D"}
  fig:panel{index = 1, box = {0, 0, 0, 1, 1, 1}, title = "3D", azimuth = -50, elevation = 30}
  fig:outline{}
  local pts = {{0.5, 0.5, 0.5}, {0.8, 0.2, 0.3}}
  fig:arrows{at = pts, dir = {{0, 0, 1}, {0.6, 0, 0.8}}, length = 0.3, style = "dashed"}
  fig:arrows{at = pts, dir = {{0, 0, 1}, {0.8, 0, 0.6}}, length = 0.3}
  fig:points{points = pts}
  fig:points{points = {{0.7, 0.3, 0.8}}, style = "asterisk"}
  fig:polyline{points = {{0, 0, 0}, {1, 0, 0.5}, {1, 1, 0.75}}, dashed = true}
  fig:text{text = "p", at = {0.5, 0.5, 0.5}}
  fig:panel{index = 2, window = {0, 0, 1, 1}, title = "2D"}
  fig:outline{}
  fig:points{points = {{0.5, 0.5}}}
  return fig
end

local has_osmesa = pcall(lamina.figure, {width = 16, height = 16, backend = "osmesa"})
local has_egl = pcall(lamina.figure, {width = 16, height = 16, backend = "egl"})
local default = expect ~= "" and expect or
                (has_osmesa and "osmesa" or has_egl and "egl" or "cairo")
print("osmesa=" .. (has_osmesa and "yes" or "no") .. " egl=" .. (has_egl and "yes" or "no")
      .. " default=" .. default)

-- the default, written twice (the views are drawn afresh each time), and
-- again from another figure; cairo when asked; OSMesa when asked and built;
-- a figure without 3D panels (figure_view3d.sh reads the files)
local fig = figure()
fig:write(out .. "/default_a.png")
fig:write(out .. "/default_b.png")
figure():write(out .. "/default_c.png")
figure("cairo"):write(out .. "/cairo.png")
if has_osmesa then figure("osmesa"):write(out .. "/osmesa.png") end
if has_egl then
  figure("egl"):write(out .. "/egl.png")
  figure("gl"):write(out .. "/gl.png")     -- "gl" is EGL where EGL starts
end
local flat = lamina.figure{width = 64, height = 64}
flat:panel{window = {0, 0, 1, 1}}
flat:outline{}
flat:write(out .. "/flat.png")

-- bad values are named
local function fails(pattern, f, ...)
  local ok, err = pcall(f, ...)
  assert(not ok and tostring(err):find(pattern), "expected an error like '" .. pattern
         .. "', got " .. tostring(err))
end
fails("lamina.figure: unknown backend 'vulkan' %(known: cairo, osmesa, egl, gl%)", lamina.figure,
      {backend = "vulkan"})
fails("lamina.figure: unknown key 'backnd'", lamina.figure, {backnd = "cairo"})
fails("'elevation' in %[%-90, 90%]", fig.panel, fig, {index = 1, box = {0, 0, 0, 1, 1, 1},
      elevation = 100})
if not has_osmesa then
  fails("built without OSMesa", lamina.figure, {backend = "osmesa"})
end
if not has_egl then
  fails("backend = \"egl\": .*libegl", lamina.figure, {backend = "egl"})
end
print("figure_view3d: ok")
