-- Sensor groups (grouping = "auto" | "joint" | "custom", sensor_groups = {{1, 2}, {3}}): what reaches
-- the library, what comes back, saves, and the refusals. Full allocation makes the lattices' sizes
-- visible: resolution^(sensors in the group) RBFs per group, created with the agent.
local T = require "helpers"
local verve = require "verve"

local function npc(n, extra)
  return T.desc({ continuous = n, actions = 4, seed = 3 }, extra)
end

local function readings(step, n, out)
  out = out or {}
  for i = 1, n do out[i] = math.sin(step * (0.31 + 0.17 * i) + i) end
  return out
end

T.check("auto is the default, with no groups", function()
  local d = verve.defaults()
  assert(d.grouping == "auto", d.grouping)
  assert(type(d.sensor_groups) == "table" and #d.sensor_groups == 0)
end)

T.check("auto gives 12 sensors a lattice per sensor and per neighbouring pair", function()
  local agent = verve.agent(npc(12, { allocation = "full", resolution = 10 }))
  assert(agent:rbf_count() == 12 * 10 + 11 * 10 * 10, agent:rbf_count())
  local d = agent:descriptor()
  assert(d.grouping == "auto" and #d.sensor_groups == 0)
  agent:close()
end)

T.check("joint over 12 sensors is one lattice: too large to allocate in full", function()
  T.expect_library_error("agent", verve.agent, npc(12, { grouping = "joint", allocation = "full" }))
  local agent = verve.agent(npc(12, { grouping = "joint" }))
  assert(agent:descriptor().grouping == "joint")
  agent:close()
end)

T.check("auto keeps memory bounded where one joint lattice keeps growing", function()
  local function rbfs_after(grouping)
    local agent = verve.agent(npc(12, { grouping = grouping }))
    local obs = { continuous = {} }
    for step = 0, 2999 do
      readings(step, 12, obs.continuous)
      agent:update(0, obs, 0.1)
    end
    local n = agent:rbf_count()
    agent:close()
    return n
  end
  local auto, joint = rbfs_after("auto"), rbfs_after("joint")
  assert(auto <= 12 * 10 + 11 * 10 * 10, "auto: " .. auto)
  assert(joint > 2 * auto, ("joint: %d, auto: %d"):format(joint, auto))
end)

T.check("custom groups (sensors from 1) reach the library and come back", function()
  local groups = {}
  for i = 1, 12 do groups[i] = { i } end
  groups[13] = { 2, 1 } -- any order
  local agent = verve.agent(npc(12, { allocation = "full", resolution = 10, sensor_groups = groups }))
  assert(agent:rbf_count() == 12 * 10 + 10 * 10, agent:rbf_count())
  local d = agent:descriptor()
  assert(d.grouping == "custom", "sensor_groups alone mean grouping = \"custom\"")
  assert(#d.sensor_groups == 13)
  for i = 1, 12 do assert(#d.sensor_groups[i] == 1 and d.sensor_groups[i][1] == i) end
  assert(#d.sensor_groups[13] == 2 and d.sensor_groups[13][1] == 1 and d.sensor_groups[13][2] == 2)
  -- descriptor() output is itself a valid descriptor, for every grouping
  local twin = verve.agent(d)
  assert(twin:rbf_count() == agent:rbf_count())
  twin:close()
  local auto = verve.agent(verve.agent(npc(5)):descriptor())
  assert(auto:descriptor().grouping == "auto")
  auto:close()
  -- grouping = "custom" given as well is the same
  local explicit = verve.agent(npc(2, { grouping = "custom", sensor_groups = { { 1, 2 } } }))
  assert(#explicit:descriptor().sensor_groups == 1)
  explicit:close()
  agent:close()
end)

T.check("saves (XML and binary) keep the groups", function()
  local agent = verve.agent(npc(6, { seed = 11, sensor_groups = { { 1, 2 }, { 3, 4, 5 }, { 6 }, { 1, 6 } } }))
  local obs = { continuous = {} }
  for step = 0, 199 do
    readings(step, 6, obs.continuous)
    agent:update(step % 7 == 0 and 1 or 0, obs, 0.1)
  end
  for _, save in ipairs { agent:save_string(), agent:save_binary_string() } do
    local copy = verve.load_string(save)
    local d = copy:descriptor()
    assert(d.grouping == "custom" and #d.sensor_groups == 4)
    assert(table.concat(d.sensor_groups[2], ",") == "3,4,5" and table.concat(d.sensor_groups[4], ",") == "1,6")
    assert(copy:rbf_count() == agent:rbf_count())
    copy:close()
  end
  local copy = verve.load_string(agent:save_binary_string())
  for step = 200, 259 do
    readings(step, 6, obs.continuous)
    assert(agent:update(0, obs, 0.1) == copy:update(0, obs, 0.1), "a loaded copy acts differently")
  end
  copy:close()
  agent:close()
end)

T.check("a brain takes groups too", function()
  local brain = verve.brain(npc(3, { sensor_groups = { { 1, 2 }, { 3 } } }))
  local body = brain:body()
  body:update(0, { continuous = { 0.1, 0.2, 0.3 } }, 0.1)
  assert(body:descriptor().grouping == "custom")
  T.expect_error("continuous sensor 3 is in none of sensor_groups", verve.brain, npc(3, { sensor_groups = { { 1, 2 } } }))
  brain:close()
end)

T.check("docs/lua.md's 12-sensor NPCs, as written there", function()
  local reward, dt, readings = 0, 0.1, readings(1, 12)
  local npc = verve.agent { continuous = 12, actions = 4 }   -- "auto": 12 single lattices, 11 pairs
  local action = npc:update(reward, { continuous = readings }, dt)   -- readings: 12 numbers in [-1, 1]
  local groups = {}
  for i = 1, 12 do groups[#groups + 1] = { i } end         -- each sensor alone
  for i = 1, 7 do groups[#groups + 1] = { i, i + 1 } end   -- neighbouring rays
  groups[#groups + 1] = { 8, 1 }                            -- the ring closes: ray 8 beside ray 1
  groups[#groups + 1] = { 9, 10 }                           -- bearing with distance
  local custom = verve.agent { continuous = 12, actions = 4, sensor_groups = groups }  -- "custom"
  assert(action >= 1 and action <= 4)
  assert(npc:descriptor().grouping == "auto" and custom:descriptor().grouping == "custom")
  assert(#custom:descriptor().sensor_groups == 12 + 7 + 2)
  local a = custom:update(reward, { continuous = readings }, dt)
  assert(a >= 1 and a <= 4)
  npc:close()
  custom:close()
end)

T.check("refusals name the group and count sensors from 1", function()
  local function bad(extra, pattern, n)
    T.expect_error(pattern, verve.agent, npc(n or 4, extra))
  end
  bad({ grouping = "pairs" }, "'grouping' must be one of \"auto\", \"joint\", \"custom\"")
  bad({ sensor_groups = 3 }, "'sensor_groups' must be a list of groups like {{1, 2}, {3}} %(got number%)")
  bad({ sensor_groups = { 1, 2 } }, "sensor_groups%[1%] must be a list of continuous sensors from 1 %(got number%)")
  bad({ sensor_groups = { { 1, 2 }, {} } }, "sensor_groups%[2%] is empty")
  bad({ sensor_groups = { { 1, 0 } } }, "sensor_groups%[1%]%[2%] must be a continuous sensor from 1 to 64 %(got 0%)")
  bad({ sensor_groups = { { 65 } } }, "sensor_groups%[1%]%[1%] must be a continuous sensor from 1 to 64 %(got 65%)")
  bad({ sensor_groups = { { 1.5 } } }, "must be a continuous sensor from 1 to 64 %(got 1.5%)")
  bad({ sensor_groups = { { "1" } } }, "must be a continuous sensor from 1 to 64 %(got string%)")
  bad({ sensor_groups = { { 1, 2, 1 } } }, "sensor_groups%[1%] lists continuous sensor 1 twice")
  bad({ sensor_groups = { { 1, 2 }, { 3, 4, 5 } } }, "sensor_groups%[2%] lists continuous sensor 5, but the agent has 4")
  bad({ sensor_groups = { { 1, 2 }, { 3 } } }, "continuous sensor 4 is in none of sensor_groups")
  bad({ grouping = "custom" }, "grouping = \"custom\" needs sensor_groups covering every continuous sensor")
  bad({ grouping = "joint", sensor_groups = { { 1, 2, 3, 4 } } },
    "sensor_groups are only used with grouping = \"custom\" %(got \"joint\"%)")
  local many = {}
  for i = 1, 65 do many[i] = { 1 } end
  bad({ sensor_groups = many }, "65 sensor_groups; at most 64", 1)
  many[65] = nil
  verve.agent(npc(1, { sensor_groups = many })):close() -- 64 groups, repeated: allowed
  verve.agent(T.desc(T.GRID, { grouping = "custom" })):close() -- no continuous sensors: no group needed
end)
