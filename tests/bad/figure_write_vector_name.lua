-- expect: 2
-- stderr: figure_write_vector_name\.lua:6: figure:write: cannot write 'out/bad/fig\.svg': this picture is pixels, written as PNG only \(name it \.png\)
-- fig:write makes pixels: a .svg / .pdf name is refused by the one image
-- writer (lr_image_write), not written as PNG bytes under that name.
local fig = lamina.figure{ width = 64, height = 64, backend = "cairo" }
fig:write("out/bad/fig.svg")
