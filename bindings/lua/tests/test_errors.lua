-- Bad input: a clear Lua error, and the agent unchanged.
local T = require "helpers"
local verve = require "verve"

local NAN, INF = 0 / 0, 1 / 0

-- Every call in `calls` must fail on `agent`; afterwards the agent must be exactly as before:
-- same save, and the same actions as its twin that never saw the bad calls.
local function refused_without_change(calls)
  local agent, twin = verve.agent(T.MIXED), verve.agent(T.MIXED)
  T.drive(agent, 1, 30)
  T.drive(twin, 1, 30)
  local saved = agent:save_string()
  for _, call in ipairs(calls) do
    T.expect_error(call[1], call[2], agent)
  end
  assert(agent:save_string() == saved, "a refused call changed the agent")
  assert(agent:stats().steps == 30)
  assert(T.same_list(T.drive(agent, 31, 50), T.drive(twin, 31, 50)), "a refused call changed later actions")
end

local function update(reward, obs, dt)
  return function(agent) return agent:update(reward, obs, dt) end
end
local GOOD_C = { 0.1, 0.2 }

T.check("update refuses wrong sizes, NaN/inf, bad discrete values, bad dt", function()
  local lib = "verve: update: .+ %[VERVE_ERROR_INVALID_ARGUMENT%] %(the library counts" -- its message, code, hint
  refused_without_change {
    { lib, update(0, { discrete = {}, continuous = GOOD_C }, 0.1) },             -- too few discrete
    { lib, update(0, { discrete = { 1, 1 }, continuous = GOOD_C }, 0.1) },       -- too many discrete
    { lib, update(0, { discrete = { 1 }, continuous = { 0.1 } }, 0.1) },         -- too few continuous
    { lib, update(0, { discrete = { 1 }, continuous = { 0, 0, 0 } }, 0.1) },     -- too many continuous
    { lib, update(0, { discrete = { 1 } }, 0.1) },                               -- continuous missing
    { lib, update(0, nil, 0.1) },
    { lib, update(0, { discrete = { 1 }, continuous = { NAN, 0 } }, 0.1) },
    { lib, update(0, { discrete = { 1 }, continuous = { 0, INF } }, 0.1) },
    { lib, update(0, { discrete = { 1 }, continuous = { 0, -INF } }, 0.1) },
    { lib, update(0, { discrete = { 1 }, continuous = { 0, 1e300 } }, 0.1) },    -- inf as a float
    { lib, update(NAN, { discrete = { 1 }, continuous = GOOD_C }, 0.1) },
    { lib, update(INF, { discrete = { 1 }, continuous = GOOD_C }, 0.1) },
    { lib, update(0, { discrete = { 0 }, continuous = GOOD_C }, 0.1) },          -- 1-based: 0 is out
    { lib, update(0, { discrete = { 4 }, continuous = GOOD_C }, 0.1) },          -- 3 values: 4 is out
    { lib, update(0, { discrete = { -2 }, continuous = GOOD_C }, 0.1) },
    { lib, update(0, { discrete = { 1 }, continuous = GOOD_C }, 0) },
    { lib, update(0, { discrete = { 1 }, continuous = GOOD_C }, -0.1) },
    { lib, update(0, { discrete = { 1 }, continuous = GOOD_C }, NAN) },
    { "obs.discrete%[1%] must be an integer value from 1 %(got number%)",
      update(0, { discrete = { 1.5 }, continuous = GOOD_C }, 0.1) },
    { "obs.discrete%[1%] must be an integer value from 1 %(got string%)",
      update(0, { discrete = { "1" }, continuous = GOOD_C }, 0.1) },
    { "obs.discrete%[1%] must be an integer", update(0, { discrete = { 2 ^ 40 }, continuous = GOOD_C }, 0.1) },
    { "obs.continuous%[2%] must be a number %(got boolean%)",
      update(0, { discrete = { 1 }, continuous = { 0, true } }, 0.1) },
    { "obs.discrete has 65 values; an agent has at most 64",
      update(0, { discrete = (function() local t = {} for i = 1, 65 do t[i] = 1 end return t end)(), continuous = GOOD_C }, 0.1) },
    { "obs.continuous must be a list %(got number%)", update(0, { discrete = { 1 }, continuous = 0.5 }, 0.1) },
    { "the observation must be a table", update(0, 7, 0.1) },
    { T.bad_arg("number", "string"), update("x", { discrete = { 1 }, continuous = GOOD_C }, 0.1) },
    { T.bad_arg("number", "nil"), update(0, { discrete = { 1 }, continuous = GOOD_C }) },
  }
end)

