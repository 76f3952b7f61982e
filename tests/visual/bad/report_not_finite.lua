-- expect: 2
-- stderr: report_not_finite.lua:4: lamina.report: 'drift' must be a finite number
-- a NaN cannot go into JSON, and a measured NaN means the run went wrong
lamina.report{ drift = 0 / 0 }
