-- porelab.random: a small deterministic random number generator (SplitMix64 on Lua 5.4
-- integers), so that scenes produce the same packing on every machine and Lua build.
-- The run seed (porelab run --seed N, docs/scene-reference.md) feeds every generator: with
-- N = 0 (the default) a generator's stream is its seed as written, otherwise a mix of both,
-- so that one scene gives a new packing per run seed and the same one for the same seed.
--   local rng = require("porelab.random").new(42)
--   rng:uniform()        -- in [0, 1)
--   rng:uniform(a, b)    -- in [a, b)
--   rng:integer(m, n)    -- in m..n
--   rng:choose(weights)  -- index i with probability weights[i] / sum(weights)
local random = {}

local Rng = {}
Rng.__index = Rng

function random.new(seed)
  if seed ~= nil and math.type(seed) ~= "integer" then
    error("random.new: seed must be an integer (got " .. tostring(seed) .. ")", 2)
  end
  local s = seed or 1
  if porelab and porelab.mix_seed then s = porelab.mix_seed(s) end
  return setmetatable({ state = s ~ 0x5DEECE66D }, Rng)
end

local function next_int(self)
  self.state = self.state + 0x9E3779B97F4A7C15
  local z = self.state
  z = (z ~ (z >> 30)) * 0xBF58476D1CE4E5B9
  z = (z ~ (z >> 27)) * 0x94D049BB133111EB
  return z ~ (z >> 31)
end

function Rng:uniform(a, b)
  local u = (next_int(self) >> 11) * (1.0 / 9007199254740992.0)
  if a == nil then return u end
  return a + (b - a) * u
end

function Rng:integer(m, n)
  if n < m then error("rng:integer: empty range " .. m .. ".." .. n, 2) end
  return m + math.floor(self:uniform() * (n - m + 1))
end

function Rng:choose(weights)
  local total = 0
  for _, w in ipairs(weights) do total = total + w end
  local x = self:uniform() * total
  for i, w in ipairs(weights) do
    x = x - w
    if x < 0 then return i end
  end
  return #weights
end

return random
