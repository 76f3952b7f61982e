-- The figure keys of sim:frame (docs/api.md, docs/rendering.md) on a real
-- run, through every backend this lamina has: one panel by body, colour
-- by a field with a colour bar and a scale bar, a quarter model mirrored
-- in x and y, a left/right split of MUSL and USL, two panels in a grid,
-- SVG and PDF. A failure is a Lua error (status 2); the unit tests check
-- the pixels (test_figure.c, test_canvas_backends.c).
local out = lamina.param("out", "out/frame_figures")

local function run(scheme)
  local sim = lamina.sim{ basis = "linear", domain = {0, 0, 1, 1}, cell = 0.05, dt = 1e-3, scheme = scheme,
                          boundary = { left = "symmetry", bottom = "symmetry" } }
  local rubber = lamina.elastic{ rho = 1000, E = 1000, nu = 0.3 }
  sim:body{ material = rubber, ppc = 4, velocity = {-0.1, -0.1}, name = "quarter disk",
            region = lamina.disk{ center = {0.3, 0.3}, radius = 0.25 } }
  sim:run{ t_end = 0.2 }
  return sim
end
local musl, usl = run("musl"), run("usl")

local backends = { "cairo" }
-- a build without a GL backend says so (EGL also when it cannot start);
-- then only the others are exercised
local function probe(name, why)
  local ok, err = pcall(musl.frame, musl, { file = out .. "/probe.png", backend = name,
                                            width = 32, height = 32 })
  if ok then
    backends[#backends + 1] = name
  else
    assert(tostring(err):find(why), err)
  end
end
probe("osmesa", "built without OSMesa")
probe("egl", "EGL")

for _, b in ipairs(backends) do
  local f = function(name) return string.format("%s/%s_%s.png", out, name, b) end
  assert(musl:frame{ file = f("body"), backend = b, width = 320, height = 240 } == f("body"))
  musl:frame{ file = f("speed"), backend = b, width = 400, height = 300, colour = "speed",
              scalebar = true, units = "m", title = "speed" }
  musl:frame{ file = f("mirror"), backend = b, width = 300, height = 300, mirror = "xy",
              colour = "syy", colourmap = "rdbu", range = {-50, 50} }
  musl:frame{ file = f("split"), backend = b, width = 400, height = 240, mirror = "x",
              split = usl, names = {"MUSL", "USL"}, colour = "pressure", scalebar = 0.25 }
  musl:frame{ file = f("panels"), backend = b, width = 480, height = 240, title = "MUSL and USL",
              colour = "speed", range = {0, 0.15}, layout = {1, 2},
              panels = { { title = "MUSL" }, { sim = usl, title = "USL", grid = false } } }
end
musl:frame{ file = out .. "/split.svg", mirror = "x", split = usl, names = {"MUSL", "USL"},
            colour = "vx", width = 400, height = 240 }
musl:frame{ file = out .. "/split.pdf", mirror = "x", split = usl, names = {"MUSL", "USL"},
            colour = "vx", width = 400, height = 240 }
print(string.format("frame_figures: %d backends, frames in %s", #backends, out))
