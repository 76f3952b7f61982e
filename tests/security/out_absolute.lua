-- expect: 2
-- stderr: out_absolute\.lua:18: sim:record: cannot write '/tmp/lamina_security_x\.csv': .*outside the output root
-- Issue 18, item 2: an absolute path outside the working directory (as
-- root it reached a system folder) is refused, for every writer.
local sim = lamina.sim{ dt = 1e-3 }
local function refused(f, ...)
  local ok, err = pcall(f, ...)
  assert(not ok and err:find("outside the output root"), tostring(err))
end
refused(sim.frame, sim, { file = "/tmp/lamina_security_x.png" })
refused(lamina.plot, { file = "/tmp/lamina_security_x.png", series = {} })
refused(lamina.plot, { file = "out/security/p.png", csv = "/tmp/lamina_security_x.csv",
                       series = {} })
refused(lamina.figure{ width = 16, height = 16 }.write, lamina.figure{ width = 16, height = 16 },
        "/tmp/lamina_security_x.png")
refused(sim.frame, sim, { file = "/etc/lamina_security_x.svg" })
-- the error a script sees when it does not catch it
sim:record{ file = "/tmp/lamina_security_x.csv" }
