-- expect: 0
-- stderr: warning: body 'gas' \(body 1\) on basis = "linear": .*sqrt\(\(gamma - 1\) p / rho\).*gas_acoustic
-- stderr-once: lamina: warning:
-- A gas on the bilinear basis is warned of once (issue 30 item 2; l_option_warn.c):
-- two sims, one warning.
for k = 1, 2 do
  local sim = lamina.sim{ domain = {0, 0, 1, 0.1}, cell = 0.1, dt = 0.01, basis = "linear" }
  sim:body{ material = lamina.gas{ rho = 1, p = 1 }, name = "gas",
            region = lamina.rect{ x0 = 0, y0 = 0, x1 = 1, y1 = 0.1 } }
  sim:run{ t_end = 0.05 }
end
