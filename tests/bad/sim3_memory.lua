-- expect: 2
-- args: --memory 64
-- stderr: sim3_memory\.lua:7: lamina\.sim: memory limit 64 MB reached \(engine: 0 MB, lua: [0-9]+ MB, render: 0 MB; engine asked for 84 MB more\)
-- The 3D grid counts against the process's one memory cap (docs/security.md
-- "Memory") and is refused before it is allocated: 101^3 nodes with the
-- B-spline's ring, 10 doubles each, 84 MB.
lamina.sim{ dim = 3, domain = {0, 0, 0, 1, 1, 1}, cell = 0.01, dt = 1e-4 }
