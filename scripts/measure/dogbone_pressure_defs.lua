-- dogbone_pressure_defs.lua - which "pressure" [T] Table 5 prints (issue 32
-- item 7; bone32). [T] Table 5 note c: "Calculated by averaging the final
-- pressure at interior grid points". Box 9's dog-bone (assets/lua/
-- dogbone_box9.lua, the page gas_dogbone's set-up) is run at each cell to
-- t_end, and at the end the gas pressure is read every way the words allow:
--   encl   gas:pressure(mem): sum V_p p_p / A over the enclosed polygon (the
--          page's; by the partition of unity the mean of the volume-
--          normalised nodal field over the whole space)
--   space  gas:pressure(): the nodal mean over nodes whose support lies
--          wholly in the gas (lamina's reading of note c)
--   part   gas:pressure("particles"): mass-weighted particle mean
--   nodal fields on the run's own basis (bilinear, or the quadratic B-spline
--   at cell 0.05), the gas mirrored across the two symmetry axes so that a
--   node on an axis sees the whole of its support as in the full problem:
--     VN_i = (gamma - 1) sum_p m_p e_p N_ip / h^2   (energy density: what
--            the grid's internal force sees, [F] eq 15 with eq 21)
--     MW_i = sum_p m_p p_p N_ip / sum_p m_p N_ip    (the usual MPM map of a
--            point quantity, mass-weighted; [T] §6.2.4: "pressure ... [is]
--            interpolated to grid points from material points")
--   averaged over the nodes inside the membrane's polygon (closed along the
--   axes) ("in"), or over the nodes with gas mass and no membrane mass
--   ("gasonly"). Also the final energies and the pressure the energy alone
--   implies, 0.4 E_int / A (the whole enclosed space at one pressure).
--   lamina run scripts/measure/dogbone_pressure_defs.lua
--     [--set cells="0.4 0.2 0.1"] [--set t_end=8.5] [--set nodes=1] [--set count=100]
local b = require("dogbone_box9")
local cells = lamina.param("cells", "0.4 0.2 0.1")
local t_end = lamina.param("t_end", 8.5)
local threads = lamina.param("threads", 2)
local out = lamina.param("out", "out/dogbone_pressure_defs")
local count = lamina.param("count", 0)   -- membrane points; 0: the deck's 600 ([T] Table 5: 56 / 100 / 200 / 400)

-- one axis' weights: node index and weight pairs for coordinate x on cell h
-- (gas_nodes.lua's, origin 0)
local gn = require("gas_nodes")
local function weights(x, h, basis)
  return gn.weights(x, 0, h, basis)
end

-- scatter sums a[node] += v * N over the particles and their mirror images
-- across x = 0 and y = 0 (the symmetry walls); keys j * 10000 + i, i, j >= 0
local function scatter(sums, px, py, h, basis, values)
  for sx = -1, 1, 2 do
    for sy = -1, 1, 2 do
      local wx, wy = weights(sx * px, h, basis), weights(sy * py, h, basis)
      for _, a in ipairs(wx) do
        for _, c in ipairs(wy) do
          if a[1] >= 0 and c[1] >= 0 then
            local key, N = c[1] * 10000 + a[1], a[2] * c[2]
            for name, v in pairs(values) do
              local s = sums[name]
              s[key] = (s[key] or 0) + v * N
            end
          end
        end
      end
    end
  end
end

print("cell  basis  t  encl  space(nodes)  part  VN_in(n)  MW_in  VN_gasonly(n)  MW_gasonly  "
      .. "E0  Eint  Ekin  Egk  Estrain  0.4Eint/A  r0 r90")
for hs in cells:gmatch("[%d.]+") do
  local h = tonumber(hs)
  local basis = h < 0.075 and "bspline2" or "linear"
  local sim, gas, mem = b.setup(h, { basis = basis, threads = threads, count = count > 0 and count or nil })
  local rec = sim:record{ every = 0.01, energy = true,
                          file = string.format("%s/energy_cell%.3f.csv", out, h), values = {
    gk = function() return sim:energy().grid_kinetic end,
    encl = function() return gas:pressure(mem) end,
    area = function() return mem:enclosed_area() end } }
  local E0 = sim:energy()
  sim:run{ t_end = t_end }
  local g, m = gas:particles(), mem:particles()
  local sums = { me = {}, m = {}, mp = {}, mm = {} }
  for i = 1, #gas do
    scatter(sums, g.x[i], g.y[i], h, basis, { me = g.mass[i] * g.e[i], m = g.mass[i], mp = g.mass[i] * g.p[i] })
  end
  for i = 1, #mem do scatter(sums, m.x[i], m.y[i], h, basis, { mm = m.mass[i] }) end
  local pts = {}
  for i = 1, #mem do pts[i] = { m.x[i], m.y[i] } end
  pts[#pts + 1] = { -1, -1 }
  local poly = lamina.polygon{ points = pts }
  local acc = { in_vn = 0, in_mw = 0, in_n = 0, go_vn = 0, go_mw = 0, go_n = 0, any_vn = 0, any_n = 0,
                in_mwall = 0, int_vn = 0, int_mw = 0, int_n = 0 }
  local gamma1 = 0.4
  local n = math.floor(1.6 / h + 0.5)
  for j = 0, n do
    for i = 0, n do
      local key = j * 10000 + i
      local vn = gamma1 * (sums.me[key] or 0) / (h * h)
      local mw = (sums.m[key] or 0) > 0 and sums.mp[key] / sums.m[key] or nil
      if poly:contains(i * h, j * h) then
        acc.in_vn, acc.in_n = acc.in_vn + vn, acc.in_n + 1
        acc.in_mw = acc.in_mw + (mw or 0)
        -- mass-weighted with the membrane's mass in the denominator (its
        -- points carry no gas pressure)
        local all = (sums.m[key] or 0) + (sums.mm[key] or 0)
        acc.in_mwall = acc.in_mwall + (all > 0 and (sums.mp[key] or 0) / all or 0)
      end
      if mw then acc.any_vn, acc.any_n = acc.any_vn + vn, acc.any_n + 1 end
      -- the grid's interior nodes (off the domain's boundary) that the gas
      -- reaches
      if mw and i > 0 and j > 0 and i < n and j < n then
        acc.int_vn, acc.int_mw, acc.int_n = acc.int_vn + vn, acc.int_mw + mw, acc.int_n + 1
      end
      if mw and (sums.mm[key] or 0) == 0 then
        acc.go_vn, acc.go_mw, acc.go_n = acc.go_vn + vn, acc.go_mw + mw, acc.go_n + 1
      end
    end
  end
  local E = sim:energy()
  local A = mem:enclosed_area()
  local space, nodes = gas:pressure()
  print(string.format("%.3f %s %.2f  %.2f  %.2f(%d)  %.2f  %.2f(%d)  %.2f  %.2f(%d)  %.2f  "
                      .. "%.3f %.3f %.3f %.3f %.4f  %.2f  %.4f %.4f",
    h, basis, sim.t, gas:pressure(mem), space, nodes, gas:pressure("particles"),
    acc.in_vn / acc.in_n, acc.in_n, acc.in_mw / acc.in_n, acc.go_vn / acc.go_n, acc.go_n, acc.go_mw / acc.go_n,
    E0.total, E.internal, E.kinetic, E.grid_kinetic, E.strain, gamma1 * E.internal / A,
    b.radius(mem, 0), b.radius(mem, 90)))
  print(string.format("  VN over every node with gas mass %.2f (%d); MW inside, membrane mass counted %.2f; "
                      .. "the grid's interior nodes with gas mass: VN %.2f MW %.2f (%d)",
                      acc.any_vn / acc.any_n, acc.any_n, acc.in_mwall / acc.in_n,
                      acc.int_vn / acc.int_n, acc.int_mw / acc.int_n, acc.int_n))
  -- the nodes inside, for a look (--set nodes=1): i j VN MW membrane-mass
  if lamina.param("nodes", 0) == 1 then
    for j = 0, n do
      for i = 0, n do
        local key = j * 10000 + i
        if poly:contains(i * h, j * h) then
          print(string.format("  node %d %d VN %.3f MW %s mem %.3g", i, j, gamma1 * (sums.me[key] or 0) / (h * h),
            (sums.m[key] or 0) > 0 and string.format("%.3f", sums.mp[key] / sums.m[key]) or "-", sums.mm[key] or 0))
        end
      end
    end
  end
end
