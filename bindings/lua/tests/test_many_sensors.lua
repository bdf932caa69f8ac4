-- 32 sensors of each kind (up to 64; issue 30): the descriptor round trip, saves that act the same,
-- a batch that acts as the agent alone, and the lattice limit (joint over more than 16 refused).
local T = require "helpers"
local verve = require "verve"

local N = 32

local function desc(extra)
  local discrete, continuous = {}, {}
  for i = 1, N do
    discrete[i] = i % 8 == 1 and 2 or 1
    continuous[i] = { circular = i % 5 == 1 }
  end
  return T.desc({ discrete = discrete, continuous = continuous, actions = 4, seed = 5 }, extra)
end

local function obs(step)
  local o = { discrete = {}, continuous = {} }
  for i = 1, N do
    o.discrete[i] = i % 8 == 1 and 1 + (math.floor(step / 3) + i) % 2 or 1
    o.continuous[i] = 0.9 * math.sin(step * 0.1 * (0.3 + 0.17 * i) + i)
  end
  return o
end

T.check("32 sensors of each kind reach the library and come back", function()
  local agent = verve.agent(desc())
  local d = agent:descriptor()
  assert(#d.discrete == N and #d.continuous == N, #d.continuous)
  assert(d.discrete[25] == 2 and d.discrete[24] == 1)
  assert(d.continuous[26].circular == true and d.continuous[27].circular == false)
  for step = 0, 199 do
    local a = agent:update(math.sin(0.05 * step), obs(step), 0.1)
    assert(a >= 1 and a <= 4)
  end
  assert(agent:rbf_count() >= 63, agent:rbf_count()) -- auto: 32 singles + 31 pairs
  for round, save in ipairs { "save_string", "save_binary_string" } do
    local copy = verve.load_string(agent[save](agent))
    for step = 140 + 60 * round, 199 + 60 * round do
      assert(agent:update(0, obs(step), 0.1) == copy:update(0, obs(step), 0.1), "a loaded copy acts differently")
    end
    copy:close()
  end
  agent:close()
end)

T.check("a batch of 32-sensor agents acts as each alone", function()
  local solo, batched = verve.agent(desc()), { verve.agent(desc()), verve.agent(desc()) }
  local batch = verve.batch { workers = 2 }
  for step = 0, 99 do
    local o = obs(step)
    local expected = solo:update(0.1, o, 0.1)
    local actions = batch:update(batched, { 0.1, 0.1 }, { o, o }, 0.1)
    assert(actions[1] == expected and actions[2] == expected, "step " .. step)
  end
  solo:close()
  for _, a in ipairs(batched) do a:close() end
end)

T.check("over 64 sensors, or one lattice over more than 16, is refused", function()
  T.expect_error("65 continuous sensors; at most 64", verve.agent, T.desc({ continuous = 65, actions = 2 }))
  T.expect_library_error("agent", verve.agent, desc({ grouping = "joint" }))
  T.expect_error("which spans at most 16", verve.agent, desc({ grouping = "joint" }))
  T.expect_error("33 continuous sensors make 65 AUTO", verve.agent, T.desc({ continuous = 33, actions = 2 }))
  local groups = {}
  for g = 0, 3 do
    local group = {}
    for k = 1, 16 do group[k] = 16 * g + k end
    groups[g + 1] = group
  end
  local agent = verve.agent(T.desc({ continuous = 64, actions = 2, sensor_groups = groups }))
  local readings = {}
  for i = 1, 64 do readings[i] = 0.5 end
  agent:update(0, { continuous = readings }, 0.1)
  assert(#agent:descriptor().sensor_groups == 4)
  agent:close()
end)


