-- expect: 0
-- Issue 18, item 1: the escapes the adversarial sweep used all fail.
-- package.loadlib(liblua, "luaopen_io") gave back the whole io library;
-- package.cpath/path could be changed; loadfile/dofile/require opened any
-- file and quoted it in errors; load accepted binary chunks.
local function fails(pattern, f, ...)
  local ok, err = pcall(f, ...)
  assert(not ok, "expected an error matching " .. pattern)
  assert(tostring(err):find(pattern), "got: " .. tostring(err))
end

-- no package library at all: no loadlib, no cpath, no path to rewrite
assert(package == nil, "package is reachable")
assert(debug == nil, "debug is reachable")
assert(string.dump == nil, "string.dump is reachable")

-- io: write only; os: clocks and dates only
for k in pairs(io) do assert(k == "write", "io." .. k .. " is reachable") end
local os_ok = { clock = true, time = true, date = true, difftime = true }
for k in pairs(os) do assert(os_ok[k], "os." .. k .. " is reachable") end
assert(type(os.clock()) == "number" and type(os.time()) == "number")

-- binary chunks: refused by mode and by content
fails("binary chunks are not allowed", load, "return 1", "x", "b")
fails("binary chunks are not allowed", load, "return 1", "x", "bt")
local f, err = load("\27Lua\84\0\25\147\13\10\26\10", "x")
assert(f == nil and err:find("attempt to load a binary chunk"), tostring(err))
assert(load("return 1 + 1")() == 2)          -- text still works
local env = {}
load("x = 5", "c", "t", env)()
assert(env.x == 5 and x == nil)               -- and env is honoured

-- files outside lamina's folders and the script's: not read, not quoted
fails("scripts may read only Lua files", dofile, "/etc/passwd")
local lf, why = loadfile("/etc/passwd")            -- as the stock loadfile: nil, why
assert(lf == nil and why:find("scripts may read only Lua files"), tostring(why))
assert(not why:find("root:"), "a line of the file leaked")
lf, why = loadfile("/etc/hostname", "t")
assert(lf == nil and why:find("scripts may read only Lua files"), tostring(why))
fails("binary chunks are not allowed", loadfile, "x.lua", "b")
fails("NUL byte", dofile, "mods/sec_mod.lua\0x")
local here = SCRIPT:match("^(.*)/") or "."
assert(loadfile(here .. "/mods/sec_mod.lua"))()   -- the script's folder is readable

-- require: lamina's library and the script's folder, plain names only
fails("bad module name", require, "../../../etc/passwd")
fails("bad module name", require, "/etc/passwd")
fails("bad module name", require, "a..b")
fails("bad module name", require, "a/b")
fails("bad module name", require, "x\0y")
fails("not found", require, "no_such_module")
fails("not found", require, "etc.passwd")
local m = require("mods.sec_mod")
assert(m.answer == 42 and m.name == "mods.sec_mod")
assert(require("mods.sec_mod") == m)          -- cached
assert(type(require("dogbone")) == "table")   -- lamina's assets/lua

-- no finalizers for script tables, no stopping the collector
fails("__gc is not available", setmetatable, {}, { __gc = function() end })
fails("invalid option", collectgarbage, "stop")
fails("invalid option", collectgarbage, "generational")
assert(collectgarbage("count") > 0)
collectgarbage()
print("sandbox holds")
