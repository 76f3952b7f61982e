-- gas_arc.lua - a pressurised arc between two gases (issue 30 item 5),
-- shared by its tests: a box 2 x 1 with fixed walls, a string of E t = 5e4
-- along a circular arc of radius 1 centred at (0.2, 0.5) from -30 to 30
-- degrees (its ends on the bottom and top walls), gas at p 2000 on its left
-- and 1000 on its right (gamma 1.4, rho 1, mu 0.5, clipped seeding),
-- started unstressed: the arc bulges right and rings down towards
-- T = dp R. o: ppc, cell (default 0.1), dt (default 3e-5).
-- Returns sim, left gas, right gas, membrane, thickness.
local M = {}

function M.setup(o)
  local h = o.cell or 0.1
  local sim = lamina.sim{ domain = {0, 0, 2, 1}, cell = h, dt = o.dt or 3e-5,
                          boundary = { left = "fixed", right = "fixed", bottom = "fixed",
                                       top = "fixed" } }
  local t = 0.01
  local g1 = lamina.gas{ rho = 1, p = 2000, gamma = 1.4, mu = 0.5 }
  local g2 = lamina.gas{ rho = 1, p = 1000, gamma = 1.4, mu = 0.5 }
  local skin = lamina.membrane{ rho = 1, E = 5e6, thickness = t }
  local function xarc(y) return 0.2 + math.sqrt(1 - (y - 0.5)^2) end
  local left = sim:body{ material = g1, ppc = o.ppc, name = "left", fill = "clipped",
                         region = function(x, y) return x < xarc(y) end }
  local right = sim:body{ material = g2, ppc = o.ppc, name = "right", fill = "clipped",
                          region = function(x, y) return x > xarc(y) end }
  local mem = sim:membrane{ material = skin, spacing = 0.5 * h, name = "arc",
                            curve = lamina.arc{ center = {0.2, 0.5}, radius = 1, from = -30,
                                                to = 30 } }
  return sim, left, right, mem, t
end

-- The pressure over the space each gas fills, independently of lamina's
-- estimate: (gamma - 1) sum m e over the area between the walls and the
-- membrane's polyline (left: the polygon through (0, 1) and (0, 0)).
function M.space_pressures(left, right, mem)
  local q = mem:particles()
  local pts = {}
  for k = 1, q.n do pts[#pts + 1] = {q.x[k], q.y[k]} end
  pts[#pts + 1] = {0, 1}
  pts[#pts + 1] = {0, 0}
  local a2 = 0
  for k = 1, #pts do
    local j = k == 1 and #pts or k - 1
    a2 = a2 + pts[j][1] * pts[k][2] - pts[k][1] * pts[j][2]
  end
  local aL = math.abs(a2) / 2
  local function energy(gas)
    local g, s = gas:particles(), 0
    for k = 1, g.n do s = s + g.mass[k] * g.e[k] end
    return s
  end
  return 0.4 * energy(left) / aL, 0.4 * energy(right) / (2 - aL)
end

-- The arc's radius from its ends and its middle point (chord and sag).
function M.radius(mem)
  local q = mem:particles()
  local n = q.n
  local ax, ay, bx, by = q.x[1], q.y[1], q.x[n], q.y[n]
  local mx = q.x[(n + 1) // 2]
  local c2 = ((bx - ax)^2 + (by - ay)^2) / 4
  local sag = math.abs(mx - (ax + bx) / 2)
  return (c2 + sag * sag) / (2 * sag)
end

return M
