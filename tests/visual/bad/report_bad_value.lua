-- expect: 2
-- stderr: report_bad_value.lua:3: lamina.report: 'radius'.tol must be a finite number >= 0
lamina.report{ radius = { 0.61, paper = 0.6, tol = -1 } }
