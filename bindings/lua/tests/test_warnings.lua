-- What the docs promise the Lua module shows: clamped_rewards and rbf_budget_hits in stats(), and
-- libverve's log warnings through verve.warnings().
local T = require "helpers"
local verve = require "verve"

local function find(list, text)
  for _, message in ipairs(list) do
    if message:find(text, 1, true) then return message end
  end
end

T.check("verve.warnings() starts empty and stays empty while nothing is wrong", function()
  local w = assert(verve.warnings())
  assert(type(w) == "table" and #w == 0, "unexpected warnings: " .. table.concat(w, " | "))
  local agent = verve.agent { discrete = { 3 }, actions = 2 }
  agent:update(0.5, { discrete = { 1 } }, 0.1)
  agent:update(-1, { discrete = { 2 } }, 0.1)
  assert(#verve.warnings() == 0)
  agent:close()
end)

T.check("a reward outside [-1, 1]: counted in clamped_rewards, warned once per agent", function()
  local agent = verve.agent { discrete = { 3 }, actions = 2 }
  agent:update(0, { discrete = { 1 } }, 0.1)
  agent:update(5, { discrete = { 2 } }, 0.1)
  agent:update(-7, { discrete = { 3 } }, 0.1)
  local s = agent:stats()
  assert(s.clamped_rewards == 2, "clamped_rewards = " .. tostring(s.clamped_rewards))
  assert(s.rbf_budget_hits == 0)
  local w = verve.warnings()
  assert(#w == 1, "expected one warning, got " .. #w .. ": " .. table.concat(w, " | "))
  assert(find(w, "a reward of 5 was clamped to [-1, 1]"), w[1])
  assert(#verve.warnings() == 0, "a second read returns what came since the first")
  agent:close()
end)

T.check("the RBF budget reached: counted in rbf_budget_hits, warned once per agent", function()
  local agent = verve.agent { continuous = 1, actions = 2, resolution = 10, max_rbfs = 2 }
  for i = 0, 20 do agent:update(0, { continuous = { -1 + i * 0.1 } }, 0.1) end
  local s = agent:stats()
  assert(s.rbf_count <= 2, "rbf_count = " .. s.rbf_count)
  assert(s.rbf_budget_hits > 0, "rbf_budget_hits = " .. tostring(s.rbf_budget_hits))
  assert(s.clamped_rewards == 0)
  local w = verve.warnings()
  assert(#w == 1 and find(w, "the RBF budget (max_rbfs = 2) is reached"), table.concat(w, " | "))
  agent:close()
end)

T.check("more warnings than are kept between reads: the rest are counted", function()
  local agents = {}
  for i = 1, 70 do
    agents[i] = verve.agent { discrete = { 2 }, actions = 2 }
    agents[i]:update(2, { discrete = { 1 } }, 0.1)
  end
  local w = verve.warnings()
  assert(#w == 65, "#w = " .. #w)
  assert(w[65] == "6 more warnings were dropped (at most 64 are kept between reads)", w[65])
  for i = 1, 70 do agents[i]:close() end
end)

print(("test_warnings (%s): all passed"):format(T.interpreter))
