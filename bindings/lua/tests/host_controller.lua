-- host_controller.lua: the game-side "brain" that a C++ engine drives (host_embed_test.cpp).
-- The engine owns the world and calls these functions; the script owns the agent.
local verve = require "verve"

local controller = {}
local agent
local obs = { continuous = { 0 } } -- reused every frame

function controller.spawn(seed)
  agent = verve.agent { continuous = { {} }, actions = 2, seed = math.floor(seed), policy_multiplier = 10 }
end

-- x: the body's position in [-1, 1]. Returns 1 (left) or 2 (right).
function controller.think(reward, x, dt)
  obs.continuous[1] = x
  return agent:update(reward, obs, dt)
end

function controller.arrived(reward)
  agent:end_episode(reward)
end

function controller.save()
  return agent:save_string()
end

function controller.restore(saved)
  agent = verve.load_string(saved)
end

return controller
