-- main.lua: teach a pet a trick, in LÖVE 11 (docs/teaching.md).
-- The pet lives in a 7 x 7 yard. Its trick: walk to the ball and sit on it; then it gets a treat
-- (+1, the only reward the game gives) and the ball lands somewhere else. It senses where the ball
-- is from where it stands and chooses one of five actions: a step north, east, south or west, or sit.
-- Alone it finds the trick by chance, slowly. You can help:
--   arrow keys, S   take the controls: the step you press is a demonstrated step, learned from
--                   as if the pet had chosen it (verve's update_demonstrated); let go and it acts
--   G / B           "good" / "bad": praise or scold what it did over the last moments (teach)
--   Space           fast-forward (x20)   Esc quit
--
-- Headless, a scripted teacher plays your part, and the run reports how many trials the pet took
-- to learn the trick (five trials in a row within 6 steps of the shortest way):
--   love verve-pet.love --headless [--seed N] [--shown N] [--praise] [--max-trials N]
-- --shown N     the teacher takes the controls for the first N trials (default 0)
-- --praise      for the first 40 trials the teacher clicks "good" half a second after the pet sits on
--               the ball and "bad" after it sits anywhere else
-- --curve N     play exactly N trials and print each as "trial,<n>,<steps>,<1 if the trick was done>"
--               (scripts/teaching_curves.sh plots them)
local base = love.filesystem.getSourceBaseDirectory()
package.cpath = base .. "/?.so;" .. base .. "/?.dll;" .. package.cpath
local verve = require "verve"

local SIZE, STEP, CAP = 7, 0.1, 100   -- cells a side; s per decision; steps before a trial is cut
local NORTH, EAST, SOUTH, WEST, SIT = 1, 2, 3, 4, 5
local MOVES = { [NORTH] = { 0, -1 }, [EAST] = { 1, 0 }, [SOUTH] = { 0, 1 }, [WEST] = { -1, 0 } }
local PRAISE_DELAY, PRAISE_TRIALS = 0.5, 40

local options = { seed = 1, shown = 0, max_trials = 2000 }
local curve = nil                     -- --curve: each trial's steps and outcome, printed at the end
local pet, ball, rng, agent
local trial, trial_steps, trial_shortest, reward, treats = 1, 0, 0, 0, 0
local in_a_row, learned_at = 0, nil
local pending, fast, held = 0, false, nil
local clicks = {}                     -- scripted praise waiting: { due = seconds, value = +-1 }
local clock = 0

local function sensors()
  -- The ball's offset from the pet, scaled into [-1, 1]: the trick is the same wherever the ball is.
  return { continuous = { (ball.x - pet.x) / (SIZE - 1), (ball.y - pet.y) / (SIZE - 1) } }
end

local function new_trial()
  pet = { x = rng:random(0, SIZE - 1), y = rng:random(0, SIZE - 1) }
  repeat ball = { x = rng:random(0, SIZE - 1), y = rng:random(0, SIZE - 1) } until ball.x ~= pet.x or ball.y ~= pet.y
  trial_steps, reward = 0, 0
  trial_shortest = math.abs(ball.x - pet.x) + math.abs(ball.y - pet.y) + 1
end

-- The scripted teacher's choice: a shortest way to the ball, then sit.
local function teacher_action()
  if pet.x == ball.x and pet.y == ball.y then return SIT end
  local dx, dy = ball.x - pet.x, ball.y - pet.y
  if dx ~= 0 and (dy == 0 or rng:random() < 0.5) then return dx > 0 and EAST or WEST end
  return dy > 0 and SOUTH or NORTH
end

local function end_trial(done)
  if done then agent:end_episode(1); treats = treats + 1 else agent:truncate_episode(0) end
  if curve then curve[#curve + 1] = { steps = trial_steps, done = done } end
  local alone = trial > options.shown and held == nil
  in_a_row = (alone and done and trial_steps <= trial_shortest + 6) and in_a_row + 1 or 0
  if in_a_row == 5 and not learned_at then learned_at = trial end
  trial = trial + 1
  new_trial()
end

local function step()
  clock = clock + STEP
  local shown = (options.headless and trial <= options.shown) and teacher_action() or held
  local action
  if shown then
    agent:update_demonstrated(reward, sensors(), STEP, shown)
    action = shown
  else
    action = agent:update(reward, sensors(), STEP)
  end
  local before = math.abs(ball.x - pet.x) + math.abs(ball.y - pet.y)
  reward = 0
  trial_steps = trial_steps + 1
  if options.praise and trial <= PRAISE_TRIALS and action == SIT then
    clicks[#clicks + 1] = { due = clock + PRAISE_DELAY, value = before == 0 and 1 or -1 }
  end
  if action == SIT then
    if pet.x == ball.x and pet.y == ball.y then return end_trial(true) end
  else
    pet.x = math.max(0, math.min(SIZE - 1, pet.x + MOVES[action][1]))
    pet.y = math.max(0, math.min(SIZE - 1, pet.y + MOVES[action][2]))
  end
  if trial_steps >= CAP then end_trial(false) end
end

local function deliver_clicks()
  while clicks[1] and clicks[1].due <= clock + 1e-9 do
    agent:teach(table.remove(clicks, 1).value)
  end
end

function love.load(args)
  for i = 1, #args do
    local a = args[i]
    if a == "--headless" then options.headless = true
    elseif a == "--praise" then options.praise = true
    elseif a == "--seed" then options.seed = tonumber(args[i + 1])
    elseif a == "--shown" then options.shown = tonumber(args[i + 1])
    elseif a == "--max-trials" then options.max_trials = tonumber(args[i + 1])
    elseif a == "--curve" then options.curve = tonumber(args[i + 1]) end
  end
  rng = love.math.newRandomGenerator(options.seed)
  agent = verve.agent { continuous = 2, actions = 5, seed = options.seed }
  agent:teach(0) -- remember what it does, for the player's (or the script's) praise
  new_trial()
  if options.headless then
    if options.curve then curve = {} end
    local last = options.curve or options.max_trials
    while (options.curve or not learned_at) and trial <= last do
      step()
      deliver_clicks()
    end
    for n, t in ipairs(curve or {}) do print(("trial,%d,%d,%d"):format(n, t.steps, t.done and 1 or 0)) end
    print(("pet seed %d, shown %d trials%s: learned the trick after %s trials, %d treats"):format(options.seed,
      options.shown, options.praise and ", praised" or "", learned_at and tostring(learned_at) or
      ("more than " .. options.max_trials), treats))
    agent:close()
    love.event.quit(0)
  end
end

function love.update(dt)
  held = nil
  local keys = { up = NORTH, right = EAST, down = SOUTH, left = WEST, s = SIT }
  for key, a in pairs(keys) do
    if love.keyboard.isDown(key) then held = a end
  end
  pending = math.min(pending + dt * (fast and 20 or 1), 1)
  while pending >= STEP do
    step()
    pending = pending - STEP
  end
end

function love.keypressed(key)
  if key == "g" then agent:teach(1)
  elseif key == "b" then agent:teach(-1)
  elseif key == "space" then fast = not fast
  elseif key == "escape" then love.event.quit() end
end

function love.quit()
  if agent then agent:close() end
end

function love.draw()
  local g, cell = love.graphics, 56
  g.clear(0.1, 0.12, 0.1)
  g.push()
  g.translate(20, 20)
  for x = 0, SIZE - 1 do
    for y = 0, SIZE - 1 do
      g.setColor(0.2, 0.32, 0.18)
      g.rectangle("fill", x * cell + 1, y * cell + 1, cell - 2, cell - 2)
    end
  end
  g.setColor(0.95, 0.9, 0.3)
  g.circle("fill", (ball.x + 0.5) * cell, (ball.y + 0.5) * cell, cell * 0.18)
  g.setColor(0.85, 0.6, 0.35)
  g.circle("fill", (pet.x + 0.5) * cell, (pet.y + 0.5) * cell, cell * 0.32)
  g.pop()
  local px = SIZE * cell + 40
  g.setColor(1, 1, 1)
  g.print(("trial %d, step %d"):format(trial, trial_steps), px, 30)
  g.print(("treats: %d"):format(treats), px, 50)
  g.print(learned_at and ("learned at trial %d"):format(learned_at) or "learning...", px, 70)
  g.print(held and "you have the controls" or "the pet acts", px, 110)
  g.print("arrows, S: take the controls\nG / B: good / bad\nSpace: fast-forward\nEsc: quit", px, 150)
end
