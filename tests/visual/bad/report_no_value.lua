-- expect: 2
-- stderr: report_no_value.lua:3: lamina.report: 'radius': the value is missing
lamina.report{ radius = { paper = 0.6 } }
