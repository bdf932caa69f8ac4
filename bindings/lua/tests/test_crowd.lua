-- Many agents from Lua: a batch gives separate agents the actions of agent:update in order and
-- every agent the same actions on any number of threads, bodies of one brain share what they learn, a brain's save (XML or binary) round-trips, bad input refuses the
-- whole batch, and no Lua code runs while a batch reads its arguments.
local T = require "helpers"
local verve = require "verve"

local function crowd()
  local brain = verve.brain { continuous = { {}, {} }, actions = 2, resolution = 8, seed = 5 }
  local agents = {
    verve.agent { discrete = { 4 }, continuous = { {} }, actions = 3, seed = 1 },
    brain:body(),
    verve.agent { continuous = { {}, {} }, actions = 2, seed = 2 },
    brain:body(),
    brain:body(),
  }
  return agents, brain
end

local function observations(agents, step)
  local obs, rewards = {}, {}
  for i, a in ipairs(agents) do
    local d = a:descriptor()
    local o = { continuous = {} }
    for c = 1, #d.continuous do o.continuous[c] = math.sin(0.3 * step + i + c) end
    if #d.discrete > 0 then o.discrete = { (step + i) % 4 + 1 } end
    obs[i], rewards[i] = o, ((step + i) % 3 == 0) and 1 or 0
  end
  return obs, rewards
end

