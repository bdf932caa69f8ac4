-- Descriptors from Lua tables: defaults, every field, the round trip, and refusals.
local T = require "helpers"
local verve = require "verve"

T.check("unspecified fields take the library defaults", function()
  local agent = verve.agent { discrete = { 4 }, actions = 2 }
  local d, defaults = agent:descriptor(), verve.defaults()
  for k, v in pairs(defaults) do
    if k ~= "discrete" and k ~= "actions" and type(v) ~= "table" then
      assert(d[k] == v, k)
    end
  end
  assert(#d.discrete == 1 and d.discrete[1] == 4 and d.actions == 2)
  agent:close()
end)

T.check("every field survives the round trip through descriptor()", function()
  local given = {
    discrete = { 10, 3 }, continuous = { { circular = true }, {}, { circular = false } },
    actions = 4, resolution = 16, allocation = "full", tau_value = 0.25, tau_discount = 2.5,
    tau_eligibility = 0.2, policy_multiplier = 7, trace_threshold = 0.05, seed = 123456789,
    planning = true, tau_model = 0.5, max_planning_steps = 20,
    planning_uncertainty_threshold = 0.3, curiosity = "novelty", curiosity_factor = 2, max_rbfs = 200000,
    grouping = "joint",
  }
  local d = verve.agent(given):descriptor()
  for k, v in pairs(given) do
    if k == "discrete" then
      assert(#d.discrete == 2 and d.discrete[1] == 10 and d.discrete[2] == 3)
    elseif k == "continuous" then
      assert(#d.continuous == 3)
      assert(d.continuous[1].circular == true and d.continuous[2].circular == false)
      assert(d.continuous[3].circular == false)
    elseif type(v) == "number" then
      assert(math.abs(d[k] - v) <= 1e-6 * math.abs(v), k .. " = " .. tostring(d[k]))
    else
      assert(d[k] == v, k .. " = " .. tostring(d[k]))
    end
  end
  -- descriptor() output is itself a valid descriptor
  local again = verve.agent(d):descriptor()
  for k, v in pairs(d) do
    if type(v) ~= "table" then assert(again[k] == v, k) end
  end
end)

T.check("continuous = N is N plain sensors; curiosity 'progress' is accepted", function()
  local d = verve.agent({ continuous = 2, actions = 3, curiosity = "progress", planning = true }):descriptor()
  assert(#d.continuous == 2 and not d.continuous[1].circular and not d.continuous[2].circular)
  assert(d.curiosity == "progress")
end)

T.check("a sensorless agent (bandit) is allowed", function()
  local d = verve.agent({ actions = 10 }):descriptor()
  assert(#d.discrete == 0 and #d.continuous == 0 and d.actions == 10)
end)

T.check("binding-side refusals name the field", function()
  local function bad(extra, pattern)
    T.expect_error(pattern, verve.agent, T.desc(T.GRID, extra))
  end
  bad({ actions = "5" }, "'actions' must be a non%-negative integer %(got string%)")
  bad({ actions = 2.5 }, "'actions' must be a non%-negative integer")
  bad({ actions = -1 }, "'actions' must be a non%-negative integer")
  bad({ resolution = 2 ^ 40 }, "'resolution' must be a non%-negative integer")
  bad({ tau_value = "0.1" }, "'tau_value' must be a number %(got string%)")
  bad({ seed = -3 }, "'seed' must be a non%-negative integer")
  bad({ seed = 0.5 }, "'seed' must be a non%-negative integer")
  bad({ planning = 1 }, "'planning' must be a boolean")
  bad({ allocation = "sparse" }, "'allocation' must be one of \"dynamic\", \"full\"")
  bad({ curiosity = true }, "'curiosity' must be one of \"none\", \"novelty\", \"progress\"")
  bad({ tau_vale = 0.1 }, "unknown descriptor field 'tau_vale'")
  bad({ [1] = 5 }, "descriptor fields are names %(got a number key%)")
  bad({ discrete = 5 }, "'discrete' must be a list of value counts")
  bad({ discrete = { 4, "x" } }, "'discrete' must be a list of non%-negative integer value counts")
  local many = {}
  for i = 1, 65 do many[i] = 1 end
  bad({ discrete = many }, "65 discrete sensors; at most 64")
  bad({ continuous = 65 }, "65 continuous sensors; at most 64")
  bad({ continuous = "two" }, "'continuous' must be a sensor count or a list of sensor tables")
  bad({ continuous = { true } }, "'continuous' must be a list of sensor tables")
  bad({ continuous = { { circular = "yes" } } }, "'circular' must be a boolean")
  bad({ continuous = { { circ = true } } }, "unknown continuous sensor field 'circ'")
  T.expect_error(T.bad_arg("table", "nil"), verve.agent, nil)
  T.expect_error(T.bad_arg("table", "number"), verve.agent, 5)
end)

T.check("library-side refusals carry the C message", function()
  T.expect_library_error("agent", verve.agent, T.desc(T.GRID, { actions = 0 }))
  T.expect_library_error("agent", verve.agent, T.desc(T.GRID, { discrete = { 4, 0 } }))
  T.expect_library_error("agent", verve.agent, T.desc(T.GRID, { tau_value = 0 / 0 }))
  T.expect_library_error("agent", verve.agent, T.desc(T.GRID, { tau_discount = -1 }))
  T.expect_library_error("agent", verve.agent, T.desc(T.GRID, { tau_value = 1e300 }))
  T.expect_library_error("agent", verve.agent, T.desc(T.MIXED, { resolution = 0 }))
end)
