-- expect: 2
-- stderr: lamina.sim: stress = "cells" is not one of "points" \| "cell"
lamina.sim{domain = {0, 0, 1, 1}, cell = 0.1, dt = 1e-4, stress = "cells"}
