-- A 3D run's frame from a script (issue 34 item 4): lamina.sim{dim = 3}'s
-- sim:frame{} reaches the 3D renderer (src/lua/l_frame3d.c). Driven by
-- tests/io/frame3d.sh, which runs it twice and compares the bytes.
local out = lamina.param("out", "out/frame3d")
local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, 1, 1, 1}, cell = 0.1, dt = 1e-3,
                        gravity = {0, 0, -9.81} }
local rock = lamina.elastic{ rho = 1000, E = 1e6, nu = 0.3 }
sim:body{ material = rock, region = lamina.ball{center = {0.5, 0.5, 0.4}, radius = 0.2},
          velocity = {0, 0, -0.5} }
sim:run{ t_end = 0.02 }
sim:frame{ file = out .. "/ball.png", title = "a falling ball", colour = "speed",
           backend = "cairo" }
