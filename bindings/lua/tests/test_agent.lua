-- Every agent method on valid input.
local T = require "helpers"
local verve = require "verve"

T.check("update returns a 1-based action and counts steps", function()
  local agent = verve.agent(T.GRID)
  local obs = { discrete = { 1, 1 } }
  local seen = {}
  for step = 1, 200 do
    obs.discrete[1], obs.discrete[2] = step % 5 + 1, step % 4 + 1 -- 1..5 and 1..4, inclusive
    local a = agent:update(-0.1, obs, 0.1)
    assert(math.floor(a) == a and a >= 1 and a <= 5, "action " .. tostring(a))
    seen[a] = true
  end
  for a = 1, 5 do assert(seen[a], "action " .. a .. " never chosen in 200 steps") end
  assert(agent:stats().steps == 200)
end)

T.check("observations may be nil or {} for a sensorless agent", function()
  local agent = verve.agent { actions = 3, seed = 3 }
  assert(agent:update(0, nil, 0.1) >= 1)
  assert(agent:update(1, {}, 0.1) >= 1)
  assert(agent:update(1, {}, 0.1) <= 3)
  assert(agent:stats().steps == 3)
end)

T.check("the same seed gives the same actions; another seed other ones", function()
  local a, b = verve.agent(T.MIXED), verve.agent(T.MIXED)
  local c = verve.agent(T.desc(T.MIXED, { seed = 12 }))
  local actions_a, actions_b, actions_c = T.drive(a, 1, 300), T.drive(b, 1, 300), T.drive(c, 1, 300)
  assert(T.same_list(actions_a, actions_b))
  assert(not T.same_list(actions_a, actions_c))
end)

T.check("stats(), value(), td_error(), rbf_count() agree", function()
  local agent = verve.agent(T.MIXED)
  local s = agent:stats()
  assert(s.steps == 0)
  T.drive(agent, 1, 50)
  s = agent:stats()
  for _, k in ipairs { "steps", "rbf_count", "live_traces", "value", "td_error", "model_error",
                       "predicted_uncertainty", "planning_steps", "curiosity_reward" } do
    assert(type(s[k]) == "number", k)
  end
  assert(s.steps == 50 and s.rbf_count > 0)
  assert(s.value == agent:value() and s.td_error == agent:td_error() and s.rbf_count == agent:rbf_count())
  assert(s.planning_steps == 0, "no planning configured")
  local mine = { unrelated = true }
  assert(agent:stats(mine) == mine and mine.steps == 50 and mine.unrelated, "fills the given table")
end)

T.check("planning and curiosity show in stats", function()
  local agent = verve.agent(T.desc(T.GRID, { planning = true, curiosity = "novelty", max_planning_steps = 5 }))
  local obs, planned = { discrete = { 1, 1 } }, 0
  for step = 1, 100 do
    obs.discrete[1], obs.discrete[2] = step % 5 + 1, math.floor(step / 5) % 4 + 1
    agent:update(step % 10 == 0 and 1 or 0, obs, 0.1)
    local s = agent:stats()
    assert(s.planning_steps <= 5)
    planned = planned + s.planning_steps
  end
  assert(planned > 0, "the agent never planned")
end)

T.check("end_episode and reset_short_term_memory keep what was learned", function()
  local agent = verve.agent(T.MIXED)
  T.drive(agent, 1, 40)
  local rbfs = agent:rbf_count()
  agent:end_episode(1)
  agent:reset_short_term_memory()
  assert(agent:rbf_count() == rbfs)
  assert(agent:stats().live_traces == 0, "traces cleared")
  T.drive(agent, 41, 10)
  assert(agent:stats().steps == 50)
end)

T.check("set_learning(false) freezes learning, the agent still acts", function()
  local agent = verve.agent { continuous = 1, actions = 2, seed = 5 }
  assert(agent:learning() == true)
  agent:update(0, { continuous = { -1 } }, 0.1)
  local rbfs = agent:rbf_count()
  agent:set_learning(false)
  assert(agent:learning() == false)
  local before = agent:sample_values { { kind = "continuous", index = 1, samples = 9 } }
  for x = -1, 1, 0.05 do
    local a = agent:update(1, { continuous = { x } }, 0.1)
    assert(a == 1 or a == 2)
  end
  assert(agent:rbf_count() == rbfs, "no RBFs allocated while learning is off")
  local after = agent:sample_values { { kind = "continuous", index = 1, samples = 9 } }
  assert(T.same_list(before, after), "values unchanged while learning is off")
  agent:set_learning(true)
  assert(agent:learning() == true)
  agent:update(1, { continuous = { 0.9 } }, 0.1)
  assert(agent:rbf_count() > rbfs, "learning again allocates")
end)

T.check("sample_values: one axis gives a list, two give t[i][j]", function()
  local agent = verve.agent(T.MIXED)
  T.drive(agent, 1, 100)
  local line = agent:sample_values { { kind = "continuous", index = 2, samples = 11 } }
  assert(#line == 11)
  for i = 1, 11 do assert(type(line[i]) == "number") end
  local grid = agent:sample_values({ { kind = "discrete", index = 1 }, { kind = "continuous", index = 1, samples = 7 } },
    { discrete = { 2 }, continuous = { 0.5, -0.5 } })
  assert(#grid == 3, "discrete samples default to the sensor's value count")
  for i = 1, 3 do assert(#grid[i] == 7) end
  -- Row i of the grid is the first axis at value i: it must equal a one-axis sweep of the
  -- second axis with the first sensor fixed at i.
  for i = 1, 3 do
    local sweep = agent:sample_values({ { kind = "continuous", index = 1, samples = 7 } },
      { discrete = { i }, continuous = { 0.5, -0.5 } })
    for j = 1, 7 do assert(math.abs(sweep[j] - grid[i][j]) < 1e-6, ("grid[%d][%d]"):format(i, j)) end
  end
  -- default base: discrete sensors at 1, continuous at 0
  local default = agent:sample_values { { kind = "discrete", index = 1 } }
  local explicit = agent:sample_values({ { kind = "discrete", index = 1 } }, { discrete = { 1 }, continuous = { 0, 0 } })
  assert(T.same_list(default, explicit))
  assert(agent:stats().steps == 100, "sampling does not step the agent")
end)

T.check("update and stats(t) make no garbage when the tables are reused", function()
  local agent = verve.agent(T.MIXED)
  local obs, stats = T.mixed_obs(1), {}
  local function churn()
    for step = 1, 2000 do
      obs.continuous[1] = (step % 50) / 25 - 1
      agent:update(0.1, obs, 0.1)
      agent:stats(stats)
    end
  end
  churn() -- warm up: RBFs allocated, tables sized, LuaJIT traces compiled
  collectgarbage()
  collectgarbage("stop")
  local before = collectgarbage("count")
  churn()
  local grown = collectgarbage("count") - before
  collectgarbage("restart")
  assert(grown < 0.5, ("2000 updates left %.2f KB of garbage"):format(grown))
end)

T.check("tostring names the agent's shape", function()
  local text = tostring(verve.agent(T.MIXED))
  assert(text:find("^verve.agent %(1 discrete, 2 continuous sensors, 3 actions%)"), text)
end)
