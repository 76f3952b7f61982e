-- lamina run --threads N reaches lamina.sim's default through the run's
-- configuration (issue 19 item 5: no environment variable between layers);
-- the user's LAMINA_THREADS is the fallback, and the key wins over both.
-- Run by tests/cli/CMakeLists.txt with LAMINA_THREADS=2 in the environment.
local want = lamina.param("want", 1)
local a = lamina.sim{ basis = "linear", dt = 1e-3 }
assert(a.threads == want, string.format("default threads %d, expected %d", a.threads, want))
local b = lamina.sim{ basis = "linear", dt = 1e-3, threads = 1 }
assert(b.threads == 1, "the key wins")
print(string.format("threads: default %d (expected %d), key 1", a.threads, want))
