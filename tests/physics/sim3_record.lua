-- sim:record in 3D (issue 34 item 1): a ball falling onto the floor,
-- recorded every 2e-3 s (t, step, the energies and a value function), the
-- CSV written at the end of each run call. Checks: the rows are the
-- samples' times (one every 2e-3 to t = 0.1, sampled as in 2D: at the step
-- boundaries, half a step of tolerance); each recorded energy equals
-- sim:energy() taken in a sim:every callback at the same steps (the same
-- sums: exactly); the value column equals body:com()'s z there; the CSV
-- read back (lamina.read_csv) equals rec:column to its 10 printed digits;
-- and 2D-only columns are refused by name.
local out = lamina.param("out", "out/sim3_record/ball.csv")
local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, 0.4, 0.4, 0.4}, cell = 0.04, dt = 1e-3,
                        gravity = {0, 0, -9.81}, boundary = { z1 = "free" } }
local ball = sim:body{ material = lamina.elastic{ rho = 1000, E = 2e4, nu = 0.3 },
                       region = lamina.ball{ center = {0.2, 0.2, 0.15}, radius = 0.08 } }
local rec = sim:record{ file = out, every = 2e-3, energy = true,
                        values = { zc = function(s) local _, _, z = ball:com() return z end } }
local seen = {}
sim:every(2e-3, function(s)
  local e = s:energy()
  local _, _, z = ball:com()
  seen[#seen + 1] = {s.t, s.nstep, e.kinetic, e.strain, e.potential, e.total, z}
end)
sim:run{ t_end = 0.05 }
sim:run{ t_end = 0.1 }
local cols = rec:columns()
assert(table.concat(cols, ",") == "t,step,kinetic,strain,internal,potential,total,zc",
       "columns: " .. table.concat(cols, ","))
assert(#rec == 51 and #seen == 51, "rows: " .. #rec .. " recorded, " .. #seen .. " seen")
local names = {"t", "step", "kinetic", "strain", "potential", "total", "zc"}
local worst = 0
for k, name in ipairs(names) do
  local c = rec:column(name)
  for i = 1, #c do
    assert(c[i] == seen[i][k], string.format("%s at row %d: %.17g recorded, %.17g seen", name, i,
                                             c[i], seen[i][k]))
  end
end
local csv = lamina.read_csv(out)
for _, name in ipairs(names) do
  local c = rec:column(name)
  for i = 1, #c do
    worst = math.max(worst, math.abs(csv[name][i] - c[i]) / math.max(1e-300, math.abs(c[i])))
  end
end
assert(worst <= 1e-9, "the CSV differs from the record by " .. worst)
local e = rec:column("total")
print(string.format("%d rows to t = %.3f; total energy %.6g -> %.6g J (kinetic at the end %.4g); "
  .. "CSV read back to %.2g relative", #rec, sim.t, e[1], e[#e], rec:column("kinetic")[#e], worst))
local ok, err = pcall(sim.record, sim, { points = { a = {ball, 1} } })
assert(not ok and err:find("'points' is not available for a 3D simulation", 1, true), err)
