-- lamina.plot from a script: plots are written and return their paths; every
-- option is accepted once; wrong tables are refused with messages that name
-- the key, the series and the lengths (a failed assert exits with status 2).
local n = 300
local t, u, ref = {}, {}, {}
for i = 1, n do
  t[i] = (i - 1) * 0.01
  ref[i] = math.sin(2 * math.pi * t[i])
  u[i] = ref[i] * math.exp(-0.3 * t[i])
end

-- the papers' kind of figure: a computed curve against the analytic one
local png, csv = lamina.plot{
  file = "out/plot_api/sine.png", title = "damped sine against the reference",
  xlabel = "t (s)", ylabel = "u (m)", csv = true,
  series = { { x = t, y = u, label = "MPM" },
             { x = t, y = ref, label = "analytic", dashed = true, color = 8 } } }
assert(png == "out/plot_api/sine.png", "lamina.plot returned " .. tostring(png))
assert(csv == "out/plot_api/sine.csv", "csv = true gave " .. tostring(csv))

-- every key once
png, csv = lamina.plot{
  file = "out/plot_api/all.png", width = 400, height = 300, title = "all keys",
  xlabel = "t", ylabel = "θ (rad)", xrange = {0, 2}, yrange = {-1.5, 1.5},
  legend = "bottom left", csv = "out/plot_api/all_data.csv",
  series = { { x = t, y = u, label = "markers", markers = true, color = 3, width = 1 },
             { x = t, y = ref, label = "thick", dashed = false, width = 2.5 },
             { x = t, y = u } } }
assert(png == "out/plot_api/all.png" and csv == "out/plot_api/all_data.csv")
assert(select("#", lamina.plot{ file = "out/plot_api/nolegend.png", legend = false,
                               series = { { x = t, y = u, label = "hidden" } } }) == 1,
       "without csv, lamina.plot returns the image path only")
for _, pos in ipairs{ "top left", "top", "bottom right", "bottom", "left", "right",
                      "center", "best" } do
  lamina.plot{ file = "out/plot_api/legend.png", legend = pos, width = 300, height = 200,
               series = { { x = t, y = u, label = pos } } }
end

-- degenerate data is drawn, not refused: gaps at NaN and inf, one point,
-- a constant
lamina.plot{ file = "out/plot_api/degenerate.png",
             series = { { x = {0, 1, 2, 3}, y = {0, 0/0, math.huge, 1}, label = "gaps" },
                        { x = {1.5}, y = {0.5}, label = "one point" },
                        { x = {0, 3}, y = {2, 2}, label = "constant" } } }

local function fails(args, expected)
  local ok, err = pcall(lamina.plot, args)
  assert(not ok, "lamina.plot accepted a wrong table; expected: " .. expected)
  assert(tostring(err):find(expected, 1, true),
         "wrong message:\n  got:      " .. tostring(err) .. "\n  expected: " .. expected)
end

local good = { { x = {0, 1}, y = {0, 1} } }
fails({ file = "out/plot_api/bad.png", series = good, colour = 2 },
      "lamina.plot: unknown key 'colour' (known keys: file, width, height, title, " ..
      "xlabel, ylabel, xrange, yrange, legend, csv, series)")
fails({ file = "out/plot_api/bad.png", series = { { x = {0, 1}, y = {0, 1}, colour = 2 } } },
      "lamina.plot: series 1: unknown key 'colour' (known keys: x, y, label, dashed, " ..
      "color, width, markers)")
fails({ file = "out/plot_api/bad.png",
        series = { good[1], { x = {0}, y = {0}, label = "FEM", dash = true } } },
      "lamina.plot: series 2 ('FEM'): unknown key 'dash'")
fails({ file = "out/plot_api/bad.png",
        series = { good[1], { x = {1, 2, 3}, y = {1, 2}, label = "FEM" } } },
      "lamina.plot: series 2 ('FEM'): x and y must have the same length " ..
      "(x has 3 values, y has 2)")
fails({ file = "out/plot_api/bad.png", series = { { x = {}, y = {} } } },
      "lamina.plot: series 1 is empty")
fails({ file = "out/plot_api/bad.png", series = { { x = {1, 2}, y = {1, "a"} } } },
      "lamina.plot: series 1: y[2] must be a number (got string)")
fails({ file = "out/plot_api/bad.png", series = { { y = {1, 2} } } },
      "lamina.plot: series 1: 'x' is required")
fails({ file = "out/plot_api/bad.png", series = { { x = {1, 2}, y = {1, 2}, color = 0 } } },
      "'color' must be a whole number >= 1")
fails({ file = "out/plot_api/bad.png", series = { { x = {1, 2}, y = {1, 2}, width = -1 } } },
      "'width' must be a line width in pixels")
fails({ file = "out/plot_api/bad.png", series = { { x = {1, 2}, y = {1, 2}, dashed = "yes" } } },
      "'dashed' must be true or false")
fails({ series = good }, "lamina.plot: 'file' is required")
fails({ file = "out/plot_api/bad.png" }, "lamina.plot: 'series' is required")
fails({ file = "out/plot_api/bad.png", series = {} }, "lamina.plot: 'series' is empty")
fails({ file = "out/plot_api/bad.png", series = { x = {1}, y = {1} } },
      "lamina.plot: 'series' must be a list of series tables")
fails({ file = "out/plot_api/bad.png", series = { 42 } }, "lamina.plot: series 1 must be a table")
fails({ file = "out/plot_api/bad.png", series = good, legend = "upper right" },
      "lamina.plot: legend = \"upper right\" is not one of \"top right\"")
fails({ file = "out/plot_api/bad.png", series = good, xrange = {1, 0} },
      "lamina.plot: 'xrange' = {1, 0} must be finite with the first below the second")
fails({ file = "out/plot_api/bad.png", series = good, yrange = {1} },
      "lamina.plot: 'yrange' must be a pair {a, b}")
fails({ file = "out/plot_api/bad.png", series = good, width = 10.5 },
      "lamina.plot: width and height must be whole numbers in [16, 16384]")
fails({ file = "out/plot_api/bad.png", series = good, csv = "out/plot_api/bad.png" },
      "is the image's own path")
fails({ file = "out/plot_api/sine.png/inside_a_file.png", series = good },
      "cannot write 'out/plot_api/sine.png/inside_a_file.png'")
fails({ "out/plot_api/bad.png" }, "lamina.plot: unexpected positional argument")
local ok, err = pcall(lamina.plot, "out/plot_api/bad.png")
assert(not ok and err:find("lamina.plot expects one table", 1, true), tostring(err))
print("plot_api: all checks passed")
