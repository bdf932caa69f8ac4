-- update_bench.lua: what one agent:update costs when called from Lua, for a few agent shapes,
-- next to the cost of the cheapest binding call (agent:learning()), i.e. the Lua<->C overhead.
--   LUA_CPATH="build/lua/5.4/?.so" lua5.4 bindings/lua/bench/update_bench.lua [seconds per case]
--   LUA_CPATH="build/lua/jit/?.so" luajit bindings/lua/bench/update_bench.lua
local verve = require "verve"
local budget = tonumber(arg and arg[1]) or 0.5

-- Runs body(i) in growing batches until `budget` CPU seconds pass; microseconds per call.
local function measure(body)
  local calls, elapsed, batch = 0, 0, 1000
  while elapsed < budget do
    local start = os.clock()
    for i = calls + 1, calls + batch do body(i) end
    elapsed = elapsed + os.clock() - start
    calls = calls + batch
    batch = batch * 2
  end
  return elapsed / calls * 1e6
end

local cases = {
  { name = "10x10 discrete grid, 5 actions", desc = { discrete = { 10, 10 }, actions = 5 },
    obs = { discrete = { 1, 1 } },
    set = function(obs, i) obs.discrete[1], obs.discrete[2] = i % 10 + 1, math.floor(i / 10) % 10 + 1 end },
  { name = "cart-pole shape: 4 continuous, res 8, 3 actions",
    desc = { continuous = 4, resolution = 8, actions = 3 }, obs = { continuous = { 0, 0, 0, 0 } },
    set = function(obs, i)
      local c = obs.continuous
      c[1], c[2], c[3], c[4] = math.sin(i * 0.01), math.cos(i * 0.013), math.sin(i * 0.007), math.cos(i * 0.02)
    end },
  { name = "10x10 grid with planning (<= 10 steps)",
    desc = { discrete = { 10, 10 }, actions = 5, planning = true, max_planning_steps = 10 },
    obs = { discrete = { 1, 1 } },
    set = function(obs, i) obs.discrete[1], obs.discrete[2] = i % 10 + 1, math.floor(i / 10) % 10 + 1 end },
}

print(("# verve %s on %s, %.1f s per case"):format(verve.version(), type(jit) == "table" and jit.version or _VERSION, budget))
print(("%-48s %12s"):format("# case", "us/call"))
local agent = verve.agent(cases[1].desc)
print(("%-48s %12.3f"):format("binding overhead: agent:learning()", measure(function() agent:learning() end)))
for _, case in ipairs(cases) do
  agent = verve.agent(case.desc)
  local obs, set = case.obs, case.set
  local us = measure(function(i)
    set(obs, i)
    agent:update(i % 13 == 0 and 1 or -0.1, obs, 0.1)
  end)
  print(("%-48s %12.3f   (%d RBFs)"):format(case.name, us, agent:rbf_count()))
  agent:close()
end
