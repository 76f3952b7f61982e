-- expect: 0
-- Creating a body or membrane is all or nothing (issue 19 item 2): a
-- sim:body whose region function fails part-way, or whose velocity
-- function fails, inside pcall, leaves no particles behind; the same for a
-- membrane whose initial_strain or velocity function fails; the run goes
-- on with only the bodies that were made, and its state equals a run that
-- never tried.
local function build(try)
  local sim = lamina.sim{dt = 1e-3, domain = {0, 0, 1, 1}, cell = 0.1}
  local el = lamina.elastic{rho = 1000, E = 1000, nu = 0.3}
  sim:body{material = el, region = lamina.disk{center = {0.3, 0.3}, radius = 0.15}}
  if try then
    local calls = 0
    local ok, err = pcall(sim.body, sim, {material = el, region = function(x, y)
      calls = calls + 1
      if calls > 20 then error("region broke at call " .. calls) end
      return x > 0.5
    end})
    assert(not ok and err:find("region broke"), err)
    ok, err = pcall(sim.body, sim, {material = el, region = lamina.rect{x0 = 0.6, y0 = 0.6, x1 = 0.9, y1 = 0.9},
      velocity = function(x, y) if x > 0.75 then error("velocity broke") end return 0, 0 end})
    assert(not ok and err:find("velocity broke"), err)
    local skin = lamina.membrane{rho = 1, E = 1e4, thickness = 0.01}
    ok, err = pcall(sim.membrane, sim, {material = skin, count = 10,
      curve = lamina.segment{from = {0.1, 0.8}, to = {0.9, 0.8}},
      initial_strain = function(u, i) if i > 5 then error("strain broke") end return 0 end})
    assert(not ok and err:find("strain broke"), err)
  end
  sim:run{t_end = 0.05}
  return sim
end
local a, b = build(false), build(true)
print("particles", a.n, b.n, "hashes", a:hash(), b:hash())
assert(a.n == b.n, "a failed body left particles: " .. a.n .. " vs " .. b.n)
assert(a:hash() == b:hash(), "the state differs after failed bodies")
