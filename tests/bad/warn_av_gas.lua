-- expect: 0
-- stderr: warning: body 'hi' \(body 1\) has av \(the artificial viscosity, \[F\] eq 24\): .*-0\.9 %.*case sod
-- stderr-once: has av
-- A gas with the artificial viscosity is warned of once, naming the
-- verification case whose plateau it pulls low (sod30, issue 30 item 2;
-- l_option_warn.c): two sims, one warning, the first gas that has av
-- named (the low-pressure gas has it too).
for k = 1, 2 do
  local sim = lamina.sim{ domain = {0, 0, 1, 0.1}, cell = 0.1, dt = 0.01 }
  sim:body{ material = lamina.gas{ rho = 1, p = 1, av = true }, name = "hi",
            region = lamina.rect{ x0 = 0, y0 = 0, x1 = 0.5, y1 = 0.1 } }
  sim:body{ material = lamina.gas{ rho = 0.125, p = 0.1, av = true }, name = "lo",
            region = lamina.rect{ x0 = 0.5, y0 = 0, x1 = 1, y1 = 0.1 } }
  sim:run{ t_end = 0.05 }
end
