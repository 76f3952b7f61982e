-- bar_wall_fem.lua - an independent reference for the two-bar impact of
-- [M] §4.1-4.2 / [T] A.1.5: not MPM, a plain finite-element bar against a
-- rigid frictionless wall (ours, written for issue 14).
--
-- Why a wall: the two bars are equal and meet head on, so in the frame of
-- their centre of mass (velocity v0/2) the problem is mirror-symmetric
-- about the plane where they meet. On that plane the normal velocity is
-- zero while they touch and the shear traction is zero (antisymmetric
-- under the mirror, continuous across the plane), so each bar sees a rigid
-- frictionless wall that it may leave: one bar at v0/2 against the wall,
-- rebounding at e v0/2, gives the two bars' velocities after release
-- v0/2 (1 -+ e). An ideal 1D rod has e = 1 (left 0, right v0); a 2D bar
-- keeps some energy in vibration.
--
-- The model: bilinear quadrilaterals, 2 x 2 Gauss points, small-strain
-- linear elasticity in plane stress or strain (the bar translates, it does
-- not rotate, so the linear strain of u = x - X is exact for the
-- translation), lumped masses, explicit central differences at a fraction
-- of the stable step; the wall as a kinematic condition on the face nodes
-- (a node that would pass the wall is put on it with no normal velocity,
-- and leaves when its own forces pull it away). The kinematic condition
-- loses the face nodes' share of the normal kinetic energy at the first
-- touch, O(h): the function returns e at the given element size; callers
-- compare two sizes.
local M = {}

-- o.lx, o.ly (bar size), o.h (element size), o.E, o.nu, o.rho,
-- o.plane ("stress" or "strain"), o.v (speed towards the wall),
-- o.t_end (time after first touch), o.cfl (fraction of the stable step).
-- Returns e (rebound speed over o.v, from the bar's momentum), the time
-- the last node left the wall, and the energy at the end over the start.
function M.rebound(o)
  local nx, ny = math.floor(o.lx / o.h + 0.5), math.floor(o.ly / o.h + 0.5)
  local hx, hy = o.lx / nx, o.ly / ny
  local E, nu, rho = o.E, o.nu, o.rho
  local c11, c12, c33
  if o.plane == "strain" then
    local f = E / ((1 + nu) * (1 - 2 * nu))
    c11, c12, c33 = f * (1 - nu), f * nu, E / (2 * (1 + nu))
  else
    local f = E / (1 - nu * nu)
    c11, c12, c33 = f, f * nu, E / (2 * (1 + nu))
  end
  local cp = math.sqrt(c11 / rho)
  local dt = (o.cfl or 0.5) * math.min(hx, hy) / cp
  local nn = (nx + 1) * (ny + 1)
  local function id(i, j) return j * (nx + 1) + i + 1 end
  local ux, uy, vx, vy, m = {}, {}, {}, {}, {}
  for k = 1, nn do ux[k], uy[k], vx[k], vy[k], m[k] = 0, 0, o.v, 0, 0 end
  local me = rho * hx * hy / 4
  for j = 0, ny - 1 do
    for i = 0, nx - 1 do
      for _, k in ipairs{ id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1) } do
        m[k] = m[k] + me
      end
    end
  end
  -- shape-function gradients at the four Gauss points of the reference
  -- element (the same for every element: a regular mesh)
  local g = 1 / math.sqrt(3)
  local gp = { {-g, -g}, {g, -g}, {g, g}, {-g, g} }
  local corners = { {-1, -1}, {1, -1}, {1, 1}, {-1, 1} }
  local dN = {}
  for q = 1, 4 do
    local xi, eta = gp[q][1], gp[q][2]
    dN[q] = {}
    for a = 1, 4 do
      local xa, ea = corners[a][1], corners[a][2]
      dN[q][a] = { xa * (1 + ea * eta) / 4 * 2 / hx, ea * (1 + xa * xi) / 4 * 2 / hy }
    end
  end
  local wq = hx * hy / 4   -- Gauss weight times the Jacobian
  local fx, fy = {}, {}
  local function forces()
    for k = 1, nn do fx[k], fy[k] = 0, 0 end
    for j = 0, ny - 1 do
      for i = 0, nx - 1 do
        local n = { id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1) }
        for q = 1, 4 do
          local d = dN[q]
          local exx, eyy, gxy = 0, 0, 0
          for a = 1, 4 do
            local k = n[a]
            exx = exx + d[a][1] * ux[k]
            eyy = eyy + d[a][2] * uy[k]
            gxy = gxy + d[a][2] * ux[k] + d[a][1] * uy[k]
          end
          local sxx, syy, sxy = c11 * exx + c12 * eyy, c12 * exx + c11 * eyy, c33 * gxy
          for a = 1, 4 do
            local k = n[a]
            fx[k] = fx[k] - wq * (d[a][1] * sxx + d[a][2] * sxy)
            fy[k] = fy[k] - wq * (d[a][1] * sxy + d[a][2] * syy)
          end
        end
      end
    end
  end
  local function energy()
    local ke = 0
    for k = 1, nn do ke = ke + 0.5 * m[k] * (vx[k] ^ 2 + vy[k] ^ 2) end
    local se = 0
    for k = 1, nn do se = se - 0.5 * (fx[k] * ux[k] + fy[k] * uy[k]) end
    return ke + se
  end
  forces()
  local e0 = energy()
  local wall = 0   -- the face's displacement that puts it on the wall
  local t, last = 0, 0
  -- central differences: v at half steps, u at whole ones
  for k = 1, nn do vx[k], vy[k] = vx[k] + 0.5 * dt * fx[k] / m[k], vy[k] + 0.5 * dt * fy[k] / m[k] end
  while t < o.t_end do
    local touching = false
    for k = 1, nn do
      ux[k], uy[k] = ux[k] + dt * vx[k], uy[k] + dt * vy[k]
    end
    for j = 0, ny do
      local k = id(nx, j)
      if ux[k] >= wall then
        vx[k] = vx[k] - (ux[k] - wall) / dt
        ux[k] = wall
        touching = true
      end
    end
    forces()
    for k = 1, nn do
      vx[k], vy[k] = vx[k] + dt * fx[k] / m[k], vy[k] + dt * fy[k] / m[k]
    end
    -- a face node on the wall whose new velocity points into it is held
    for j = 0, ny do
      local k = id(nx, j)
      if ux[k] >= wall and vx[k] > 0 then vx[k] = 0; touching = true end
    end
    t = t + dt
    if touching then last = t end
  end
  local p, mt = 0, 0
  for k = 1, nn do p, mt = p + m[k] * vx[k], mt + m[k] end
  -- velocities at t - dt/2 against displacements at t: the energy is
  -- accurate to O(dt), enough for a percent
  return -p / mt / o.v, last, energy() / e0
end

return M
