-- dogbone_means.lua - the dog-bone pages' end-of-run numbers from their
-- record (columns t, p, pp, hoop, r0, r90, total, kinetic, gk): the means
-- over the last time unit ([T] Table 5's "final" values read as the
-- settled state), p r / t with r the mean of the radii at 0 and 90 degrees
-- ([T] Table 6), and the energy seen two ways: the particles' total, and
-- the total as the grid sees it (the particles' kinetic energy replaced by
-- the grid's: FLIP's hidden velocity left out; [T] §6.2's loss).
-- Shared by assets/lua/dogbone_box9_page.lua and gas_dogbone_superellipse.
local M = {}

-- rec: the run's sim:record; thickness: the membrane's. Returns a table:
-- p, pp, hoop, r0, r90 (means over [t0, t_end], t0 = t_end - 1 or 0), prt, pprt (p r / t
-- by the two pressures), tot, ke, gk, n (the columns), dE (particles' total,
-- relative), vis (the grid's view, per row), loss (its relative fall),
-- hidden (kinetic energy the grid does not see at the end).
function M.at_end(rec, t_end, thickness)
  local e = {}
  local t0 = math.max(0, t_end - 1)
  e.t0 = t0
  e.p, e.hoop = rec:mean("p", t0, t_end), rec:mean("hoop", t0, t_end)
  e.pp = rec:mean("pp", t0, t_end)
  e.r0, e.r90 = rec:mean("r0", t0, t_end), rec:mean("r90", t0, t_end)
  e.prt = e.p * 0.5 * (e.r0 + e.r90) / thickness
  e.pprt = e.pp * 0.5 * (e.r0 + e.r90) / thickness
  e.tot, e.ke, e.gk = rec:column("total"), rec:column("kinetic"), rec:column("gk")
  local tot, ke, gk, n = e.tot, e.ke, e.gk, #e.tot
  e.n = n
  e.dE = (tot[n] - tot[1]) / tot[1]
  e.vis = {}
  for i = 1, n do e.vis[i] = tot[i] - ke[i] + gk[i] end
  e.loss, e.hidden = (e.vis[1] - e.vis[n]) / e.vis[1], ke[n] - gk[n]
  return e
end

return M
