-- Issue 30 item 5, one particle a cell: tests/physics/gas_pressure_space.lua's
-- check at ppc = 1. EXPECTED TO FAIL (tests/CMakeLists.txt, WILL_FAIL):
-- measured gas:pressure() +0.94 % (left, 66 nodes) and +2.98 % (right, 43
-- nodes) from the space's pressure; dp R / T 0.929 with gas:pressure()'s values (0.944
-- with the space's);
-- the particle mean is -34 % / -10 %. With one particle a cell the gas
-- stands apart from the membrane by half a cell and clumps, leaving cells
-- empty: the nodes wholly in the gas read its bulk, the space's mean counts
-- the gap beside the membrane; neither balances the arc within 1 %.
local arc = require("gas_arc")
for _, ppc in ipairs{1} do
  local sim, left, right, mem, t = arc.setup{ ppc = ppc }
  sim:run{ t_end = 0.3 }
  local sL, sR = arc.space_pressures(left, right, mem)
  local gL, nL = left:pressure()
  local gR, nR = right:pressure()
  local pL, pR = left:pressure("particles"), right:pressure("particles")
  local R, T = arc.radius(mem), mem:hoop_stress() * t
  local ratio = (gL - gR) * R / T
  print(string.format("ppc %2d: space %.2f | %.2f; gas:pressure() %.2f (%d nodes) %+.3f %% | "
    .. "%.2f (%d nodes) %+.3f %%; particle mean %+.2f %% | %+.2f %%; dp R / T %.4f", ppc, sL, sR,
    gL, nL, 100 * (gL / sL - 1), gR, nR, 100 * (gR / sR - 1), 100 * (pL / sL - 1),
    100 * (pR / sR - 1), ratio))
  assert(nL > 20 and nR > 20, "too few nodes wholly in the gas")
  assert(math.abs(gL / sL - 1) < 0.01, "left gas: gas:pressure() not within 1 % of the space's")
  assert(math.abs(gR / sR - 1) < 0.01, "right gas: gas:pressure() not within 1 % of the space's")
  assert(math.abs(ratio - 1) < 0.02, "T = dp R: " .. ratio)
end
