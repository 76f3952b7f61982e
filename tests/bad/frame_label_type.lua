-- expect: 2
-- stderr: frame_label_type\.lua:7: sim:frame: 'label' must be a string, true or false \(got table\)
-- Issue 31 item 7: any type was accepted for sim:frame's label (a table
-- drew the default label). A string, true (the default) or false (none).
local sim = lamina.sim{ dt = 1e-3, domain = {0, 0, 1, 1}, cell = 0.1 }
sim:frame{ file = "out/bad/frame_label_ok.png", width = 16, height = 16, label = false }
sim:frame{ file = "out/bad/frame_label.png", width = 16, height = 16, label = {} }
