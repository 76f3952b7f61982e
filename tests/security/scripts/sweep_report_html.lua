-- Run by security.sweep_summary_markup (issue 31 item 8): reported strings
-- with HTML, a table bar and a terminal escape reach sweep's summary.md
-- (and the copy printed).
local v = lamina.param("v", 1)
lamina.report{ v = v, note = "<script>alert(1)</script> | a & b \27[2J end" }
