-- helpers.lua: what the test scripts share. Plain asserts, no framework: a failing check raises
-- an error, the interpreter exits non-zero and CTest reports the test as failed.
local M = {}

M.lua54 = _VERSION == "Lua 5.4" -- LuaJIT reports "Lua 5.1"
M.interpreter = type(jit) == "table" and jit.version or _VERSION

-- Runs one named check and reports it.
function M.check(name, fn)
  io.write(name, " ... ")
  io.flush()
  fn()
  print("ok")
end

-- Calls fn(...) and asserts it raises an error whose message contains `pattern` (a Lua
-- pattern). Returns the message.
function M.expect_error(pattern, fn, ...)
  local ok, err = pcall(fn, ...)
  assert(not ok, ("expected an error matching %q, but the call succeeded"):format(pattern))
  err = tostring(err)
  assert(err:find(pattern), ("error %q does not match %q"):format(err, pattern))
  return err
end

-- Lua's own "bad argument" message for a wrong type. The argument number and function name are
-- left open: they depend on how the method was called (a:f() counts self out) and the interpreter.
function M.bad_arg(expected, got)
  return "bad argument #%d+ to '[%w_.?]+' %(" .. expected .. " expected, got " .. got .. "%)"
end

-- A library-side refusal: "verve: <fn>: <verve_last_error()> [<verve_result_name()>]". The C
-- message must be there, not just the code.
function M.expect_library_error(fn_name, fn, ...)
  local err = M.expect_error("verve: " .. fn_name .. ": ", fn, ...)
  local message = err:match("verve: " .. fn_name .. ": (.-) %[VERVE_[%u_]+%]")
  assert(message and #message > 0, ("no library message in %q"):format(err))
  return err
end

-- Small descriptors used across the scripts; `extra` fields override.
function M.desc(base, extra)
  local d = {}
  for k, v in pairs(base) do d[k] = v end
  for k, v in pairs(extra or {}) do d[k] = v end
  return d
end
M.GRID = { discrete = { 5, 4 }, actions = 5, seed = 7 }
M.MIXED = { discrete = { 3 }, continuous = { { circular = true }, {} }, actions = 3, seed = 11 }

-- A deterministic walk of observations for the MIXED descriptor, reusing one table.
function M.mixed_obs(step, obs)
  obs = obs or { discrete = { 1 }, continuous = { 0, 0 } }
  obs.discrete[1] = step % 3 + 1
  obs.continuous[1] = math.sin(step * 0.37)
  obs.continuous[2] = math.cos(step * 0.21) * 0.9
  return obs
end

-- Drives `agent` for n steps over mixed_obs; returns the list of actions.
function M.drive(agent, first, n)
  local actions, obs = {}, nil
  for step = first, first + n - 1 do
    obs = M.mixed_obs(step, obs)
    actions[#actions + 1] = agent:update((step % 7 == 0) and 1 or -0.1, obs, 0.1)
  end
  return actions
end

function M.same_list(a, b)
  if #a ~= #b then return false end
  for i = 1, #a do
    if a[i] ~= b[i] then return false end
  end
  return true
end

-- A file name for a save; the caller removes it.
function M.temp_path()
  local path = os.tmpname()
  os.remove(path)
  return path .. ".xml"
end

return M
