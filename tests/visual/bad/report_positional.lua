-- expect: 2
-- stderr: report_positional.lua:4: lamina.report: unexpected positional argument \(write lamina.report\{name = value\}\)
local r = 0.61
lamina.report{ r }
