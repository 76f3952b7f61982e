-- expect: 2
-- stderr: gas_split_huge\.lua:6: lamina\.gas: split must be >= 0 and at most 4096, the limit of points per cell \(got 1e\+308\)
-- Issue 18, memory: lamina.gas{split = 1e308} split every gas point at
-- every step (the point count doubled and more each step, without bound).
-- split = n keeps about n points per cell: it is bounded like ppc.
lamina.gas{ rho = 1, e = 250, gamma = 1.4, split = 1e308 }
