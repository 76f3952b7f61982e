"""What tests/io/fields_agree.py (2D) and fields_agree3.py (3D) check with:
a failure that names the script, and two arrays equal to a tolerance
relative to the second's scale (at least 1)."""
import sys

import numpy as np


def checks(name):
    """fail(msg) and same(a, b, what, tol=1e-13) for the script `name`."""

    def fail(msg):
        print(f"{name}: FAILED:", msg)
        sys.exit(1)

    def same(a, b, what, tol=1e-13):
        a, b = np.asarray(a, float), np.asarray(b, float)
        if a.shape != b.shape:
            fail(f"{what}: shape {a.shape} vs {b.shape}")
        scale = max(1.0, float(np.max(np.abs(b))))
        err = float(np.max(np.abs(a - b)))
        if err > tol * scale:
            fail(f"{what}: differs by {err:g} (scale {scale:g})")

    return fail, same
