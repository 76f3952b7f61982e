-- sim:frame{phi = true} and membrane:phi(x, y) (issue 16 item 1): the
-- circular membrane of V6 after 5 steps, for every normals method with a
-- phi - "isosurface", "hybrid", "linear", "mass_matrix",
-- "mass_matrix_quadratic" ([T] §7.7) and
-- "connectivity" (drawn with the isosurface construction on its points).
-- The phi drawn is the construction's own, element by element
-- (lm_membrane_phi: the same points and random points as the step's fit),
-- and membrane:phi reads the same values: at the membrane points it must
-- be 1 up to the least-squares residual ([N] eq 10: rows phi = 1 at the
-- points), and it must fall off the membrane (below 1 a tenth of a cell
-- inside, toward the gas's phi = 0 side, for the fits oriented that way, or
-- at least differ from 1 there). The colour-function methods have no phi:
-- asking for it is an error naming the membrane.
local cm = require("circle_membrane")
local out = "out/frame_phi"
local tol = { isosurface = 0.02, hybrid = 0.05, linear = 0.1, mass_matrix = 0.1,
              mass_matrix_quadratic = 0.05, connectivity = 0.02 }
for _, method in ipairs{"isosurface", "hybrid", "linear", "mass_matrix", "mass_matrix_quadratic",
                        "connectivity"} do
  local sim, gas, mem = cm.setup{normals = method}
  sim:step(5)
  local q = mem:particles()
  local worst, off, n = 0, 0, 0
  for i = 3, q.n - 2 do
    local v = mem:phi(q.x[i], q.y[i])
    if v then
      worst = math.max(worst, math.abs(v - 1))
      local r = math.sqrt(q.x[i]^2 + q.y[i]^2)
      local w = mem:phi(q.x[i] * (1 - 0.01 / r), q.y[i] * (1 - 0.01 / r))
      if w then off, n = off + math.abs(w - 1), n + 1 end
    end
  end
  print(string.format("%-12s: |phi - 1| at the points <= %.2e; mean |phi - 1| 0.01 inside %.3f",
                      method, worst, off / math.max(n, 1)))
  assert(worst <= tol[method], method .. ": phi at the membrane points is not 1")
  assert(n > 0 and off / n > 10 * worst, method .. ": phi does not vary across the membrane")
  sim:frame{file = string.format("%s/%s.png", out, method), width = 300, height = 300,
            phi = true, normals = true, particles = "membranes", window = {0, 0, 0.7, 0.7}}
end
local sim = cm.setup{normals = "colour"}
sim:step(1)
local ok, err = pcall(sim.frame, sim, {file = out .. "/colour.png", phi = true})
assert(not ok and err:find("has no phi"), "colour normals: " .. tostring(err))
print("colour: refused: " .. err:match("phi of membrane[^\n]*"))
