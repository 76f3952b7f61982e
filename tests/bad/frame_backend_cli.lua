-- expect: 2
-- args: --backend vulkan
-- stderr: lamina run: --backend vulkan: unknown backend 'vulkan' \(known: cairo, osmesa, egl, gl\)
-- `lamina run --backend` is checked before the script runs.
error("not reached: the command line is refused first")
