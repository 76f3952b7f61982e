-- A ringing elastic disk flying across the grid keeps its energy with the
-- smooth bases (the default quadratic B-spline, and uGIMP): nothing in the
-- model makes energy, so the total at every sample stays within 1 % of its
-- start (MUSL and FLIP lose a little; they must not gain). The bilinear
-- basis fails this badly (the total grows threefold in 1 s here: the
-- cell-crossing noise of its kinked hats does work on the vibration,
-- docs/robustness.md "Energy growth of a moving body on the bilinear
-- basis"); that run is tests/bad/energy_growth_linear.lua, which checks
-- that lamina says so.
local function run(basis)
  local sim = lamina.sim{ basis = basis, domain = {0, 0, 10, 10}, cell = 0.0625, dt = 2.5e-4 }
  local mat = lamina.elastic{ rho = 1, E = 1e4, nu = 0.3, plane = "stress" }
  -- speed 3 to the left, and a compression wave to ring: v_x += 0.5 (x - x0) / r
  local disk = sim:body{ material = mat, ppc = 4, name = "disk",
                         velocity = function(x, _) return -3 + 0.5 * (x - 8.5) / 0.75, 0 end,
                         region = lamina.disk{ center = {8.5, 5}, radius = 0.75 } }
  local e0 = sim:energy().total
  local lo, hi = 1, 1
  sim:every(0.05, function(s)
    local r = s:energy().total / e0
    lo, hi = math.min(lo, r), math.max(hi, r)
  end)
  sim:run{ t_end = 1 }
  print(string.format("%-8s E/E0 between %.5f and %.5f; the disk at x = %.3f", basis, lo, hi,
                      (disk:com())))
  return lo, hi
end
for _, basis in ipairs{ "bspline2", "gimp" } do
  local lo, hi = run(basis)
  assert(hi <= 1.01, basis .. ": the energy grew to " .. hi .. " of its start")
  assert(lo >= 0.99, basis .. ": the energy fell to " .. lo .. " of its start")
end
