-- expect: 2
-- stderr: plot_vector_name\.lua:6: .*cannot write 'out/bad/plot\.pdf': this picture is pixels, written as PNG only \(name it \.png\)
-- lamina.plot draws pixels: a .svg / .pdf name is refused by the one image
-- writer (lr_image_write), not written as PNG bytes under that name.
local x, y = {0, 1}, {0, 1}
lamina.plot{ file = "out/bad/plot.pdf", series = {{x = x, y = y}} }
