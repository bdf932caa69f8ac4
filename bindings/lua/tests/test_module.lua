-- The module table: loading, version, defaults.
local T = require "helpers"
local verve = require "verve"
print("interpreter: " .. T.interpreter)

T.check("require returns the same module table twice", function()
  assert(type(verve) == "table")
  assert(require "verve" == verve)
  for _, name in ipairs { "agent", "load", "load_string", "defaults", "version" } do
    assert(type(verve[name]) == "function", name)
  end
end)

T.check("version() gives a string and the packed number", function()
  local text, number = verve.version()
  local major, minor, patch = text:match("^(%d+)%.(%d+)%.(%d+)$")
  assert(major, text)
  assert(number == major * 65536 + minor * 256 + patch, "packed number " .. tostring(number))
  assert(text == "0.1.0" or tonumber(major) == 0, "this binding was written for 0.x")
end)

T.check("defaults() lists every descriptor field with the library's defaults", function()
  local d = verve.defaults()
  assert(#d.discrete == 0 and #d.continuous == 0)
  assert(d.resolution == 10)
  assert(d.allocation == "dynamic")
  assert(math.abs(d.tau_value - 0.1) < 1e-6)
  assert(math.abs(d.tau_discount - 1.0) < 1e-6)
  assert(math.abs(d.tau_eligibility - 0.1) < 1e-6)
  assert(math.abs(d.policy_multiplier - 5) < 1e-6)
  assert(math.abs(d.trace_threshold - 0.01) < 1e-6)
  assert(d.planning == false and d.curiosity == "none")
  assert(d.max_planning_steps == 10)
  assert(math.abs(d.planning_uncertainty_threshold - 0.5) < 1e-6)
  assert(math.abs(d.curiosity_factor - 5) < 1e-6)
  assert(d.planning_accumulates_uncertainty == true and d.learn_from_real_steps == true)
  assert(d.discrete_prediction == "categorical")
  assert(math.type == nil or math.type(d.seed) == "integer")
  assert(d ~= verve.defaults(), "a fresh table each call")
end)
