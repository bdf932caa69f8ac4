-- Truncation, greedy play, action probabilities and action masks through the Lua module.
local T = require "helpers"
local verve = require "verve"

local CUE = { discrete = { 2 }, actions = 3, policy_multiplier = 1, seed = 5 }

local function teach(agent, best, trials)
  for _ = 1, trials do
    local a = agent:update(0, { discrete = { 1 } }, 0.1)
    agent:end_episode(a == best and 1 or -1)
  end
end

T.check("action_probabilities(): uniform at first, then the learned preference", function()
  local agent = verve.agent(CUE)
  local p = agent:action_probabilities()
  assert(#p == 3)
  for a = 1, 3 do assert(math.abs(p[a] - 1 / 3) < 1e-6) end
  teach(agent, 2, 300)
  agent:update(0, { discrete = { 1 } }, 0.1)
  p = agent:action_probabilities()
  assert(math.abs(p[1] + p[2] + p[3] - 1) < 1e-5)
  assert(p[2] > 0.9, "p[2] = " .. p[2])
end)

T.check("greedy play always takes the most probable action", function()
  local agent = verve.agent(CUE)
  assert(agent:action_selection() == "sample")
  teach(agent, 3, 200)
  agent:set_learning(false)
  agent:set_action_selection("greedy")
  assert(agent:action_selection() == "greedy")
  for _ = 1, 50 do assert(agent:update(0, { discrete = { 1 } }, 0.1) == 3) end
  T.expect_error("invalid option", function() agent:set_action_selection("random") end)
end)

T.check("a mask of booleans limits the choice; bad masks are refused", function()
  local agent = verve.agent(CUE)
  for _ = 1, 100 do
    local a = agent:update(0, { discrete = { 1 } }, 0.1, { false, true, false })
    assert(a == 2, "masked action " .. a .. " chosen")
    agent:end_episode(1)
  end
  assert(agent:action_probabilities()[1] == 0)
  T.expect_error("allows no action", function() agent:update(0, { discrete = { 1 } }, 0.1, { false, false, false }) end)
  T.expect_error("3 actions", function() agent:update(0, { discrete = { 1 } }, 0.1, { true, true }) end)
  T.expect_error("must be true or false", function() agent:update(0, { discrete = { 1 } }, 0.1, { 1, 1, 1 }) end)
end)

T.check("truncate_episode() learns the last reward without ending the trial", function()
  local agent = verve.agent(CUE)
  agent:update(0, { discrete = { 1 } }, 0.1)
  agent:update(0, { discrete = { 2 } }, 0.1)
  agent:end_episode(1)
  agent:update(0, { discrete = { 2 } }, 0.1)
  local v = agent:value()
  agent:truncate_episode(-0.5)
  local gamma = math.exp(-0.1)
  assert(math.abs(agent:td_error() - (-0.5 + gamma * v - v)) < 1e-5, "td error " .. agent:td_error())
  assert(agent:stats().live_traces == 0)
  T.expect_error("finite", function() agent:truncate_episode(0 / 0) end)
end)

T.check("policy_weight_bound is a descriptor field", function()
  local agent = verve.agent(T.desc(CUE, { policy_weight_bound = 4 }))
  assert(agent:descriptor().policy_weight_bound == 4)
  assert(verve.defaults().policy_weight_bound == 0)
  T.expect_error("policy_weight_bound", function() verve.agent(T.desc(CUE, { policy_weight_bound = -1 })) end)
end)

T.check("update_demonstrated(): the shown action becomes the policy's; bad actions are refused", function()
  local agent = verve.agent(CUE)
  for _ = 1, 10 do agent:update_demonstrated(0, { discrete = { 1 } }, 0.1, 3) end
  agent:update(0, { discrete = { 1 } }, 0.1)
  assert(agent:action_probabilities()[3] > 0.6, "p[3] = " .. agent:action_probabilities()[3]) -- 1/3 untaught
  T.expect_error("action must be an integer", function() agent:update_demonstrated(0, { discrete = { 1 } }, 0.1, 0) end)
  T.expect_library_error("update_demonstrated", function() agent:update_demonstrated(0, { discrete = { 1 } }, 0.1, 4) end)
  T.expect_error("forbids", function()
    agent:update_demonstrated(0, { discrete = { 1 } }, 0.1, 1, { false, true, true })
  end)
end)

T.check("teach(): praise of an answer a moment ago makes it the policy's; bad praise is refused", function()
  local agent = verve.agent(T.desc(CUE, { discrete = { 3 } }))
  agent:teach(0) -- the pet starts remembering its acts
  for _ = 1, 40 do
    local answer = agent:update(0, { discrete = { 1 } }, 0.1)
    for _ = 1, 5 do agent:update(0, { discrete = { 3 } }, 0.1) end
    agent:teach(answer == 2 and 1 or -1)
    for _ = 1, 20 do agent:update(0, { discrete = { 3 } }, 0.1) end
  end
  agent:update(0, { discrete = { 1 } }, 0.1)
  assert(agent:action_probabilities()[2] > 0.6, "p[2] = " .. agent:action_probabilities()[2])
  T.expect_library_error("teach", function() agent:teach(1.5) end)
  T.expect_library_error("teach", function() agent:teach(0 / 0) end)
end)

