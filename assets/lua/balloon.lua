-- balloon.lua - a gas-filled membrane circle falling under gravity onto a
-- fixed floor (issue 30 items 5-6), shared by its tests: the whole circle
-- (no symmetry), a closed membrane counter-clockwise from 0 degrees, the
-- default basis and force unless o says otherwise.
-- o: p (gas pressure, default 30), E (membrane, default 2e3), normals,
-- orient, force, basis, cell (default 0.05), ppc (default 4), spacing (membrane points,
-- cells; default 0.5). Returns sim, gas, membrane.
local M = {}

function M.setup(o)
  o = o or {}
  local h = o.cell or 0.05
  local sim = lamina.sim{ domain = {0, 0, 1.2, 1.2}, cell = h, dt = o.dt or 1e-4, basis = o.basis,
                          mass = o.mass, gravity = {0, -10},
                          boundary = { left = "fixed", right = "fixed", bottom = "fixed",
                                       top = "fixed" } }
  local air = lamina.gas{ rho = 1, p = o.p or 30, gamma = 1.4, mu = 0.05 }
  local skin = lamina.membrane{ rho = 2, E = o.E or 2e3, nu = 0.3, thickness = 0.01,
                                law = "plane_stress" }
  local c, r = {0.6, 0.55}, 0.3
  local gas = sim:body{ material = air, ppc = o.ppc or 4, name = "air", fill = "clipped",
                        region = lamina.disk{ center = c, radius = r } }
  local mem = sim:membrane{ material = skin, spacing = (o.spacing or 0.5) * h, name = "skin",
                            normals = o.normals, orient = o.orient, force = o.force,
                            curve = lamina.arc{ center = c, radius = r, from = 0, to = 360 } }
  return sim, gas, mem
end

-- The points whose normal points into the region the membrane encloses,
-- judged independently of lamina's rule: the outward normal of the polygon
-- from its own winding (shoelace sign) and each point's neighbours.
function M.inward(mem)
  local q = mem:particles()
  local n, a2 = q.n, 0
  for k = 1, n do
    local j = k == 1 and n or k - 1
    a2 = a2 + q.x[j] * q.y[k] - q.x[k] * q.y[j]
  end
  local s = a2 > 0 and 1 or -1        -- counter-clockwise: outward is the right
  local bad = 0
  for k = 1, n do
    local i, j = k == 1 and n or k - 1, k == n and 1 or k + 1
    local dx, dy = q.x[j] - q.x[i], q.y[j] - q.y[i]
    local ox, oy = s * dy, -s * dx     -- the right of (dx, dy) when s = 1
    if q.nx[k] * ox + q.ny[k] * oy <= 0 then bad = bad + 1 end
  end
  return bad, q
end

return M
