-- title: Two disks meet (a demo figure for the gallery machinery)
-- source: after Sulsky, Chen & Schreyer 1994, the two-disk impact; a test
--   scene of lamina's own, not a reproduction of a paper's figure
-- look: the disks approach along the diagonal and flatten where they touch;
--   the single tracer particle near the top-left corner stays where it is
--   (the negative control moves it by one particle spacing)
-- checks: total momentum stays zero to round-off; total energy stays within
--   10 % of its start while the disks are in contact
-- assumed: E = 1000, rho = 1000, nu = 0.3 (plane strain) as in the example;
--   the disks are smaller than the example's so that they meet sooner
-- visual: t_end=0.6
--
-- tests/visual/CMakeLists.txt renders this into a temporary gallery
-- (lamina gallery --scripts tests/visual/scenes) and compares its thumbnail
-- with tests/visual/baselines/scenes/demo.png.
local out       = lamina.param("out", "out/demo")
local t_end     = lamina.param("t_end", 0.7)
local tracer_dx = lamina.param("tracer_dx", 0)   -- negative control: a changed simulation
local title     = lamina.param("title", "two disks meet")   -- ... a changed drawing

local cell = 0.05
local sim = lamina.sim{ basis = "linear", domain = {0, 0, 1, 1}, cell = cell, dt = 1e-3 }
local rubber = lamina.elastic{ rho = 1000, E = 1000, nu = 0.3, plane = "strain" }
sim:body{ material = rubber, ppc = 4, velocity = { 0.15,  0.15}, name = "lower",
          region = lamina.disk{ center = {0.32, 0.32}, radius = 0.15 } }
sim:body{ material = rubber, ppc = 4, velocity = {-0.15, -0.15}, name = "upper",
          region = lamina.disk{ center = {0.68, 0.68}, radius = 0.15 } }
-- exactly one particle: a tiny disk around one sub-cell centre (2x2 per cell)
sim:body{ material = rubber, ppc = 4, name = "tracer",
          region = lamina.disk{ center = {2.25 * cell + tracer_dx, 17.75 * cell},
                                radius = 0.1 * cell } }

local e0 = sim:energy().total
local worst = 0
sim:every(0.1, function(s)
  worst = math.max(worst, math.abs(s:energy().total - e0) / e0)
  s:frame{ file = string.format("%s/frame_%04d.png", out, s.nstep), width = 320, height = 320,
           title = title }
end)
sim:run{ t_end = t_end }

local px, py = sim:momentum()
lamina.report{
  momentum = { math.sqrt(px * px + py * py), paper = 0, tol = 1e-12, unit = "kg m/s" },
  energy_change = { 100 * worst, paper = 0, tol = 10, unit = "%" },
  particles = sim.n,
  state_hash = sim:hash(),
}
