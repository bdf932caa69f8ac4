-- hot_plate.lua: the thesis's 1D hot plate task (chapter 5), written in Lua.
-- A robot on 20 positions; the two edges are safe (+1, the trial ends there), every step
-- elsewhere hurts (-1). Actions: 1 left, 2 stay, 3 right. Positions are 1-based, like every
-- Verve index in Lua. Use it as a module: local HotPlate = require "hot_plate".
local HotPlate = {}
HotPlate.__index = HotPlate

local MOVES = { -1, 0, 1 }

-- Park-Miller "minimal standard" generator: exact in LuaJIT's doubles and in Lua 5.4's
-- integers, so both interpreters draw the same start positions from the same seed.
local MODULUS = 2147483647
local function next_random(state)
  return (state * 16807) % MODULUS
end

-- opts: size (20), continuous (false: one discrete sensor), seed (1).
function HotPlate.new(opts)
  opts = opts or {}
  local self = setmetatable({
    size = opts.size or 20,
    continuous = opts.continuous or false,
    rng = (opts.seed or 1) % (MODULUS - 1) + 1,
    position = 1,
  }, HotPlate)
  -- One observation table, refilled each step: the agent copies it, so no garbage per step.
  self.obs = self.continuous and { continuous = { 0 } } or { discrete = { 0 } }
  return self
end

-- The descriptor for verve.agent, with the thesis's settings (policy multiplier 10,
-- continuous resolution 10); `extra` overrides or adds fields.
function HotPlate:descriptor(extra)
  local d = { actions = #MOVES, policy_multiplier = 10 }
  if self.continuous then
    d.continuous, d.resolution = { {} }, 10
  else
    d.discrete = { self.size }
  end
  for k, v in pairs(extra or {}) do d[k] = v end
  return d
end

function HotPlate:observe()
  if self.continuous then
    self.obs.continuous[1] = -1 + (self.position - 1) * 2 / (self.size - 1)
  else
    self.obs.discrete[1] = self.position
  end
  return self.obs
end

-- A new trial from a random position off the edges.
function HotPlate:reset()
  self.rng = next_random(self.rng)
  self.position = 2 + self.rng % (self.size - 2)
  return self:observe()
end

-- Returns reward, done.
function HotPlate:step(action)
  self.position = math.max(1, math.min(self.size, self.position + MOVES[action]))
  if self.position == 1 or self.position == self.size then return 1, true end
  return -1, false
end

-- One trial driven by `agent`; returns the steps it took (max_steps if it never got out).
function HotPlate:run_trial(agent, dt, max_steps)
  local obs, reward = self:reset(), 0
  for step = 1, max_steps do
    local r, done = self:step(agent:update(reward, obs, dt))
    if done then
      agent:end_episode(r)
      return step
    end
    reward, obs = r, self:observe()
  end
  agent:truncate_episode(reward) -- cut off, not terminal: learn the last reward, bootstrap from here
  return max_steps
end

return HotPlate
