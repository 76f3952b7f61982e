-- riemann.lua - the exact solution of the Riemann problem for a gamma-law
-- gas: the reference for the Sod shock tube ([F] §4.1, Fig 6; docs/physics.md
-- V4). Two nonlinear waves (shock or rarefaction) around a contact; the
-- star pressure solves f_L(p) + f_R(p) + (u_R - u_L) = 0 by Newton's
-- method; the solution is self-similar in xi = (x - x0)/t.
--
-- local s = riemann.solve{ left = {rho, u, p}, right = {rho, u, p}, gamma = 1.4 }
-- s.p_star, s.u_star, s.rho_star_left, s.rho_star_right, s.shock_speed
-- s:sample(xi) -> rho, u, p (and e = p / ((gamma - 1) rho))
local M = {}

local function wave(p, rho, pk, ck, g)
  -- f_K(p) and its derivative: a shock when p > p_K, else a rarefaction
  if p > pk then
    local A, B = 2 / ((g + 1) * rho), (g - 1) / (g + 1) * pk
    local r = math.sqrt(A / (p + B))
    return (p - pk) * r, r * (1 - 0.5 * (p - pk) / (p + B))
  end
  local e = (g - 1) / (2 * g)
  return 2 * ck / (g - 1) * ((p / pk)^e - 1), (p / pk)^(-(g + 1) / (2 * g)) / (rho * ck)
end

function M.solve(o)
  local g = o.gamma or 1.4
  local rl, ul, pl = o.left[1], o.left[2], o.left[3]
  local rr, ur, pr = o.right[1], o.right[2], o.right[3]
  local cl, cr = math.sqrt(g * pl / rl), math.sqrt(g * pr / rr)
  local p = 0.5 * (pl + pr)
  for _ = 1, 100 do
    local fl, dl = wave(p, rl, pl, cl, g)
    local fr, dr = wave(p, rr, pr, cr, g)
    local dp = (fl + fr + ur - ul) / (dl + dr)
    p = math.max(1e-12, p - dp)
    if math.abs(dp) < 1e-14 * p then break end
  end
  local fl = wave(p, rl, pl, cl, g)
  local fr = wave(p, rr, pr, cr, g)
  local s = { gamma = g, p_star = p, u_star = 0.5 * (ul + ur) + 0.5 * (fr - fl),
              left = {rl, ul, pl, cl}, right = {rr, ur, pr, cr} }
  local G6 = (g - 1) / (g + 1)
  local function star_rho(rk, pk)
    if p > pk then return rk * (p / pk + G6) / (G6 * p / pk + 1) end
    return rk * (p / pk)^(1 / g)
  end
  s.rho_star_left, s.rho_star_right = star_rho(rl, pl), star_rho(rr, pr)
  if p > pr then
    s.shock_speed = ur + cr * math.sqrt((g + 1) / (2 * g) * p / pr + (g - 1) / (2 * g))
  end
  return setmetatable(s, { __index = M })
end

-- The state at xi = (x - x0) / t (Toro's sampling, written out for each
-- side so that every sign is visible).
function M.sample(s, xi)
  local g, p, u = s.gamma, s.p_star, s.u_star
  local G6 = (g - 1) / (g + 1)
  local r, v, pp
  if xi <= u then
    local rk, uk, pk, ck = s.left[1], s.left[2], s.left[3], s.left[4]
    if p > pk then                                   -- left shock
      local S = uk - ck * math.sqrt((g + 1) / (2 * g) * p / pk + (g - 1) / (2 * g))
      if xi < S then r, v, pp = rk, uk, pk
      else r, v, pp = rk * (p / pk + G6) / (G6 * p / pk + 1), u, p end
    else                                             -- left rarefaction
      local head, tail = uk - ck, u - ck * (p / pk)^((g - 1) / (2 * g))
      if xi < head then r, v, pp = rk, uk, pk
      elseif xi > tail then r, v, pp = rk * (p / pk)^(1 / g), u, p
      else
        local c = 2 / (g + 1) * (ck + (g - 1) / 2 * (uk - xi))
        r, v, pp = rk * (c / ck)^(2 / (g - 1)), 2 / (g + 1) * (ck + (g - 1) / 2 * uk + xi),
                   pk * (c / ck)^(2 * g / (g - 1))
      end
    end
  else
    local rk, uk, pk, ck = s.right[1], s.right[2], s.right[3], s.right[4]
    if p > pk then                                   -- right shock
      local S = uk + ck * math.sqrt((g + 1) / (2 * g) * p / pk + (g - 1) / (2 * g))
      if xi > S then r, v, pp = rk, uk, pk
      else r, v, pp = rk * (p / pk + G6) / (G6 * p / pk + 1), u, p end
    else                                             -- right rarefaction
      local head, tail = uk + ck, u + ck * (p / pk)^((g - 1) / (2 * g))
      if xi > head then r, v, pp = rk, uk, pk
      elseif xi < tail then r, v, pp = rk * (p / pk)^(1 / g), u, p
      else
        local c = 2 / (g + 1) * (ck - (g - 1) / 2 * (uk - xi))
        r, v, pp = rk * (c / ck)^(2 / (g - 1)), 2 / (g + 1) * (-ck + (g - 1) / 2 * uk + xi),
                   pk * (c / ck)^(2 * g / (g - 1))
      end
    end
  end
  return r, v, pp, pp / ((g - 1) * r)
end

return M
