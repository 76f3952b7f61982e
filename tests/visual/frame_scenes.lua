-- frame_scenes.lua - the small scenes tests/visual/frame_check.py reads back
-- pixel by pixel (issue 35 item 4; docs/api.md "sim:frame"):
--
-- 1. scale: a taut string (assets/lua/string_modes.lua's: L = 1 between
--    fixed walls, E = 1e4, t = 0.01, initial strain 0.05) started in its
--    first mode, v_y = v0 sin(pi x / L), v0 chosen for an amplitude of
--    0.2 % of L, run a quarter period. Frames before and after, with
--    scale = 100 and without; the script prints the middle point's
--    displacement as the run left it, from which the check predicts the
--    pixels (amplitude x k x pixels per length).
-- 2. tension: the same string at rest, coloured by "tension" with the
--    automatic range, with range = {-sigma t, sigma t} (sigma the string's
--    own hoop_stress, t its thickness) and with range = {-sigma, sigma}.
-- 3. pressure: gas at p = 10 inside a membrane under a stress of 500, as
--    built (every gas point at p = 10, so the automatic range is 5 to 15
--    and the gas is the map's middle), drawn by body, by "pressure" (the default) and, as the check's negative
--    control, as pressure used to be drawn (every body, diverging map).
--
-- Lines "fact NAME VALUE" on stdout are what the check needs.
local out = lamina.param("out", "out/frame_check")
local function fact(name, v) print(string.format("fact %s %.17g", name, v)) end

local E, t, rho, e0, L = 1e4, 0.01, 1, 0.05, 1
local h = 1 / 32
local y0 = 0.5 + 0.3 * h
local walls = { left = "fixed", right = "fixed", top = "free", bottom = "free" }
local skin = lamina.membrane{ rho = rho, E = E, nu = 0, thickness = t, law = "uniaxial" }

-- 1. scale -----------------------------------------------------------------
do
  local sim = lamina.sim{ dt = 0.4 * h / math.sqrt(E / rho), cell = h, domain = {0, 0, 1, 1},
                          boundary = walls }
  -- mu and T as string_modes.lua reads them, to give v0 for amplitude A
  local probe = sim:membrane{ material = skin, initial_strain = e0, spacing = 0.5 * h,
    curve = lamina.segment{ from = {0, y0}, to = {L, y0} } }
  local P = probe:particles()
  local mu = P.mass[2] / math.sqrt((P.x[3] - P.x[2]) ^ 2 + (P.y[3] - P.y[2]) ^ 2)
  local f = 1 / (2 * L) * math.sqrt(probe:hoop_stress() * t / mu)
  local A = 0.002 * L
  local v0 = A * 2 * math.pi * f

  local run = lamina.sim{ dt = 0.4 * h / math.sqrt(E / rho), cell = h, domain = {0, 0, 1, 1},
                          boundary = walls }
  local s = run:membrane{ material = skin, initial_strain = e0, spacing = 0.5 * h,
    curve = lamina.segment{ from = {0, y0}, to = {L, y0} },
    velocity = function(u) return 0, v0 * math.sin(math.pi * u) end }
  local common = { width = 480, height = 320, window = {-0.05, 0.25, 1.05, 0.75}, grid = false,
                   label = false, normals = false }
  local function frame(name, extra)
    local o = { file = out .. "/" .. name .. ".png" }
    for k, v in pairs(common) do o[k] = v end
    for k, v in pairs(extra) do o[k] = v end
    run:frame(o)
  end
  frame("s0_k100", { scale = 100 })
  frame("s0_k1", { title = "plain", phi = false })
  local Q0 = s:particles()
  run:run{ t_end = 1 / (4 * f) }
  frame("s1_k100", { scale = 100 })
  frame("s1_titled", { scale = 100, title = "string" })
  frame("s1_k1", { title = "plain", phi = false })
  local Q = s:particles()
  local mid, best = 1, math.huge
  for i = 1, Q.n do
    if math.abs(Q0.x[i] - 0.5 * L) < best then best, mid = math.abs(Q0.x[i] - 0.5 * L), i end
  end
  fact("amplitude", Q.y[mid] - Q0.y[mid])
  fact("x_first", Q0.x[1])
  fact("x_last", Q0.x[Q.n])
  fact("length", L)
end

-- 2. tension ---------------------------------------------------------------
do
  local es = 0.037   -- a stress whose range ends are not round tick values
  local sim = lamina.sim{ dt = 0.4 * h / math.sqrt(E / rho), cell = h, domain = {0, 0, 1, 1},
                          boundary = walls }
  local s = sim:membrane{ material = skin, initial_strain = es, spacing = 0.5 * h,
    curve = lamina.segment{ from = {0, y0}, to = {L, y0} } }
  sim:step()
  local sigma = s:hoop_stress()
  fact("sigma", sigma)
  fact("thickness", t)
  local common = { width = 320, height = 240, window = {-0.05, 0.3, 1.05, 0.7}, grid = false,
                   label = false, normals = false, phi = false, colour = "tension",
                   particles = "membranes" }
  local function frame(name, extra)
    local o = { file = out .. "/" .. name .. ".png" }
    for k, v in pairs(common) do o[k] = v end
    for k, v in pairs(extra) do o[k] = v end
    sim:frame(o)
  end
  frame("tension_auto", {})
  frame("tension_sigma_t", { range = { -sigma * t, sigma * t } })
  frame("tension_sigma", { range = { -sigma, sigma } })
end

-- 3. pressure --------------------------------------------------------------
do
  local sim = lamina.sim{ dt = 1e-5, cell = 0.05, domain = {0, 0, 1, 1} }
  local gas = sim:body{ material = lamina.gas{ rho = 1, p = 10 }, ppc = 4, name = "gas",
                        region = lamina.disk{ center = {0.5, 0.5}, radius = 0.3 } }
  local mem = sim:membrane{ material = skin, initial_strain = e0, count = 120, name = "skin",
                            curve = lamina.arc{ center = {0.5, 0.5}, radius = 0.32, from = 0, to = 360 } }
  fact("gas_pressure", gas:pressure("particles"))
  fact("membrane_stress", mem:hoop_stress())
  local common = { width = 320, height = 320, grid = false, label = false, normals = false,
                   phi = false, colourbar = false }
  local function frame(name, extra)
    local o = { file = out .. "/" .. name .. ".png" }
    for k, v in pairs(common) do o[k] = v end
    for k, v in pairs(extra) do o[k] = v end
    sim:frame(o)
  end
  frame("gas_body", {})
  frame("gas_pressure", { colour = "pressure" })
  frame("gas_pressure_old", { colour = "pressure", colourmap = "rdbu", colour_bodies = { gas, mem } })
end
print("frame_scenes: written")
