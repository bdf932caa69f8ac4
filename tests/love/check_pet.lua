-- Runs the shipped pet game (samples/love_pet) headless with its scripted teacher and holds it to
-- bars measured on it (docs/teaching.md): over seeds 1-10, the trials until the pet does its trick
-- five times in a row, alone, with the teacher at the controls for the first 30 trials, and with the
-- teacher only clicking "good" or "bad" half a second after each sit. Measured (LÖVE 11.4): alone
-- 218.6, shown 51.9 (4.2x fewer), praised 89.6 (2.4x fewer).
-- Usage: luajit check_pet.lua <love> <verve-pet.love> <scratch dir>
local love, game, scratch = arg[1], arg[2], arg[3]
local SEEDS = 10
local failures = 0

local function check(ok, message)
  print((ok and "ok:     " or "FAILED: ") .. message)
  if not ok then failures = failures + 1 end
end

local function trials(args)
  local cmd = ("XDG_DATA_HOME='%s' XDG_RUNTIME_DIR='%s' '%s' '%s' --headless %s 2>&1"):format(scratch, scratch, love,
    game, args)
  local pipe = io.popen(cmd)
  local out = pipe:read("*a")
  pipe:close()
  local n = out:match("learned the trick after (%d+) trials")
  if not n then
    io.write(out)
    error("no report from: " .. cmd)
  end
  return tonumber(n)
end

os.execute(("rm -rf '%s' && mkdir -p -m 700 '%s'"):format(scratch, scratch))
local mean = { alone = 0, shown = 0, praised = 0 }
for seed = 1, SEEDS do
  local alone = trials(("--seed %d"):format(seed))
  local shown = trials(("--seed %d --shown 30"):format(seed))
  local praised = trials(("--seed %d --praise"):format(seed))
  print(("seed %d: trials to learn the trick: alone %d, shown %d, praised %d"):format(seed, alone, shown, praised))
  mean.alone = mean.alone + alone / SEEDS
  mean.shown = mean.shown + shown / SEEDS
  mean.praised = mean.praised + praised / SEEDS
end
print(("mean of %d seeds: alone %.1f, shown for 30 trials %.1f, praised %.1f"):format(SEEDS, mean.alone, mean.shown,
  mean.praised))
check(mean.alone >= 3 * mean.shown, "shown, the trick is learned in at least 3x fewer trials")
check(mean.alone >= 1.3 * mean.praised, "praised, the trick is learned in at least 1.3x fewer trials")
os.exit(failures == 0 and 0 or 1)
