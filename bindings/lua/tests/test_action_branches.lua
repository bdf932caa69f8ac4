-- Action branches (action_branches = {3, 2}): several choices per step, one combined action. Actions
-- and choices count from 1 here, as every action in this module; masks and probabilities hold one
-- entry per choice of each branch, branch after branch.
local T = require "helpers"
local verve = require "verve"

local function obs(step)
  return { continuous = { math.sin(step * 0.37), math.cos(step * 0.21) * 0.9 } }
end

local function npc(extra)
  return T.desc({ continuous = 2, action_branches = { 3, 2 }, seed = 5 }, extra)
end

T.check("one action set is the default: no branches", function()
  local d = verve.defaults()
  assert(type(d.action_branches) == "table" and #d.action_branches == 0)
end)

T.check("branches without actions: the library sets actions to their product", function()
  local agent = verve.agent(npc())
  local d = agent:descriptor()
  assert(d.actions == 6, d.actions)
  assert(#d.action_branches == 2 and d.action_branches[1] == 3 and d.action_branches[2] == 2)
  -- descriptor() output is itself a valid descriptor
  local twin = verve.agent(d)
  assert(twin:descriptor().actions == 6)
  twin:close()
  -- actions given and equal to the product is the same
  local explicit = verve.agent(npc { actions = 6 })
  assert(#explicit:descriptor().action_branches == 2)
  explicit:close()
  agent:close()
end)

T.check("a per-branch mask holds every step's choices", function()
  local agent = verve.agent(npc())
  -- branch 1: choices 1 and 3 allowed; branch 2: choice 2 only
  local mask = { true, false, true, false, true }
  for step = 0, 199 do
    local a = agent:update(step % 5 == 0 and 1 or 0, obs(step), 0.1, mask)
    assert(a >= 1 and a <= 6, a)
    local c = agent:split_action(a)
    assert(#c == 2 and (c[1] == 1 or c[1] == 3) and c[2] == 2, ("action %d is {%d, %d}"):format(a, c[1], c[2]))
  end
  local p = agent:action_probabilities()
  assert(#p == 5, #p)
  assert(math.abs(p[1] + p[2] + p[3] - 1) < 1e-5 and math.abs(p[4] + p[5] - 1) < 1e-5)
  assert(p[2] == 0 and p[4] == 0, "a masked choice has probability 0")
  agent:close()
end)

T.check("split and join round trip, branch 1 fastest", function()
  local agent = verve.agent(npc())
  for a = 1, 6 do
    local c = agent:split_action(a)
    assert(agent:join_action(c) == a)
  end
  assert(table.concat(agent:split_action(1), ",") == "1,1")
  assert(table.concat(agent:split_action(2), ",") == "2,1")
  assert(table.concat(agent:split_action(4), ",") == "1,2")
  assert(agent:join_action { 3, 2 } == 6)
  -- one action set: one choice, the action itself
  local plain = verve.agent { actions = 4 }
  assert(table.concat(plain:split_action(3), ",") == "3" and plain:join_action { 3 } == 3)
  plain:close()
  agent:close()
end)

T.check("a demonstrated action is a combined action, within the mask", function()
  local agent = verve.agent(npc())
  local a = agent:join_action { 3, 2 }
  agent:update_demonstrated(0, obs(0), 0.1, a, { true, false, true, false, true })
  T.expect_library_error("update_demonstrated", agent.update_demonstrated, agent, 0, obs(1), 0.1,
    agent:join_action { 2, 2 }, { true, false, true, false, true })
  agent:close()
end)

T.check("saves (XML and binary) keep the branches", function()
  local agent = verve.agent(npc())
  for step = 0, 99 do agent:update(step % 7 == 0 and 1 or 0, obs(step), 0.1) end
  for _, save in ipairs { agent:save_string(), agent:save_binary_string() } do
    local copy = verve.load_string(save)
    local d = copy:descriptor()
    assert(d.actions == 6 and table.concat(d.action_branches, ",") == "3,2")
    for step = 100, 139 do
      assert(agent:update(0, obs(step), 0.1) == copy:update(0, obs(step), 0.1), "a loaded copy acts differently")
    end
    copy:close()
    agent:close()
    agent = verve.load_string(save)
  end
  agent:close()
end)

T.check("a brain's bodies take branches too", function()
  local brain = verve.brain(npc())
  local body = brain:body()
  local c = body:split_action(body:update(0, obs(0), 0.1, { false, true, false, true, true }))
  assert(c[1] == 2)
  brain:close()
end)

T.check("docs/lua.md's branched NPC, as written there", function()
  local reward, dt = 0, 0.1
  local readings = { 0.2, -0.5 }
  -- move: 1 left, 2 stay, 3 right; turn: 1 left, 2 none, 3 right; use: 1 no, 2 yes
  local npc = verve.agent { continuous = 2, action_branches = { 3, 3, 2 } }   -- actions = 18
  local allowed = { true, true, true,  true, true, true,  true, false }        -- "use" not ready yet
  local action = npc:update(reward, { continuous = readings }, dt, allowed)
  local choice = npc:split_action(action)                                     -- {move, turn, use}
  local move, turn, use = choice[1], choice[2], choice[3]
  assert(use == 1 and move >= 1 and move <= 3 and turn >= 1 and turn <= 3)
  assert(npc:join_action { move, turn, use } == action)
  assert(#npc:action_probabilities() == 3 + 3 + 2)
  npc:close()
end)

T.check("refusals: a wrong product, a bad mask, bad choices", function()
  T.expect_error("'action_branches' must be a list of choice counts like {3, 3, 2} %(got number%)",
    verve.agent, npc { action_branches = 3 })
  T.expect_error("action_branches%[2%] must be a number of choices, at least 1 %(got 0%)",
    verve.agent, npc { action_branches = { 3, 0 } })
  T.expect_error("9 action_branches; at most 8", verve.agent, npc { action_branches = { 2, 2, 2, 2, 2, 2, 2, 2, 2 } })
  local err = T.expect_library_error("agent", verve.agent, npc { actions = 5 })
  assert(err:find("product"), err)
  local agent = verve.agent(npc())
  -- 6 flags (one per combined action) instead of 5 (one per choice of each branch)
  T.expect_library_error("update", agent.update, agent, 0, obs(0), 0.1, { true, true, true, true, true, true })
  -- branch 2 allows nothing
  T.expect_library_error("update", agent.update, agent, 0, obs(0), 0.1, { true, true, true, false, false })
  T.expect_error("the action must be an integer from 1", agent.split_action, agent, 0)
  T.expect_library_error("split_action", agent.split_action, agent, 7)
  T.expect_library_error("join_action", agent.join_action, agent, { 4, 1 })
  T.expect_library_error("join_action", agent.join_action, agent, { 1, 1, 1 })
  T.expect_error("choice 2 must be an integer from 1 %(got 0%)", agent.join_action, agent, { 1, 0 })
  -- nothing changed: the agent still acts
  local a = agent:update(0, obs(1), 0.1)
  assert(a >= 1 and a <= 6)
  agent:close()
end)