T.check("other methods refuse bad arguments without change", function()
  local lib = "%[VERVE_ERROR_[%u_]+%]$"
  refused_without_change {
    { lib, function(a) a:end_episode(NAN) end },
    { T.bad_arg("number", "no value"), function(a) a:end_episode() end },
    { T.bad_arg("boolean", "number"), function(a) a:set_learning(1) end },
    { T.bad_arg("table", "number"), function(a) a:stats(5) end },
    { T.bad_arg("string", "no value"), function(a) a:save() end },
  }
end)

T.check("sample_values refuses bad axes and bases", function()
  local agent = verve.agent(T.MIXED)
  T.drive(agent, 1, 20)
  local C1 = { kind = "continuous", index = 1, samples = 5 }
  local function sample(axes, base) return function() return agent:sample_values(axes, base) end end
  T.expect_error("give 1 or 2 axes %(got 0%)", sample {})
  T.expect_error("give 1 or 2 axes %(got 3%)", sample { C1, C1, C1 })
  T.expect_error(T.bad_arg("table", "nil"), sample(nil))
  T.expect_error("each axis must be a table", sample { 5 })
  T.expect_error("axis kind must be \"continuous\" or \"discrete\"", sample { { kind = "angle", index = 1, samples = 3 } })
  T.expect_error("axis index must be an integer from 1 %(got number%)", sample { { kind = "continuous", index = 0, samples = 3 } })
  T.expect_error("axis samples must be a non%-negative integer", sample { { kind = "continuous", index = 1 } })
  T.expect_error("unknown axis field 'sample'", sample { { kind = "continuous", index = 1, sample = 3 } })
  T.expect_error("more than %d+ samples", sample { { kind = "continuous", index = 1, samples = 100000 },
                                                  { kind = "continuous", index = 2, samples = 100000 } })
  T.expect_library_error("sample_values", agent.sample_values, agent, { { kind = "continuous", index = 3, samples = 5 } })
  T.expect_library_error("sample_values", agent.sample_values, agent, { { kind = "discrete", index = 2 } })
  T.expect_library_error("sample_values", agent.sample_values, agent, { { kind = "discrete", index = 1, samples = 4 } })
  T.expect_library_error("sample_values", agent.sample_values, agent, { C1 }, { discrete = { 1 }, continuous = { 0 } })
  T.expect_library_error("sample_values", agent.sample_values, agent, { C1 }, { discrete = { 9 }, continuous = { 0, 0 } })
  T.expect_library_error("sample_values", agent.sample_values, agent, { C1 }, { discrete = { 1 }, continuous = { 0, NAN } })
end)

T.check("corrupt, truncated or missing saves are refused", function()
  local agent = verve.agent(T.MIXED)
  T.drive(agent, 1, 20)
  local good = agent:save_string()
  T.expect_library_error("load_string", verve.load_string, "")
  T.expect_library_error("load_string", verve.load_string, "not xml at all")
  T.expect_library_error("load_string", verve.load_string, good:sub(1, math.floor(#good / 2)))
  T.expect_library_error("load_string", verve.load_string, (good:gsub("</verve_agent>", "")))
  T.expect_library_error("load_string", verve.load_string, (good:gsub('actions="3"', 'actions="three"')))
  T.expect_library_error("load_string", verve.load_string, (good:gsub("<weights[^>]*>", "%0 nan")))
  T.expect_library_error("load_string", verve.load_string, "<verve/>")
  T.expect_error(T.bad_arg("string", "nil"), verve.load_string, nil)
  T.expect_library_error("load", verve.load, "/nonexistent/dir/agent.xml")
  T.expect_library_error("save", agent.save, agent, "/nonexistent/dir/agent.xml")
  T.expect_error(T.bad_arg("string", "table"), verve.load, {})
  assert(verve.load_string(good):save_string() == good, "a good save still loads")
end)

T.check("methods need an agent as self", function()
  local agent = verve.agent(T.GRID)
  T.expect_error(T.bad_arg("verve.agent", "number"), agent.update, 5, 0, {}, 0.1)
  T.expect_error(T.bad_arg("verve.agent", "table"), agent.stats, {})
  T.expect_error(T.bad_arg("verve.agent", "[%w*]+"), agent.close, io.stdout)
end)
