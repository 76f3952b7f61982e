-- expect: 2
-- stderr: sandbox\.lua:5: attempt to call a nil value \(field 'execute'\)
-- Scenario scripts cannot run programs or open files by themselves:
-- output paths go through lamina (docs/design.md, "A script is untrusted input").
os.execute("true")