T.check("a batch gives separate agents the actions of updates in order, all agents the same on 1, 2 and 3 threads", function()
  local solo = crowd()
  local separate = { [1] = true, [3] = true }  -- the others are bodies of one brain (docs/crowds.md)
  local expected = {}
  for step = 1, 60 do
    local obs, rewards = observations(solo, step)
    for i, a in ipairs(solo) do expected[#expected + 1] = a:update(rewards[i], obs[i], 0.1) end
  end
  local first
  for _, workers in ipairs { 1, 2, 3 } do
    local agents = crowd()
    local batch = verve.batch { workers = workers }
    assert(batch:workers() == workers)
    local got, actions = {}, {}
    for step = 1, 60 do
      local obs, rewards = observations(agents, step)
      assert(batch:update(agents, rewards, obs, 0.1, actions) == actions, "fills the table it is given")
      for i = 1, #agents do got[#got + 1] = actions[i] end
    end
    for k = 1, #expected do
      if separate[(k - 1) % #agents + 1] then
        assert(got[k] == expected[k], ("action %d: %d vs %d"):format(k, got[k], expected[k]))
      end
    end
    first = first or got
    for k = 1, #first do assert(got[k] == first[k], ("%d workers, action %d: %d vs %d"):format(workers, k, got[k], first[k])) end
    batch:close()
  end
end)

T.check("bad input anywhere refuses the whole batch", function()
  local agents = crowd()
  local batch = verve.batch()
  local obs, rewards = observations(agents, 1)
  local before = agents[4]:save_string()
  obs[2].continuous[1] = 0 / 0
  T.expect_library_error("update", batch.update, batch, agents, rewards, obs, 0.1)
  assert(agents[4]:save_string() == before, "a refused batch changed an agent")
  T.expect_error("counts must match", batch.update, batch, agents, { 1 }, obs, 0.1)
  T.expect_error("agents%[2%] is not an open agent", batch.update, batch, { agents[1], 7 }, { 0, 0 }, { {}, {} }, 0.1)
  T.expect_error("workers must be", verve.batch, { workers = -1 })
  T.expect_error("unknown batch field", verve.batch, { threads = 2 })
  batch:close()
  T.expect_error("the batch is closed", batch.update, batch, agents, rewards, obs, 0.1)
end)

T.check("a batch reads observations raw: no metamethod can close an agent or the batch mid-call", function()
  local agents = crowd()
  local batch = verve.batch { workers = 1 }
  local obs, rewards = observations(agents, 1)
  local calls = 0
  local closer = { __index = function() calls = calls + 1; agents[1]:close(); batch:close() end }
  -- obs[2]'s values behind __index: read raw, it has none, which the library refuses (agent 1 has 2)
  local fields = obs[2]
  obs[2] = setmetatable({}, { __index = function(_, k) closer.__index(); return fields[k] end })
  T.expect_library_error("update", batch.update, batch, agents, rewards, obs, 0.1)
  assert(calls == 0, "a metamethod ran inside batch:update")
  obs[2] = fields
  assert(#batch:update(agents, rewards, obs, 0.1) == #agents, "agents and batch still open")
  batch:close()
end)

T.check("bodies of one brain share what they learn; its save loads as a brain and as an agent", function()
  local brain = verve.brain { continuous = { {} }, actions = 2, seed = 3 }
  local teacher, pupil = brain:body(), brain:body()
  for _ = 1, 300 do teacher:update(1, { continuous = { 0.5 } }, 0.1) end
  pupil:set_learning(false)
  pupil:update(0, { continuous = { 0.5 } }, 0.1)
  assert(pupil:value() > 1, "the pupil does not know what the teacher learned: " .. pupil:value())
  assert(brain:rbf_count() == pupil:rbf_count())
  local saved = brain:save_string()
  local copy = verve.load_brain_string(saved)
  assert(copy:rbf_count() == brain:rbf_count())
  assert(copy:save_string() == saved)
  local agent = verve.load_string(saved)
  agent:update(0, { continuous = { 0.5 } }, 0.1)
  assert(math.abs(agent:value() - pupil:value()) < 1e-6)
  T.expect_library_error("load_brain_string", verve.load_brain_string, saved:sub(1, 100))
  brain:close()
  teacher:update(1, { continuous = { 0.5 } }, 0.1) -- the body keeps the brain alive
  T.expect_error("the brain is closed", brain.body, brain)
end)

T.check("a brain's binary save loads as a brain and as an agent, an agent's as a brain", function()
  local brain = verve.brain { discrete = { 3 }, continuous = { {} }, actions = 2, seed = 4 }
  local bodies = { brain:body(), brain:body() }
  for step = 1, 200 do
    bodies[step % 2 + 1]:update(step % 5 == 0 and 1 or 0, { discrete = { step % 3 + 1 }, continuous = { math.sin(step) } }, 0.1)
  end
  local bytes = brain:save_binary_string()
  assert(bytes:sub(1, 8) == "VERVEBIN", "starts with the binary magic")
  assert(#bytes < #brain:save_string(), "smaller than the XML")
  local copy = verve.load_brain_string(bytes)
  assert(copy:save_binary_string() == bytes and copy:save_string() == brain:save_string())
  local agent = verve.load_string(bytes)
  assert(verve.load_brain_string(agent:save_binary_string()):save_binary_string() == bytes)
  assert(verve.load_brain_string(bodies[1]:save_binary_string()):save_binary_string() == bytes)
  local path = T.temp_path()
  brain:save_binary(path)
  assert(verve.load_brain(path):save_binary_string() == bytes)
  assert(verve.load(path):rbf_count() == brain:rbf_count())
  os.remove(path)
  T.expect_library_error("load_brain_string", verve.load_brain_string, bytes:sub(1, 40))
  local damaged = bytes:sub(1, 99) .. string.char((bytes:byte(100) + 1) % 256) .. bytes:sub(101)
  local ok, err = pcall(verve.load_brain_string, damaged)
  assert(not ok and tostring(err):find("checksum"), tostring(err))
  T.expect_library_error("save_binary", brain.save_binary, brain, "/nonexistent/dir/brain.bin")
  brain:close()
  T.expect_error("the brain is closed", brain.save_binary_string, brain)
end)

T.check("a batch with demonstrated actions gives the steps of update_demonstrated and update in order", function()
  local solo, batched = crowd(), crowd()
  local batch = verve.batch { workers = 2 }
  local actions = {}
  for step = 1, 40 do
    local obs, rewards = observations(solo, step)
    local shown = { false, step % 2 + 1, false, 1, false }  -- agent 2 and body 4 are shown; body 5 alone
    local expected = {}
    for i, a in ipairs(solo) do
      if shown[i] then
        a:update_demonstrated(rewards[i], obs[i], 0.1, shown[i])
        expected[i] = shown[i]
      else
        expected[i] = a:update(rewards[i], obs[i], 0.1)
      end
    end
    batch:update(batched, rewards, obs, 0.1, actions, shown)
    for i = 1, #expected do assert(actions[i] == expected[i], ("step %d agent %d"):format(step, i)) end
  end
  for i = 1, #solo do assert(batched[i]:save_binary_string() == solo[i]:save_binary_string(), "agent " .. i) end
  local obs, rewards = observations(solo, 1)
  T.expect_error("demonstrated%[2%] must be an action from 1", function()
    batch:update(batched, rewards, obs, 0.1, nil, { false, 0, false, false, false })
  end)
  T.expect_library_error("update", function() batch:update(batched, rewards, obs, 0.1, nil, { 9, false, false, false, false }) end)
end)
