-- Save and load, to a file and to a string: the loaded agent acts exactly as the original.
local T = require "helpers"
local verve = require "verve"

local function trained(desc, steps)
  local agent = verve.agent(desc)
  T.drive(agent, 1, steps)
  agent:end_episode(1)
  T.drive(agent, steps + 1, steps)
  return agent
end

-- Both agents must be indistinguishable from here on.
local function assert_twins(a, b)
  local da, db = a:descriptor(), b:descriptor()
  for k, v in pairs(da) do
    if type(v) ~= "table" then assert(db[k] == v, k) end
  end
  local sa, sb = a:stats(), b:stats()
  assert(sa.steps == sb.steps and sa.rbf_count == sb.rbf_count, "stats differ")
  assert(a:learning() == b:learning())
  local axis = { { kind = "continuous", index = 1, samples = 9 }, { kind = "continuous", index = 2, samples = 5 } }
  local va, vb = a:sample_values(axis), b:sample_values(axis)
  for i = 1, 9 do
    for j = 1, 5 do assert(va[i][j] == vb[i][j], "value function differs") end
  end
  assert(T.same_list(T.drive(a, 1000, 300), T.drive(b, 1000, 300)), "actions differ after loading")
end

T.check("save_string / load_string round trip gives identical actions", function()
  local agent = trained(T.MIXED, 120)
  local text = agent:save_string()
  assert(type(text) == "string" and #text > 100)
  local copy = verve.load_string(text)
  assert(copy:save_string() == text, "saving the copy gives the same bytes")
  assert_twins(agent, copy)
end)

T.check("save / load through a file gives identical actions", function()
  local agent = trained(T.desc(T.MIXED, { planning = true, curiosity = "novelty" }), 80)
  agent:set_learning(false)
  local path = T.temp_path()
  agent:save(path)
  local copy = verve.load(path)
  os.remove(path)
  assert(copy:learning() == false, "the learning switch is saved")
  assert_twins(agent, copy)
end)

T.check("saving overwrites a previous save", function()
  local path = T.temp_path()
  verve.agent(T.GRID):save(path)
  local agent = trained(T.MIXED, 30)
  agent:save(path)
  local copy = verve.load(path)
  os.remove(path)
  assert(#copy:descriptor().continuous == 2)
  assert_twins(agent, copy)
end)

T.check("save_binary_string / load_string: a compact binary save, identical actions", function()
  local agent = trained(T.MIXED, 120)
  local bytes = agent:save_binary_string()
  assert(bytes:sub(1, 8) == "VERVEBIN", "starts with the binary magic")
  assert(#bytes < #agent:save_string(), "smaller than the XML")
  local copy = verve.load_string(bytes)
  assert(copy:save_binary_string() == bytes, "saving the copy gives the same bytes")
  assert(copy:save_string() == agent:save_string(), "the same agent as the XML save says")
  assert_twins(agent, copy)
end)

T.check("save_binary / load through a file gives identical actions", function()
  local agent = trained(T.desc(T.MIXED, { planning = true, curiosity = "novelty" }), 80)
  local path = T.temp_path()
  agent:save_binary(path)
  local copy = verve.load(path)
  os.remove(path)
  assert_twins(agent, copy)
end)

T.check("a damaged binary save is refused with a clear error", function()
  local bytes = verve.agent(T.MIXED):save_binary_string()
  local at = math.floor(#bytes / 2)
  local damaged = bytes:sub(1, at - 1) .. string.char((bytes:byte(at) + 1) % 256) .. bytes:sub(at + 1)
  local ok, err = pcall(verve.load_string, damaged)
  assert(not ok and tostring(err):find("checksum"), tostring(err))
  ok, err = pcall(verve.load_string, bytes:sub(1, 40))
  assert(not ok and tostring(err):find("truncated"), tostring(err))
end)

T.check("recordings: demonstrated steps recorded, saved, loaded and replayed train as the steps did", function()
  local function desc() return { discrete = { 3 }, continuous = 1, actions = 2, seed = 9 } end
  local shown, replayed = verve.agent(desc()), verve.agent(desc())
  local rec = verve.recording(shown)
  for i = 1, 30 do
    local obs = { discrete = { i % 3 + 1 }, continuous = { math.sin(i) } }
    local action = i % 2 + 1
    rec:add_step(0.1, obs, 0.1, action)
    shown:update_demonstrated(0.1, obs, 0.1, action)
    if i % 10 == 0 then rec:add_end_episode(1); shown:end_episode(1) end
  end
  rec:add_truncation(0)
  shown:truncate_episode(0)
  assert(rec:size() == 34, "size " .. rec:size())
  local copy = verve.load_recording_string(rec:save_string())
  assert(copy:save_string() == rec:save_string())
  replayed:replay(copy)
  assert(replayed:save_binary_string() == shown:save_binary_string(), "a replay trains as the steps did")
  T.expect_error("action must be an integer", function() rec:add_step(0, { discrete = { 1 }, continuous = { 0 } }, 0.1, 0) end)
  T.expect_library_error("add_step", function() rec:add_step(0, { discrete = { 4 }, continuous = { 0 } }, 0.1, 1) end)
  T.expect_library_error("load_recording_string", function() verve.load_recording_string("VERVEREC garbage") end)
  local other = verve.agent({ continuous = 2, actions = 2 })
  T.expect_library_error("replay", function() other:replay(copy) end)
  rec:close()
  T.expect_error("closed", function() rec:size() end)
end)
