-- Learning through the binding: the 1D hot plate of samples/lua (thesis chapter 5), where the
-- best policy needs 5 steps on average and a random one about 50.
local T = require "helpers"
local verve = require "verve"
local HotPlate = require "hot_plate"

local RUNS, TRIALS, DT, MAX_STEPS = 5, 40, 0.1, 1000

-- Mean steps per trial over RUNS agents, and the last agent.
local function curve(continuous)
  local steps, agent = {}, nil
  for t = 1, TRIALS do steps[t] = 0 end
  for run = 1, RUNS do
    local task = HotPlate.new { continuous = continuous, seed = run }
    agent = verve.agent(task:descriptor { seed = run })
    for t = 1, TRIALS do steps[t] = steps[t] + task:run_trial(agent, DT, MAX_STEPS) / RUNS end
  end
  return steps, agent
end

local function mean(list, first, last)
  local sum = 0
  for i = first, last do sum = sum + list[i] end
  return sum / (last - first + 1)
end

for _, continuous in ipairs { false, true } do
  local kind = continuous and "continuous" or "discrete"
  T.check("hot plate, " .. kind .. " sensor: steps to an edge fall", function()
    local steps, agent = curve(continuous)
    local early, late = mean(steps, 1, 5), mean(steps, TRIALS - 9, TRIALS)
    print(("\n  trials 1-5: %.1f steps, trials %d-%d: %.1f steps"):format(early, TRIALS - 9, TRIALS, late))
    assert(late < 10, "late trials still take " .. late .. " steps")
    assert(late < early / 2, "no clear improvement")
    -- The learned value function is higher next to the safe edges than in the middle.
    local axis = continuous and { kind = "continuous", index = 1, samples = 20 } or { kind = "discrete", index = 1 }
    local v = agent:sample_values { axis }
    assert(v[2] > v[10] and v[19] > v[11], ("values %.2f %.2f %.2f %.2f"):format(v[2], v[10], v[11], v[19]))
  end)
end
