-- expect: 2
-- stderr: report_unknown_key.lua:5: lamina.report: 'radius': unknown key 'pape' \(known: the value first, then paper, ref, unit, tol\)
-- stderr: stack traceback
lamina.report{ ok = 1 }
lamina.report{ radius = { 0.61, pape = 0.6 } }
