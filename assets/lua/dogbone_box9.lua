-- dogbone_box9.lua - the dog-bone as the dissertation ran it: [T] Appendix
-- A.4.7, Box 9 ("Input for Membrane Expansion Simulation 4"), read as
-- exactly as the text allows ([T] §6.2, Fig 47, Tables 4-6; docs/physics.md
-- V7). lamina's earlier construction (a superellipse lobe and neck) stays
-- in assets/lua/dogbone.lua.
--
-- What the deck says, and how each entry is read here ([T] A.4 has no
-- description of the format: the meaning comes from the other boxes and the
-- text; every choice is marked CHOICE):
--   $in nx = 33, ny = 33, xleft = 0, xright = 1.6, ybot = 0, ytop = 1.6:
--     33 x 33 nodes on 1.6 x 1.6, cell h = 1.6 / 32 = 0.05 ([T] Table 5's
--     simulation 4).
--   tmax = 8.500014, tstep = dtmax = 0.35e-4: dt = 3.5e-5 to t = 8.5.
--     CHOICE (other cells): dt = 0.35e-4 * h / 0.05 = 7e-4 h, the deck's
--     Courant number at every cell. That number is dt c / h = 1.04 for
--     lamina's plane-stress membrane wave c = sqrt(E / ((1 - nu^2) rho))
--     (0.99 for the uniaxial sqrt(E / rho)): above lamina's default limit
--     of 1, so the simulation sets courant = 1.05 (MUSL's bar is stable to
--     2.15 h / c, [T] Ch. 8; docs/api.md `courant`).
--   wl = 4, wb = 4, wr = 1, wt = 1: the codes are not explained. Read from
--     the other boxes: 0 holds (the pendulum's pivot wall, Box 6 wt = 0; the
--     piston tube's ends, Box 12), 1 lets material slide (the piston tube's
--     side walls, Box 12 wl = wr = 1), 4 (and 6 in Boxes 1-2) are the
--     quarter model's symmetry lines. CHOICE: left and bottom "symmetry",
--     right and top "symmetry" too (a roller; nothing reaches them: the
--     membrane settles at r ~ 1.4 < 1.6).
--   $fluid mu = 0.10, gm1 = .4, siep = 0.25d3, lambda = coef1 = coef2 = 0:
--     viscosity 0.1 ([T] Table 4; [F] Table II says 0.2), gamma = 1.4,
--     e = 250 (p0 = 0.4 * 1 * 250 = 100, Fig 47's "Pi = 100"), artificial
--     viscosity off.
--   $reg nreg = 2: the gas as two quadrilaterals,
--     (0, 0) (0.426, 0) (0.426, 0.9) (0, 0.95) and
--     (0.426, 0.65) (0.9, 0.65) (0.9, 0.74) (0.426, 0.9):
--     areas 0.39405 + 0.08058 = 0.47463 (the "0.475" of issue 16).
--     xcenter / rix / rex (0 / 2000) only bound the regions (no effect).
--   nprg = 64, 64: material points per cell ([T] Table 5 note a, "Material
--     points per cell", 64 for the fluid), seeded at the centres of an 8 x 8
--     grid of sub-cells inside each region (lamina's fill = "centres"). The
--     seeded gas area is what the points carry: 0.49000 / 0.47313 /
--     0.47359 / 0.47395 at cells 0.4 / 0.2 / 0.1 / 0.05.
--   densir = 1: gas density 1.
--   The membrane, the deck's second file (format of Boxes 4, 5, 7 and 13:
--   density / material constants / constitutive path / "no. particles in
--   the sequence" / "total no. particles, no. per cell" / one line per
--   point: x, y and five zero fields):
--     0.5                         membrane density 0.5 ([T] Table 4)
--     1.0d6, 0.300d0, 10.d25, 2.d25, 1.0d25, 1.d2, 0.d0
--                                 E = 1e6, nu = 0.3 (the rest as in every
--                                 membrane deck; no thickness among them)
--     3,3,3,8                     the membrane law (8), as Boxes 4, 5, 7
--     600                         600 points in the sequence
--     600, 6.8207                 600 points in all, np2 = 6.8207 "per cell"
--     0.4999900.0011100.00.00.00.00.0
--                                 fixed width (F8.6, F8.6, 5 F3.1): the
--                                 first point (0.499990, 0.001110), at rest,
--                                 no initial stress; the other 599 lines are
--                                 not printed.
--   np2 is not a length: the spring-mass deck (Box 4: density 0.1, cell
--   0.1 x 0.1, "10,3 !total no. particles, no. per cell") gives points of
--   0.1 * 0.01 / 3 = 3.33e-4, [T] §5.5's "3.33 ... 10,000 times the mass of
--   the other material points". So a membrane point weighs
--   rho h^2 / np2 = 0.5 * 0.05^2 / 6.8207 = 1.8326e-4 and stands for the
--   area h^2 / np2 = 3.6653e-4 = thickness * ds. The 600 points weigh
--   0.10996; with the seeded gas 0.47395 the total is 0.58391: [T] Table 5's
--   0.584 (at cell 0.4 the same membrane and the seeded gas 0.49000 give
--   0.59996, Table 5's 0.600; at 0.2 and 0.1, 0.58309 and 0.58355 against
--   Table 5's 0.584 and 0.583: the last digit swapped).
--   Thickness: not in the deck. [T] Table 6 note a and [F] Table IV: "with
--   thickness equal to 0.1". Then each point stands for
--   ds = 3.6653e-4 / 0.1 = 3.6653e-3 of membrane and the 600 points for
--   600 ds = 2.1992: the quarter circle of radius 1.400, i.e. [T] Table 5's
--   final radius 1.394 / 1.396 for a membrane that barely stretches (hoop
--   stress ~400 / E = 1e6). The deck gives the points no initial stress:
--   the line is stress-free as placed, so its geometric length is its
--   natural length, 2.2, the same as its material.
--   The curve of the 599 points not printed. The text gives: the first
--   point (0.49999, 0.00111), i.e. x = 0.5 nudged 1e-5 off the grid line
--   x = 10 h; Fig 47's labels "x = 0.5" (the membrane at 0 degrees) and
--   "y = 1" (at 90 degrees); a dog-bone that holds the two gas quadrilaterals;
--   and (above) a length of 2.2. CHOICE: the gas's outline stood off outward,
--   straight edges meeting at corners:
--     neck   x = 0.49999 (the first point's x; the gas edge x = 0.426,
--            standoff 0.074),
--     knob   y = 0.65 - d, x = 0.9 + d and the slanted edge parallel to the
--            gas's (0.9, 0.74)-(0.426, 0.9), each a distance d outside it,
--     top    the line through (0, 1) parallel to the gas's top edge
--            (0.426, 0.9)-(0, 0.95) (standoff 0.0497),
--   with d solved so that the points lie at the deck's spacing ds: the
--   first at the deck's (0.49999, 0.00111), the 600th the same 0.00111 of
--   arc short of (0, 1), 599 ds between them (outline length
--   599 ds + 0.00222 = 2.1977): d = 0.0463 (d = 0.05, the top's standoff,
--   would make it 0.4 % longer). Corners are sharp (the deck's
--   points are read from a file; nothing says they were rounded).
--   The 400 membrane points [T] Table 5 lists for simulation 4 disagree with
--   the deck's 600; with np2 = 6.8207, 400 points would weigh 0.0733 and
--   the total 0.547, not 0.584, so the deck's 600 is used. The decks of
--   simulations 1-3 (56 / 100 / 200 points) are not given; CHOICE: the same
--   600-point membrane at every cell (Table 5's total masses 0.600 and
--   0.584 at cells 0.4 and 0.05 come out of it), only the grid and dt
--   change.
--   Membrane law: [T] Table 4, "wrinkle algorithm on" (lamina's one_way);
--   plane stress with nu = 0.3 (lamina's plane_stress law: [T] §5 membrane
--   in the x-y plane, 2D plane stress in the normal-tangent frame).
local M = {}

-- The deck's numbers ([T] Box 9)
M.deck = { nx = 33, ny = 33, width = 1.6, cell = 0.05, dt = 0.35e-4, t_max = 8.5,
           mu = 0.1, gamma = 1.4, e = 250, rho_gas = 1, nprg = 64,
           rho_membrane = 0.5, E = 1e6, nu = 0.3, points = 600, np2 = 6.8207,
           first = { 0.49999, 0.00111 },
           thickness = 0.1 }   -- [T] Table 6 note a (not in the deck)

M.gas_polygons = {
  { {0, 0}, {0.426, 0}, {0.426, 0.9}, {0, 0.95} },
  { {0.426, 0.65}, {0.9, 0.65}, {0.9, 0.74}, {0.426, 0.9} },
}

local function shoelace(p)
  local a = 0
  for i = 1, #p do
    local q, r = p[i], p[i % #p + 1]
    a = a + q[1] * r[2] - r[1] * q[2]
  end
  return 0.5 * math.abs(a)
end

-- The gas regions' area (exact polygons): 0.47463.
function M.gas_area()
  local a = 0
  for _, p in ipairs(M.gas_polygons) do a = a + shoelace(p) end
  return a
end

-- A membrane point's mass rho h^2 / np2 at the deck's cell, its share of
-- membrane ds = h^2 / (np2 t), and the membrane's mass.
function M.point_mass() local d = M.deck; return d.rho_membrane * d.cell ^ 2 / d.np2 end
function M.point_ds() local d = M.deck; return d.cell ^ 2 / (d.np2 * d.thickness) end
function M.membrane_mass() return M.deck.points * M.point_mass() end

local function intersect(p, u, q, v)
  -- p + s u = q + r v
  local det = u[1] * (-v[2]) - u[2] * (-v[1])
  local rx, ry = q[1] - p[1], q[2] - p[2]
  local s = (rx * (-v[2]) - ry * (-v[1])) / det
  return { p[1] + s * u[1], p[2] + s * u[2] }
end

-- The outline (corners) with knob standoff d, from the 0-degree axis to the
-- 90-degree axis.
function M.outline(d)
  local x0 = M.deck.first[1]
  local su = { 0.426 - 0.9, 0.9 - 0.74 }                      -- gas's slanted edge
  local n = math.sqrt(su[1] ^ 2 + su[2] ^ 2)
  local sn = { su[2] / n, -su[1] / n }                         -- its outward normal
  if sn[1] < 0 then sn = { -sn[1], -sn[2] } end
  local sp = { 0.9 + d * sn[1], 0.74 + d * sn[2] }
  local c3 = intersect({ 0.9 + d, 0 }, { 0, 1 }, sp, su)
  local c4 = intersect(sp, su, { 0, 1 }, { -0.426, 0.05 })
  return { { x0, 0 }, { x0, 0.65 - d }, { 0.9 + d, 0.65 - d }, c3, c4, { 0, 1 } }
end

function M.length(pts)
  local l = 0
  for i = 2, #pts do
    l = l + math.sqrt((pts[i][1] - pts[i - 1][1]) ^ 2 + (pts[i][2] - pts[i - 1][2]) ^ 2)
  end
  return l
end

-- The end gap: the first point's arc distance from the 0-degree axis.
M.gap = M.deck.first[2]

-- d such that the outline is 599 ds + 2 gap long (bisection).
function M.standoff()
  local want = (M.deck.points - 1) * M.point_ds() + 2 * M.gap
  local lo, hi = 0, 0.2
  for _ = 1, 80 do
    local mid = 0.5 * (lo + hi)
    if M.length(M.outline(mid)) < want then lo = mid else hi = mid end
  end
  return 0.5 * (lo + hi)
end

-- The membrane curve: the outline from arc length gap to length - gap (the
-- first and the 600th point are its ends).
function M.polyline()
  local o = M.outline(M.standoff())
  local total = M.length(o)
  local function at(s)
    local acc = 0
    for i = 2, #o do
      local a, b = o[i - 1], o[i]
      local l = math.sqrt((b[1] - a[1]) ^ 2 + (b[2] - a[2]) ^ 2)
      if s <= acc + l or i == #o then
        local f = (s - acc) / l
        return { a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2]) }, i
      end
      acc = acc + l
    end
  end
  local first, i1 = at(M.gap)
  local last, i2 = at(total - M.gap)
  local pts = { first }
  for i = i1, i2 - 1 do pts[#pts + 1] = o[i] end
  pts[#pts + 1] = last
  return pts
end

-- Inside the gas (either quadrilateral).
local regions
function M.contains(x, y)
  if not regions then
    regions = {}
    for i, p in ipairs(M.gas_polygons) do regions[i] = lamina.polygon{ points = p } end
  end
  return regions[1]:contains(x, y) or regions[2]:contains(x, y)
end

-- The radius at 0 or 90 degrees: the deck's end points lie 0.00111 off the
-- axes, so the ray along an axis meets no segment (membrane:radius_at gives
-- nil); the radius there is the end point's distance from the centre (its
-- angle from the axis is under 0.1 degree), the material point location
-- [T] §6.2 says its radii are based on.
function M.radius(mem, deg)
  local p = mem:particles()
  local i = deg == 0 and 1 or #mem
  return math.sqrt(p.x[i] ^ 2 + p.y[i] ^ 2)
end

-- The record values the measure scripts follow (scripts/measure/dogbone_*):
-- the enclosed gas's pressure, the hoop stress and the radii at 0 and 90
-- degrees, for sim:record{values = ...}.
-- For the measure scripts: the bodies' total mass, and a body's largest
-- point speed.
function M.total_mass(bodies)
  local mass = 0
  for _, body in ipairs(bodies) do
    local mm = body:particles().mass
    for i = 1, #body do mass = mass + mm[i] end
  end
  return mass
end
function M.max_speed(body)
  local g = body:particles()
  local v = 0
  for q = 1, #body do v = math.max(v, g.vx[q] ^ 2 + g.vy[q] ^ 2) end
  return math.sqrt(v)
end

-- The page's numbers as the measure scripts report them
-- (scripts/measure/dogbone_*.lua): the means of M.history_values' columns over
-- the run's last time unit [t1 - 1, t1], p r / t from them, printed with the
-- mass and the total energy at the start and end; returns r0, r90, p, hoop,
-- prt, t1.
function M.last_unit(rec, t1, mass)
  local t0 = math.max(0, t1 - 1)
  local r0, r90, p, hoop = rec:mean("r0", t0, t1), rec:mean("r90", t0, t1), rec:mean("p", t0, t1),
                           rec:mean("hoop", t0, t1)
  local prt = p * 0.5 * (r0 + r90) / M.deck.thickness
  local tot = rec:column("total")
  print(string.format("  over [%.2f, %.2f]: r(0) %.4f r(90) %.4f pressure %.3f hoop %.1f vs p r / t %.1f (%+.2f %%) "
    .. "mass %.5f energy %.3f -> %.3f", t0, t1, r0, r90, p, hoop, prt, 100 * (hoop - prt) / prt, mass, tot[1],
    tot[#tot]))
  return r0, r90, p, hoop, prt, t1
end

function M.history_values(gas, mem)
  return { p = function() return gas:pressure(mem) end,
           hoop = function() return mem:hoop_stress() end,
           r0 = function() return M.radius(mem, 0) end,
           r90 = function() return M.radius(mem, 90) end }
end

-- dt at cell h: the deck's Courant number (dt = 0.35e-4 at h = 0.05).
function M.dt(h) return M.deck.dt * h / M.deck.cell end

-- The expansion problem at cell h. o: normals (default "connectivity",
-- oriented away from the origin), pic (default 0), split (gas splitting),
-- threads, density (lamina.gas{density}), basis, force (sim:membrane{force},
-- default "point"), count (membrane points, default the deck's 600),
-- multirate (the gas's step m x the deck's dt with sub-steps, below).
-- Returns sim, gas, membrane.
function M.setup(h, o)
  o = o or {}
  local d = M.deck
  -- o.substeps = k: multi-rate stepping (docs/api.md `substeps`), the gas
  -- stepping k times the deck's dt and the membrane k sub-steps of it
  local k = o.substeps
  -- o.multirate = m (> 1): the gas at m x the deck's dt, the membrane in the
  -- fewest sub-steps within its Courant limit, the impulse form, and a gas
  -- point's viscosity at most 0.25 rho h^2 / dt (lamina.sim{substeps = "auto",
  -- multirate = "impulse", viscous_limit = 0.25}: what carries this deck's
  -- MUSL step past a rarefied gas point's explicit viscous limit,
  -- docs/performance.md "The gas's step beside a membrane"); nil or 1: the
  -- plain step, every hash as before
  local m = o.multirate and o.multirate > 1 and o.multirate or nil
  local sim = lamina.sim{ domain = {0, 0, d.width, d.width}, cell = h, dt = M.dt(h) * (k or m or 1),
                          courant = 1.05,   -- the deck's dt c / h = 1.04 (above)
                          boundary = { left = "symmetry", bottom = "symmetry",
                                       right = "symmetry", top = "symmetry" },
                          pic = o.pic or 0, threads = o.threads,
                          basis = o.basis or "linear", substeps = k or (m and "auto"),
                          multirate = m and "impulse", viscous_limit = m and 0.25 }
  local air = lamina.gas{ rho = d.rho_gas, e = d.e, gamma = d.gamma, mu = d.mu, split = o.split,
                          density = o.density }
  local skin = lamina.membrane{ rho = d.rho_membrane, E = d.E, nu = d.nu, thickness = d.thickness,
                                law = "plane_stress", one_way = true }
  local gas = sim:body{ material = air, ppc = d.nprg, region = M.contains, name = "gas" }
  local mem = sim:membrane{ material = skin, name = "membrane", count = o.count or d.points,
                            normals = o.normals or "connectivity", orient = {0, 0},
                            force = o.force or "point",
                            curve = lamina.polyline(M.polyline()) }
  return sim, gas, mem
end

return M
