-- title: The expanding cylinder at t = 0.01: the two unsuccessful normals methods
-- source: York's dissertation [T] §7.5.2, Fig 74
-- look: points and normals at t = 0.01, (a) the cubic method, (b) the
--   quadratic: both membranes far out of the circle they started on and
--   past all the connectivity run reaches (it rings about delta r = 0.009),
--   the quadratic's normals scattered, the cubic's following its kinked
--   outline ([T]: "the material point positions and normals ... for the two
--   unsuccessful methods"); the
--   cubic's drawn on its whole circle's first quadrant, its gas points small
--   (a clipped first point sets the disc size). The simple colour function
--   beside them (not in [T]'s figure) does as the quadratic
-- checks: [T]'s "unsuccessful" as a number (ours): the connectivity run's
--   largest delta r up to t = 0.01 (the successful method; [T]'s mean of the
--   points at 0, 45 and 90 degrees) over each method's delta r at t = 0.01,
--   below 1 (0.5 +- 0.5, as the ratios of normals_cylinder_expansion, whose
--   runs to t = 0.05 these are: Fig 73's curves and Fig 75). Printed beside:
--   the largest angle between each membrane's normals and the line joining
--   its points' neighbours (the connectivity normal; the ends left out)
-- assumed: the scene of normals_cylinder_expansion (assets/lua/
--   cylinder_expansion.lua; [T] gives no parameters): radius 1.0, walls at
--   x, y = 1.5, gas rho 1, p0 1000, gamma 1.4, mu 0.2, 16 ppc, membrane rho
--   0.5, E 1e6, nu 0.3, t 0.1 plane stress, point forces, cell 0.1, linear
--   basis, dt 2e-5. The quadratic (and simple colour) on the quarter with the
--   colour on the membrane's points alone; the cubic method (its equations
--   7.6-7.7 lost, read as the cubic B-spline on the 16 vertices about each
--   point, normals = "cubic_colour") on the whole circle as [T] ran it ("the
--   boundary conditions for the cubic gradient were not implemented"), 720
--   points, the colour carried on the gas's points too ([T] §7.5's "with the
--   internal fluid")
-- thumb: 74_cubic_colour_t0.010.png
local out = lamina.param("out", "out/normals_cylinder_expansion_fig74")
local t_end = lamina.param("t_end", 0.01)

local C = require("cylinder_expansion")
local ends = require("circle_membrane")

local methods = {
  { key = "connectivity", label = "connectivity" },
  { key = "cubic_colour", label = "cubic", whole = true, gas_colour = true, fig = "Fig 74(a)" },
  { key = "quadratic_colour", label = "quadratic colour", fig = "Fig 74(b)" },
  { key = "colour", label = "simple colour", fig = "not in Fig 74" },
}
local runs, hashes = {}, {}
for _, m in ipairs(methods) do
  local sim, _, mem = C.setup{ normals = m.key, whole = m.whole, gas_colour = m.gas_colour }
  local rec = sim:record{ every = 2.5e-4, values = { dr = function() return C.dr3(mem) end } }
  if m.fig then
    sim:at(t_end, function(s)
      s:frame{ file = string.format("%s/74_%s_t%.3f.png", out, m.key, t_end), width = 420,
               height = 440, window = {0, 0, 1.5, 1.5}, discs = "spacing",
               title = string.format("%s: %s, t = %.2f", m.fig, m.label, t_end) }
    end)
  end
  sim:run{ t_end = t_end }
  local dr = rec:column("dr")
  local top = 0
  for i = 1, #dr do top = math.max(top, dr[i]) end
  runs[m.key] = { at_end = dr[#dr], top = top, scatter = ends.worst_connectivity_error(mem) }
  hashes[#hashes + 1] = sim:hash()
end

local conn = runs.connectivity.top
print(string.format("delta r at t = %g: connectivity's largest %.4f (the equilibrium %.4f); cubic %.4f, "
  .. "quadratic %.4f, simple colour %.4f; largest angle from the connectivity normal: cubic %.1f, "
  .. "quadratic %.1f, simple colour %.1f deg", t_end, conn, C.equilibrium(), runs.cubic_colour.at_end,
  runs.quadratic_colour.at_end, runs.colour.at_end, runs.cubic_colour.scatter,
  runs.quadratic_colour.scatter, runs.colour.scatter))
local h64 = 0xcbf29ce484222325
for _, c in ipairs(hashes) do for i = 1, #c do h64 = (h64 ~ c:byte(i)) * 0x100000001b3 end end
lamina.report{
  cubic_unsuccessful = { conn / runs.cubic_colour.at_end, ref = 0.5, tol = 0.5,
                         unit = "(the connectivity run's largest delta r over the cubic's at t = 0.01; "
                                .. "[T] Fig 74 'unsuccessful': below 1)" },
  quadratic_unsuccessful = { conn / runs.quadratic_colour.at_end, ref = 0.5, tol = 0.5,
                             unit = "(the same for the quadratic; [T] Fig 74 'unsuccessful': below 1)" },
  colour_unsuccessful = { conn / runs.colour.at_end, unit = "(the same for the simple colour, not in [T]'s figure)" },
  cubic_normal_scatter = { runs.cubic_colour.scatter,
                           unit = "deg, largest angle from the connectivity normal (whole circle)" },
  quadratic_normal_scatter = { runs.quadratic_colour.scatter, unit = "deg, the same" },
  colour_normal_scatter = { runs.colour.scatter, unit = "deg, the same" },
  state_hash = string.format("%016x", h64),
}
