-- expect: 2
-- stderr: sim3_gravity_pair\.lua:4: lamina\.sim: 'gravity' must be three numbers \{x, y, z\} in 3D \(got 2\)
-- A 2D vector in a 3D sim is refused naming the key (issue 34 item 1).
lamina.sim{ dim = 3, domain = {0, 0, 0, 1, 1, 1}, cell = 0.1, dt = 1e-3, gravity = {0, -9.81} }
