-- train_hot_plate.lua: trains Verve agents on the 1D hot plate and prints the learning curve
-- (mean steps to a safe edge per trial, averaged over runs), then the learned value function.
--
--   LUA_CPATH="build/lua/5.4/?.so" lua5.4 samples/lua/train_hot_plate.lua [--runs 20]
--       [--trials 40] [--continuous] [--seed 1]
-- (for LuaJIT: LUA_CPATH="build/lua/jit/?.so" luajit samples/lua/train_hot_plate.lua)
local here = (arg and arg[0] or ""):match("^(.*)[/\\]") or "."
package.path = here .. "/?.lua;" .. package.path

local verve = require "verve"
local HotPlate = require "hot_plate"

local options = { runs = 20, trials = 40, seed = 1, continuous = false }
local i = 1
while arg and arg[i] do
  local name = arg[i]:match("^%-%-(.+)$")
  if name == "continuous" then
    options.continuous = true
  elseif name and type(options[name]) == "number" and tonumber(arg[i + 1]) then
    options[name] = math.floor(tonumber(arg[i + 1]))
    i = i + 1
  else
    io.stderr:write("usage: train_hot_plate.lua [--runs N] [--trials N] [--continuous] [--seed N]\n")
    os.exit(2)
  end
  i = i + 1
end

local DT, MAX_STEPS = 0.1, 1000
local totals = {}
for t = 1, options.trials do totals[t] = 0 end

local last_agent
for run = 1, options.runs do
  local task = HotPlate.new { continuous = options.continuous, seed = options.seed * 7919 + run }
  local agent = verve.agent(task:descriptor { seed = options.seed * 1000 + run })
  for t = 1, options.trials do
    totals[t] = totals[t] + task:run_trial(agent, DT, MAX_STEPS)
  end
  if last_agent then last_agent:close() end -- free now rather than at the next GC cycle
  last_agent = agent
end

local interpreter = type(jit) == "table" and jit.version or _VERSION
print(("# verve %s, %s, 1D hot plate (%s sensor), %d runs"):format(verve.version(), interpreter,
  options.continuous and "continuous" or "discrete", options.runs))
print("# trial  mean_steps")
for t = 1, options.trials do
  print(("%7d  %10.2f"):format(t, totals[t] / options.runs))
end

-- The last agent's value function over the plate: high at the safe edges, low in the middle.
local axis = options.continuous and { kind = "continuous", index = 1, samples = 20 }
  or { kind = "discrete", index = 1 }
local values = last_agent:sample_values { axis }
local cells = {}
for p, v in ipairs(values) do cells[p] = ("%+.2f"):format(v) end
print("# value by position: " .. table.concat(cells, " "))
last_agent:close()
