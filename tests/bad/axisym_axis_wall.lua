-- expect: 2
-- stderr: axisym_axis_wall\.lua:5: lamina\.sim: axisymmetric: the left side is the axis r = 0 and must be boundary "symmetry" \(it is "fixed"\)
-- The axis of an axisymmetric run is a symmetry wall; the default
-- "fixed" there would hold the axial motion on it.
local sim = lamina.sim{ domain = {0, 0, 1, 1}, dt = 1e-3, axisymmetric = true }
