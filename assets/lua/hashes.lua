-- hashes.lua - one state hash for a page that runs several simulations
-- (issue 32): the visual regression compares a page's state_hash with its
-- baseline to tell a simulation change from a drawing change, so a page
-- that hashed one run of several let the others' changes pass unseen (the
-- noise_spring page did). fold{h1, h2, ...} folds the runs' hashes (the
-- 16-hex-digit strings of sim:hash()), in order, into one such string by
-- 64-bit FNV-1a over their characters.
local M = {}

function M.fold(list)
  local h = 0xcbf29ce484222325
  for _, s in ipairs(list) do
    for i = 1, #s do h = (h ~ s:byte(i)) * 0x100000001b3 end
  end
  return string.format("%016x", h)
end

return M
