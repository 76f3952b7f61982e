-- expect: 2
-- stderr: sim3_boundary_side\.lua:5: lamina\.sim: boundary\.bottom is a 2D side; with dim = 3 the faces are x0, x1, y0, y1, z0, z1
-- The 2D side names in 3D: refused by name, so that a script ported from 2D
-- cannot leave z unconstrained silently (docs/3d.md "Lua API").
lamina.sim{ dim = 3, domain = {0, 0, 0, 1, 1, 1}, cell = 0.1, dt = 1e-3,
            boundary = { bottom = "fixed" } }
