-- expect: 0
-- Issue 31 item 7: the bulk sweep. Every constructor x key x bad value
-- (NaN, +-inf, -1, 0, 1e300, +-1e18, 2^63, and the wrong types string,
-- table, function, boolean) is called under pcall. Each must be refused
-- with a message that names the key, or be on the list `documented` below
-- (a value the key takes, with the meaning docs/api.md gives it). A crash
-- or hang fails the test (ctest's time limit); so does a silent
-- acceptance or a refusal that does not say which key. The list of what
-- was wrong when it was written is in docs/security.md ("Bad values").
local nan, inf = 0 / 0, 1 / 0
local bad = {
  {"nan", nan}, {"inf", inf}, {"-inf", -inf}, {"-1", -1}, {"0", 0}, {"1e300", 1e300},
  {"1e18", 1e18}, {"-1e18", -1e18}, {"2^63", 2^63}, {"int1e18", 1000000000000000000},
  {"string", "x"}, {"table", {}}, {"function", function() return 0 end},
  {"true", true}, {"false", false},
}

local function sim() return lamina.sim{ dt = 1e-3, domain = {0, 0, 1, 1}, cell = 0.1 } end
local function el() return lamina.elastic{ rho = 1000, E = 1e5 } end
local function body(s)
  return s:body{ material = el(), region = lamina.disk{center = {0.5, 0.5}, radius = 0.2} }
end

-- name, a function making the base table, and how to call with it
local cases = {
  {"lamina.sim", function() return {dt = 1e-3, domain = {0, 0, 1, 1}, cell = 0.1} end,
   function(t) return lamina.sim(t) end},
  {"lamina.elastic", function() return {rho = 1000, E = 1e5} end,
   function(t) return lamina.elastic(t) end},
  {"lamina.membrane", function() return {rho = 1000, E = 1e5, thickness = 0.01} end,
   function(t) return lamina.membrane(t) end},
  {"lamina.gas", function() return {rho = 1, e = 2.5} end,
   function(t) return lamina.gas(t) end},
  {"lamina.linear_fluid", function() return {rho = 1000, beta = 1e5} end,
   function(t) return lamina.linear_fluid(t) end},
  {"lamina.disk", function() return {center = {0.5, 0.5}, radius = 0.2} end,
   function(t) return lamina.disk(t) end},
  {"lamina.rect", function() return {x0 = 0.1, y0 = 0.1, x1 = 0.5, y1 = 0.5} end,
   function(t) return lamina.rect(t) end},
  {"lamina.segment", function() return {from = {0.1, 0.5}, to = {0.9, 0.5}} end,
   function(t) return lamina.segment(t) end},
  {"lamina.arc", function() return {center = {0.5, 0.5}, radius = 0.2, from = 0, to = 360} end,
   function(t) return lamina.arc(t) end},
  {"sim:body", function()
     return {material = el(), region = lamina.disk{center = {0.5, 0.5}, radius = 0.2}} end,
   function(t) return sim():body(t) end},
  {"sim:membrane", function()
     return {material = lamina.membrane{rho = 1000, E = 1e5, thickness = 0.01},
             curve = lamina.arc{center = {0.5, 0.5}, radius = 0.2}, spacing = 0.05} end,
   function(t) return sim():membrane(t) end},
  {"sim:record", function() return {file = "out/security/sweep/r.csv", every = 1e-3} end,
   function(t) return sim():record(t) end},
  {"sim:vtk", function() return {file = "out/security/sweep/v", every = 1e-3} end,
   function(t) return sim():vtk(t) end},
  {"sim:checkpoint", function() return {file = "out/security/sweep/c.ck", every = 1e-3} end,
   function(t) return sim():checkpoint(t) end},
  {"sim:frame", function() return {file = "out/security/sweep/f.png", width = 16, height = 16} end,
   function(t) return sim():frame(t) end},
  {"sim:run", function() return {t_end = 1e-3} end,
   function(t) return sim():run(t) end},
  {"body:pin", function() return {points = {1}} end,
   function(t) local s = sim(); return body(s):pin(t) end},
  {"lamina.figure", function() return {width = 16, height = 16} end,
   function(t) return lamina.figure(t) end},
  {"lamina.plot", function()
     return {file = "out/security/sweep/p.png", width = 200, height = 150,
             series = {{x = {0, 1}, y = {0, 1}}}} end,
   function(t) return lamina.plot(t) end},
  {"lamina.plot series", function() return {x = {0, 1}, y = {0, 1}} end,
   function(t) return lamina.plot{file = "out/security/sweep/p.png", width = 200,
                                  height = 150, series = {t}} end},
}

-- keys to sweep, per case (the keys each constructor knows, docs/api.md)
local keys = {
  ["lamina.sim"] = {"domain", "cell", "dt", "scheme", "gravity", "boundary", "courant",
                    "pic", "seed", "threads", "basis", "stress", "axisymmetric", "mass"},
  ["lamina.elastic"] = {"rho", "E", "nu", "plane"},
  ["lamina.membrane"] = {"rho", "E", "nu", "thickness", "law", "one_way"},
  ["lamina.gas"] = {"rho", "e", "gamma", "mu", "av", "split", "density"},
  ["lamina.linear_fluid"] = {"rho", "beta"},
  ["lamina.disk"] = {"center", "radius"},
  ["lamina.rect"] = {"x0", "y0", "x1", "y1"},
  ["lamina.segment"] = {"from", "to"},
  ["lamina.arc"] = {"center", "radius", "from", "to"},
  ["sim:body"] = {"material", "region", "ppc", "velocity", "name", "fill"},
  ["sim:membrane"] = {"material", "curve", "spacing", "normals", "initial_strain",
                      "end_mass", "velocity", "name", "orient", "force"},
  ["sim:record"] = {"file", "every", "energy", "points", "angle", "values", "average"},
  ["sim:vtk"] = {"file", "every"},
  ["sim:checkpoint"] = {"file", "every"},
  ["sim:frame"] = {"file", "width", "height", "title", "label", "backend", "layout",
                   "panels", "window", "grid", "colour", "colour_bodies", "colourmap",
                   "range", "colourbar", "scalebar", "units", "mirror", "split",
                   "names", "normals", "discs", "band", "phi", "contours",
                   "contour_levels", "particles", "contact"},
  ["sim:run"] = {"t_end"},
  ["body:pin"] = {"points", "velocity"},
  ["lamina.figure"] = {"width", "height", "panels", "title", "backend"},
  ["lamina.plot"] = {"file", "width", "height", "title", "xlabel", "ylabel", "xrange",
                     "yrange", "legend", "csv", "series"},
  ["lamina.plot series"] = {"x", "y", "label", "dashed", "color", "width", "markers"},
}

-- Accepted on purpose: "case.key=value" -> the documented meaning.
local documented = {}
local function allow(case, key, values, why)
  for v in values:gmatch("%S+") do documented[case .. "." .. key .. "=" .. v] = why end
end
local numbers = "nan inf -inf -1 0 1e300 1e18 -1e18 2^63 int1e18"
local truth = "true false"
-- switches: any boolean
allow("lamina.sim", "axisymmetric", truth, "a switch")
allow("lamina.membrane", "one_way", truth, "a switch")
allow("sim:record", "energy", truth, "a switch")
allow("sim:frame", "grid", truth, "a switch")
allow("sim:frame", "colourbar", truth, "a switch")
allow("sim:frame", "scalebar", "true", "a round length")
allow("sim:frame", "phi", truth, "a switch")
allow("sim:frame", "contact", truth, "a switch")
allow("sim:frame", "normals", truth, "true: every point's, false: none")
allow("sim:frame", "particles", truth, "false: none")
allow("sim:frame", "label", truth, "true: the default label, false: none")
allow("lamina.plot", "csv", truth, "a switch")
allow("lamina.plot series", "dashed", truth, "a switch")
allow("lamina.plot series", "markers", truth, "a switch")
-- free text: any string
for _, k in ipairs{"title", "label", "units"} do allow("sim:frame", k, "string", "free text") end
allow("sim:body", "name", "string", "free text")
allow("sim:membrane", "name", "string", "free text")
allow("lamina.figure", "title", "string", "free text")
for _, k in ipairs{"title", "xlabel", "ylabel"} do allow("lamina.plot", k, "string", "free text") end
allow("lamina.plot series", "label", "string", "free text")
-- functions where a function is documented
allow("sim:body", "region", "function", "f(x, y) -> inside")
allow("sim:body", "velocity", "function", "f(x, y) -> vx, vy")
allow("sim:membrane", "curve", "function", "f(u) -> x, y")
allow("sim:membrane", "initial_strain", "function", "f(u, i) -> strain")
allow("body:pin", "points", "function", "a points function")
allow("body:pin", "velocity", "function", "f(t) -> vx, vy")
-- empty tables where a list or map is documented (nothing in it)
allow("sim:record", "points", "table", "no points")
allow("sim:record", "angle", "table", "no angles")
allow("sim:record", "values", "table", "no values")
allow("sim:frame", "colour_bodies", "table", "no body coloured")
allow("body:pin", "points", "table", "no point pinned")
-- numbers with a documented meaning
allow("lamina.sim", "seed", "0 -1 1e18 -1e18 int1e18 2^63", "any whole number seeds the generator")
allow("lamina.sim", "pic", "0", "0: FLIP")
allow("lamina.elastic", "nu", "0", "nu in [0, 0.5)")
allow("lamina.membrane", "nu", "0", "the default")
allow("lamina.gas", "mu", "0", "no viscosity (the default)")
allow("lamina.gas", "split", "0", "no splitting (the default)")
allow("lamina.arc", "from", "0 -1 1e18 -1e18 int1e18 2^63 1e300", "any angle, degrees")
allow("lamina.arc", "to", "0 -1 1e18 -1e18 int1e18 2^63 1e300", "any angle, degrees")
allow("lamina.rect", "x0", "0 -1", "a coordinate")
allow("lamina.rect", "y0", "0 -1", "a coordinate")
allow("sim:membrane", "initial_strain", "0", "no prestrain")
allow("sim:membrane", "end_mass", "0", "a massless end point is refused elsewhere or lumps nothing")
allow("sim:frame", "scalebar", "1e300 1e18 int1e18 2^63", "a length (the bar is clipped)")
allow("sim:frame", "scalebar", "false", "no scale bar")
allow("sim:frame", "mirror", "false", "no mirror image")
allow("sim:frame", "mirror", "string", "\"x\": about the left side")
allow("sim:frame", "mirror", "table", "mirror = {} lists no mirror line")
allow("sim:frame", "contact", "table", "contact = {} shows no pair")
-- a path: any string (confined to the output root, l_path.c)
for _, c in ipairs{"sim:frame", "sim:record", "sim:vtk", "sim:checkpoint", "lamina.plot"} do
  allow(c, "file", "string", "a path")
end
allow("lamina.plot", "csv", "string", "the CSV's path")
allow("lamina.plot", "legend", truth, "true: the best corner, false: none")
allow("lamina.sim", "boundary", "table", "{} : every side the default wall")
allow("lamina.gas", "av", "table", "{} : the default coefficients")
allow("lamina.gas", "av", truth, "true: the default coefficients, false: none")
-- large finite constants: any finite positive value is a material; a
-- stiffness whose waves outrun dt is refused at the first step by the
-- Courant check (naming the body and c_max), as is a dt too large
local large = "1e300 1e18 2^63 int1e18"
for _, k in ipairs{"rho", "E"} do allow("lamina.elastic", k, large, "finite; the Courant check") end
for _, k in ipairs{"rho", "E", "thickness"} do allow("lamina.membrane", k, large, "finite; Courant") end
allow("lamina.membrane", "E", "0", "a string with no stiffness (a chain of masses)")
for _, k in ipairs{"rho", "e", "gamma", "mu"} do allow("lamina.gas", k, large, "finite; Courant") end
allow("lamina.gas", "e", "0", "a cold gas: no pressure")
for _, k in ipairs{"rho", "beta"} do allow("lamina.linear_fluid", k, large, "finite; Courant") end
allow("lamina.sim", "dt", large, "finite; refused by the Courant check at the first step")
allow("lamina.sim", "courant", large, "a Courant number no step exceeds: no check (finite)")
allow("lamina.sim", "cell", large, "one cell over the domain (the body's cells are refused)")
allow("sim:membrane", "end_mass", large, "a heavy end point (finite)")
allow("sim:membrane", "initial_strain", "-1", "logarithmic strain: rest length e x drawn")
allow("lamina.disk", "radius", large, "finite: a disk covering the domain")
allow("lamina.arc", "radius", large, "finite: a curve the membrane's point count refuses")
allow("lamina.rect", "x1", large, "finite: to the domain's edge")
allow("lamina.rect", "y1", large, "finite: to the domain's edge")
allow("lamina.rect", "x0", "-1e18", "finite: from the domain's edge")
allow("lamina.rect", "y0", "-1e18", "finite: from the domain's edge")
-- intervals and windows longer than any run: once / the whole run
for _, c in ipairs{"sim:record", "sim:vtk", "sim:checkpoint"} do
  allow(c, "every", large, "an interval longer than the run: the first sample only")
end
allow("sim:record", "average", "0", "no running mean (the default)")
allow("sim:record", "average", large, "a window longer than the run: the mean so far")
allow("sim:run", "t_end", "-1 0 -1e18", "a time already reached: no step")
_ = numbers

local calls, refused, accepted, wrong = 0, 0, 0, {}
for _, c in ipairs(cases) do
  local name, base, call = c[1], c[2], c[3]
  for _, key in ipairs(keys[name]) do
    for _, b in ipairs(bad) do
      local t = base()
      t[key] = b[2]
      -- a string for a path is a path: keep it in the sweep's folder
      if b[1] == "string" and (key == "file" or key == "csv") then
        t[key] = "out/security/sweep/x_" .. key
      end
      calls = calls + 1
      local ok, err = pcall(call, t)
      local id = name .. "." .. key .. "=" .. b[1]
      if ok then
        if documented[id] then accepted = accepted + 1
        else wrong[#wrong + 1] = "accepted: " .. id end
      else
        err = tostring(err)
        if err:find("'" .. key .. "'", 1, true) or err:find(key .. " ", 1, true)
           or err:find(key .. "=", 1, true) or err:find(key .. ":", 1, true)
           or err:find(key .. ")", 1, true) or err:find(key .. ".", 1, true) then
          refused = refused + 1
        else
          wrong[#wrong + 1] = "unclear: " .. id .. ": " .. err:gsub("\n.*", "")
        end
      end
    end
  end
end
-- Positional arguments: refused naming the call, or documented.
local f = function() end
local positional = {
  {"sim:at", "at", function(v) sim():at(v, f) end},
  {"sim:every", "every", function(v) sim():every(v, f) end},
  {"sim:step", "step", function(v) sim():step(v) end},
  {"rec:mean", "mean", function(v)
     local s = sim(); local r = s:record{every = 1e-3}; s:step(2); return r:mean("t", v, 1) end},
  {"rec:column", "column", function(v)
     local s = sim(); local r = s:record{every = 1e-3}; return r:column(v) end},
  {"lamina.report", "report", function(v) lamina.report{sweep_value = v} end},
}
allow("sim:at", "t", "-1 0 -1e18", "a time already passed: at the next step")
allow("sim:at", "t", "1e300 1e18 2^63 int1e18", "a time the run does not reach: never")
allow("sim:every", "interval", "1e300 1e18 2^63 int1e18", "longer than the run: at the first step")
allow("sim:step", "n", "0", "no step")
allow("rec:mean", "t0", "-inf -1 0 -1e18", "from the first sample")
for _, v in ipairs{"-1", "0", "1e300", "1e18", "-1e18", "2^63", "int1e18", "string", "true", "false"} do
  allow("lamina.report", "value", v, "a finite number, a string or a boolean is reported")
end
local arg_of = {["sim:at"] = "t", ["sim:every"] = "interval", ["sim:step"] = "n",
                ["rec:mean"] = "t0", ["rec:column"] = "name", ["lamina.report"] = "value"}
for _, c in ipairs(positional) do
  for _, b in ipairs(bad) do
    calls = calls + 1
    local ok, err = pcall(c[3], b[2])
    local id = c[1] .. "." .. arg_of[c[1]] .. "=" .. b[1]
    if ok then
      if documented[id] then accepted = accepted + 1
      else wrong[#wrong + 1] = "accepted: " .. id end
    else
      err = tostring(err)
      if err:find(c[1], 1, true) or err:find("'" .. c[2] .. "'", 1, true) then
        refused = refused + 1
      else
        wrong[#wrong + 1] = "unclear: " .. id .. ": " .. err:gsub("\n.*", "")
      end
    end
  end
end

if #wrong > 0 then
  error(#wrong .. " of " .. calls .. " calls wrong:\n" .. table.concat(wrong, "\n"), 0)
end
print(("bad_values_sweep: %d calls, %d refused naming the key, %d accepted as documented")
      :format(calls, refused, accepted))
