-- report.lua: what a --minutes run prints: each simulated minute's measures for the agents and
-- the baselines side by side, then a summary line per driver and measure that tests parse:
--   <driver> <measure> first <k> min <x> last <k> min <y> all <z>
-- with k a quarter of the run (at least 1). Measures are per NPC-minute (targets, reward) or a
-- share of the time (wall contact, hazard).
local report = {}

local MEASURES = { "targets", "wall", "hazard", "reward" }
local PERCENT = { wall = true, hazard = true }

local function mean(history, from, to, field)
  local sum = 0
  for m = from, to do sum = sum + history[m][field] end
  return sum / (to - from + 1)
end

local function cell(m, field)
  return PERCENT[field] and ("%5.1f%%"):format(100 * m[field]) or ("%6.2f"):format(m[field])
end

-- main: { name, history }; baselines: a list of the same, run in the same arena for as long.
function report.print(main, baselines)
  local all = { main }
  for _, b in ipairs(baselines) do all[#all + 1] = b end
  local head = "minute"
  for _, d in ipairs(all) do head = head .. ("  | %s: targets  wall  hazard  reward"):format(d.name) end
  print(head)
  for m = 1, #main.history do
    local line = ("%6d"):format(m)
    for _, d in ipairs(all) do
      line = line .. "  |"
      for _, f in ipairs(MEASURES) do line = line .. " " .. cell(d.history[m], f) end
    end
    print(line)
  end
  local n = #main.history
  local k = math.max(1, math.floor(n / 4))
  for _, d in ipairs(all) do
    for _, f in ipairs(MEASURES) do
      local scale = PERCENT[f] and 100 or 1
      print(("%s %s first %d min %.2f last %d min %.2f all %.2f"):format(d.name, f, k,
        scale * mean(d.history, 1, k, f), k, scale * mean(d.history, n - k + 1, n, f), scale * mean(d.history, 1, n, f)))
    end
  end
end

return report
