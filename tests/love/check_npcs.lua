-- Runs the shipped LÖVE sample (samples/love) headless and holds it to bars measured on it:
-- over seeds 1-6, 20 simulated minutes from fresh brains, then a restart of each game that loads
-- the saved brains and plays 4 more minutes. Measured (Release, LÖVE 11.4): food per NPC-minute
-- 0.75 in minutes 1-5, 2.89 in minutes 16-20, 3.30 after the restart; time in the hazard 3.2% -> 0.8%.
-- Usage: luajit check_npcs.lua <love> <verve-npcs.love> <scratch dir>
local love, game, scratch = arg[1], arg[2], arg[3]
local SEEDS = 6
local failures = 0

local function check(ok, message)
  print((ok and "ok:     " or "FAILED: ") .. message)
  if not ok then failures = failures + 1 end
end

-- Runs the game with its save directory under `dir`; returns its output and report figures.
local function play(dir, args)
  local cmd = ("XDG_DATA_HOME='%s' XDG_RUNTIME_DIR='%s' '%s' '%s' --headless %s 2>&1"):format(dir, dir, love,
    game, args)
  local pipe = io.popen(cmd)
  local out = pipe:read("*a")
  pipe:close()
  local food = { out:match("food per NPC%-minute: minutes 1%-%d+ ([%d.]+), minutes %d+%-%d+ ([%d.]+), all %d+ ([%d.]+)") }
  local hazard = { out:match("time in hazard %%: minutes 1%-%d+ ([%d.]+), minutes %d+%-%d+ ([%d.]+)") }
  if not food[1] or not hazard[1] then
    io.write(out)
    error("no report from: " .. cmd)
  end
  return out, { early = tonumber(food[1]), late = tonumber(food[2]), all = tonumber(food[3]),
                hazard_early = tonumber(hazard[1]), hazard_late = tonumber(hazard[2]) }
end

local sum = { early = 0, late = 0, hazard_early = 0, hazard_late = 0, continued = 0 }
for seed = 1, SEEDS do
  local dir = ("%s/seed%d"):format(scratch, seed)
  os.execute(("rm -rf '%s' && mkdir -p -m 700 '%s'"):format(dir, dir))
  local _, fresh = play(dir, ("--minutes 20 --fresh --seed %d"):format(seed))
  local out, continued = play(dir, ("--minutes 4 --seed %d"):format(100 + seed))
  check(out:find("8 brains loaded", 1, true), ("seed %d: the restarted game loads the 8 saved brains"):format(seed))
  print(("seed %d: food per NPC-minute %.2f early, %.2f late, %.2f after the restart; hazard %.1f%% -> %.1f%%")
    :format(seed, fresh.early, fresh.late, continued.all, fresh.hazard_early, fresh.hazard_late))
  for k in pairs(fresh) do if sum[k] then sum[k] = sum[k] + fresh[k] end end
  sum.continued = sum.continued + continued.all
end
for k, v in pairs(sum) do sum[k] = v / SEEDS end

print(("mean of %d seeds: food per NPC-minute %.2f (minutes 1-5), %.2f (16-20), %.2f (restarted); hazard %.1f%% -> %.1f%%")
  :format(SEEDS, sum.early, sum.late, sum.continued, sum.hazard_early, sum.hazard_late))
check(sum.late >= 2.0 and sum.late >= 2 * sum.early, "food rises: late >= 2.0 and >= 2x early")
check(sum.hazard_late < 0.5 * sum.hazard_early, "time in the hazard falls below half")
check(sum.continued >= 2.0 and sum.continued >= 2 * sum.early, "a restarted game continues: >= 2.0 and >= 2x fresh early")

-- A damaged save costs that NPC its brain, not the game.
local dir = scratch .. "/seed1"
local f = assert(io.open(dir .. "/love/verve-npcs/npc1.xml", "w"))
f:write("<verve_agent>not a brain")
f:close()
local out = play(dir, "--minutes 1 --seed 7")
check(out:find("npc1.xml is not a usable brain", 1, true) and out:find("7 brains loaded", 1, true),
  "a corrupt npc1.xml: that NPC starts fresh, the other 7 load")

if failures > 0 then
  print(failures .. " check(s) failed")
  os.exit(1)
end
