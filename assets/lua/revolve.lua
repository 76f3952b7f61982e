-- revolve.lua - an axisymmetric run seen in 3D: its (r, z) cross-section
-- revolved about the axis (issue 15 item 4), drawn through lamina.figure's
-- 3D panels (OSMesa or EGL with a depth buffer, else cairo; docs/api.md,
-- "lamina.figure").
--
--   local revolve = require("revolve")
--   revolve.frame(sim, { file = "out/bag3d.png", bodies = {gas, bag, probe},
--                        title = "t = 40 ms" })
--
-- Each membrane becomes its surface of revolution, drawn as meridians (the
-- membrane's polyline turned to `meridians` angles) and rings (every
-- `ring_every`-th point's circle); the other bodies' particles are drawn in
-- the cut plane, both halves of the section (r cos 0 and r cos 180), so the
-- picture is the mirrored cross-section of sim:frame{mirror = "x"} set in
-- the revolved surface. Only the half of the surface facing away from the
-- viewer (angles from 90 to 270 degrees past the azimuth) is drawn when
-- `cutaway` is true (the default), so the inside stays visible.
--
-- o: file and bodies (the body handles to draw, required), width (800), height (700), title, azimuth (-60),
-- elevation (20), meridians (24), ring_every (the membrane's points / 16),
-- cutaway (true), dots (the particles' marker radius in pixels, 1.2),
-- backend (lamina.figure's). Returns the file name.
local M = {}

local function membrane_of(b)
  local ok, r = pcall(function() return b:particles().nx ~= nil end)
  return ok and r
end

-- The box that holds the revolved run: r up to the largest radius, z over
-- the particles' range, with a margin.
local function bounds(parts)
  local rmax, z0, z1 = 0, math.huge, -math.huge
  for _, P in ipairs(parts) do
    for k = 1, P.n do
      rmax = math.max(rmax, P.x[k])
      z0, z1 = math.min(z0, P.y[k]), math.max(z1, P.y[k])
    end
  end
  local m = 0.05 * math.max(rmax, z1 - z0)
  return rmax + m, z0 - m, z1 + m
end

function M.frame(sim, o)
  assert(type(o) == "table" and o.file and type(o.bodies) == "table",
         "revolve.frame(sim, {file = ..., bodies = {...}})")
  assert(sim.axisymmetric, "revolve.frame: the sim is not axisymmetric")
  local az = o.azimuth or -60
  local nmer = o.meridians or 24
  local cutaway = o.cutaway ~= false
  local bodies, parts = o.bodies, {}
  for i, b in ipairs(bodies) do parts[i] = b:particles() end
  local R, z0, z1 = bounds(parts)
  local fig = lamina.figure{ width = o.width or 800, height = o.height or 700,
                             title = o.title, backend = o.backend }
  fig:panel{ index = 1, box = {-R, -R, z0, R, R, z1}, azimuth = az,
             elevation = o.elevation or 20 }
  -- the angles drawn: all, or the far half seen from the azimuth
  local function shown(th)
    if not cutaway then return true end
    local d = math.cos(math.rad(th - az))
    return d <= 1e-9
  end
  local colours = { {0.12, 0.35, 0.75}, {0.75, 0.3, 0.1}, {0.2, 0.55, 0.25}, {0.45, 0.3, 0.6} }
  for i, b in ipairs(bodies) do
    local P = parts[i]
    if membrane_of(b) then
      for k = 0, nmer - 1 do
        local th = 360 * k / nmer
        if shown(th) then
          local c, s = math.cos(math.rad(th)), math.sin(math.rad(th))
          local pts = {}
          for j = 1, P.n do pts[j] = { P.x[j] * c, P.x[j] * s, P.y[j] } end
          fig:polyline{ points = pts, colour = "black", width = 1.2 }
        end
      end
      local every = o.ring_every or math.max(1, P.n // 16)
      for j = 1, P.n, every do
        local pts = {}
        for k = 0, 96 do
          local th = 360 * k / 96
          if shown(th) then
            pts[#pts + 1] = { P.x[j] * math.cos(math.rad(th)), P.x[j] * math.sin(math.rad(th)), P.y[j] }
          end
        end
        if #pts > 1 then fig:polyline{ points = pts, colour = "grey", width = 0.8 } end
      end
    else
      -- the section's particles in the cut plane, both halves
      local pts = {}
      local c, s = math.cos(math.rad(az + 90)), math.sin(math.rad(az + 90))
      for j = 1, P.n do
        pts[#pts + 1] = { P.x[j] * c, P.x[j] * s, P.y[j] }
        pts[#pts + 1] = { -P.x[j] * c, -P.x[j] * s, P.y[j] }
      end
      fig:points{ points = pts, style = "dot", size = o.dots or 1.2,
                  colour = colours[(i - 1) % #colours + 1] }
    end
  end
  fig:polyline{ points = { {0, 0, z0}, {0, 0, z1} }, colour = "grey", width = 1, dashed = true }
  return fig:write(o.file)
end

return M
