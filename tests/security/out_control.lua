-- expect: 2
-- stderr: out_control\.lua:6: sim:frame: cannot write 'out/security/a\\10b\.png': the file name contains a control character
-- Issue 18, item 2: control characters in a file name are refused (shown
-- escaped in the message, so the message stays one line).
local sim = lamina.sim{ dt = 1e-3 }
sim:frame{ file = "out/security/a\nb.png", width = 16, height = 16 }
