-- Closing: close(), __gc, and Lua 5.4's to-be-closed variables (<close>).
local T = require "helpers"
local verve = require "verve"

local function assert_closed(agent)
  local calls = {
    function() agent:update(0, { discrete = { 1, 1 } }, 0.1) end,
    function() agent:end_episode(0) end,
    function() agent:reset_short_term_memory() end,
    function() agent:set_learning(true) end,
    function() agent:learning() end,
    function() agent:descriptor() end,
    function() agent:value() end,
    function() agent:td_error() end,
    function() agent:rbf_count() end,
    function() agent:stats() end,
    function() agent:sample_values { { kind = "discrete", index = 1 } } end,
    function() agent:save(T.temp_path()) end,
    function() agent:save_string() end,
  }
  for _, call in ipairs(calls) do T.expect_error("verve: the agent is closed", call) end
  assert(tostring(agent):find("^verve.agent %(closed%)"), tostring(agent))
end

T.check("close() makes every method fail; closing twice is harmless", function()
  local agent = verve.agent(T.GRID)
  agent:update(0, { discrete = { 1, 1 } }, 0.1)
  agent:close()
  assert_closed(agent)
  agent:close()
  assert_closed(agent)
end)

T.check("garbage collection frees unreferenced and closed agents", function()
  -- Whether the native agents are really freed, exactly once, is for the sanitizer build to
  -- see (LeakSanitizer, double-free checks); here: the userdata are collected without crashing.
  local weak = setmetatable({}, { __mode = "v" })
  for i = 1, 300 do
    local agent = verve.agent(T.desc(T.MIXED, { seed = i }))
    T.drive(agent, 1, 5)
    if i % 2 == 0 then agent:close() end -- __gc must not free these twice
    weak[i] = agent
  end
  collectgarbage()
  collectgarbage()
  assert(next(weak) == nil, "agents were not collected")
end)

T.check("a table whose __index closes the agent: the call fails cleanly, the freed agent is never used", function()
  -- Reading the observation or an axis runs the metamethod; the native handle must be fetched
  -- after it, or the call would use freed memory.
  local function closing(agent, fields)
    return setmetatable({}, { __index = function(_, key) agent:close(); return fields[key] end })
  end
  local a1 = verve.agent(T.GRID)
  T.expect_error("verve: the agent is closed", function() a1:update(0, closing(a1, { discrete = { 1, 1 } }), 0.1) end)
  local a2 = verve.agent(T.GRID)
  T.expect_error("verve: the agent is closed", function()
    a2:sample_values({ closing(a2, { kind = "discrete", index = 1 }) })
  end)
  local a3 = verve.agent(T.GRID)
  T.expect_error("verve: the agent is closed", function()
    a3:sample_values({ { kind = "discrete", index = 1 } }, closing(a3, { discrete = { 1, 1 } }))
  end)
end)

if T.lua54 then
  -- Compiled at run time: LuaJIT cannot parse the <close> attribute.
  local chunk = assert(load([[
    local verve, T, fail = ...
    local escaped
    do
      local agent <close> = verve.agent(T.GRID)
      agent:update(0, { discrete = { 2, 3 } }, 0.1)
      escaped = agent
    end
    local ok = pcall(function()
      local agent <close> = verve.agent(T.GRID)
      fail.agent = agent
      error("leaving by error")
    end)
    assert(not ok)
    return escaped, fail.agent
  ]]))
  T.check("<close> closes at scope exit, also when leaving by error", function()
    local scoped, failed = chunk(verve, T, {})
    assert_closed(scoped)
    assert_closed(failed)
  end)
else
  print("(no <close> in " .. T.interpreter .. ": agents close by close() or the GC)")
end
