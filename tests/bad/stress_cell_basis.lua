-- expect: 2
-- stderr: lamina.sim: stress = "cell" works with basis = "linear" only \(got basis = "gimp"\)
lamina.sim{dt = 1e-3, stress = "cell", basis = "gimp"}
