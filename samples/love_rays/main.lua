-- main.lua: NPCs that see with rays, in LÖVE 11 (docs/lua.md, "NPCs that see with rays").
-- Six NPCs walk a 10 x 10 m arena with five boxes and a red hazard disc; each has its own Verve
-- agent, at the library's default settings, and its own target to fetch (+1; a new one appears
-- elsewhere). Standing in the hazard costs 1 a step (0.1 s), touching a wall or box 0.1 a step.
-- An NPC senses as a game NPC does: 8 rays over its front half (rays.lua), bearing and distance to
-- its target, its speed and turn rate, and whether the hazard is ahead or underfoot (world.lua).
-- It acts on two branches at once: turn {left, none, right} x move {stop, forward}.
--
--   love verve-rays.love [--headless] [--minutes N] [--seed N] [--driver D] [--progress K]
--                        [--screenshot FILE]
-- --minutes N    run N simulated minutes flat out, then the scripted steering and a random policy
--                for N minutes in the same arena, print each minute's measures and a summary, quit
-- --seed N       decides the arena, starts, targets and each agent's random stream (default 1)
-- --driver D     in the window: agents (default), script or random
-- --progress K   also reward K per metre an NPC closes on its target (default 0: arrival only;
--                with 2 the agents learn to fetch, docs/lua.md)
-- --screenshot F at the end of --minutes, save the window as F in the save directory
-- Keys: Space fast-forwards (x20), R shows or hides the rays, Esc quits.

-- Native modules cannot load from inside a .love archive: verve.so (verve.dll) ships beside it.
local base = love.filesystem.getSourceBaseDirectory()
package.cpath = base .. "/?.so;" .. base .. "/?.dll;" .. package.cpath
local verve = require "verve"
local world = require "world"
local rays = require "rays"
local steering = require "steering"
local report = require "report"

local options = { seed = 1, driver = "agents" }
local current                       -- the world on screen (or training, with --minutes)
local fast, show_rays, pending = false, true, 0

-- The drivers: each returns the turn and move choices (from 1) for NPC i.
local drivers = {
  agents = function(_, _, npc)
    local choice = npc.agent:split_action(npc.agent:update(npc.reward, npc.obs, world.STEP))
    return choice[1], choice[2]
  end,
  script = steering,
}
local random_rng
drivers.random = function() return random_rng:random(1, 3), random_rng:random(1, 2) end

local function new_world(driver)
  random_rng = love.math.newRandomGenerator(options.seed + 7)
  return world.new(options.seed, drivers[driver], driver == "agents" and function(i)
    return verve.agent(world.descriptor(options.seed * 1000 + i))
  end or nil, options.progress)
end

local function run(w, minutes)
  for _ = 1, minutes * world.STEPS_PER_MINUTE do w:step() end
  return w.history
end

function love.load(args)
  local i = 1
  while args[i] do
    local a, value = args[i], args[i + 1]
    if a == "--minutes" and tonumber(value) then options.minutes, i = math.floor(tonumber(value)), i + 1
    elseif a == "--seed" and tonumber(value) then options.seed, i = math.floor(tonumber(value)), i + 1
    elseif a == "--driver" and drivers[value] then options.driver, i = value, i + 1
    elseif a == "--progress" and tonumber(value) and tonumber(value) >= 0 then
      options.progress, i = tonumber(value), i + 1
    elseif a == "--screenshot" and value then options.screenshot, i = value, i + 1
    elseif a ~= "--headless" then error("unknown argument " .. a .. " (see the top of main.lua)") end
    i = i + 1
  end
  if not love.graphics and not options.minutes then error("--headless needs --minutes N") end
  current = new_world(options.driver)
  print(("verve %s on %s: %d NPCs driven by %s, seed %d, progress reward %g per metre"):format(verve.version(),
    jit and jit.version or _VERSION, world.NPCS, options.driver, options.seed, options.progress or 0))
end

-- The end of a --minutes run: the baselines in the same arena, the report, then quit.
local function finish_run()
  local baselines = {}
  for _, name in ipairs { "script", "random" } do
    if name ~= options.driver then
      local w = new_world(name)
      baselines[#baselines + 1] = { name = name, history = run(w, options.minutes) }
    end
  end
  report.print({ name = options.driver, history = current.history }, baselines)
  if not options.screenshot then return love.event.quit(0) end
  love.graphics.captureScreenshot(function(image) -- called once the next frame is drawn
    image:encode("png", options.screenshot)
    print("screenshot: " .. love.filesystem.getSaveDirectory() .. "/" .. options.screenshot)
    love.event.quit(0)
  end)
end

function love.update(dt)
  if options.minutes then -- flat out: one simulated minute per frame
    if #current.history < options.minutes then
      run(current, 1)
      if #current.history == options.minutes then finish_run() end
    end
    return
  end
  pending = math.min(pending + dt * (fast and 20 or 1), 1) -- never more than 1 s behind
  while pending >= world.STEP do
    current:step()
    pending = pending - world.STEP
  end
end

function love.keypressed(key)
  if key == "space" then fast = not fast
  elseif key == "r" then show_rays = not show_rays
  elseif key == "escape" then love.event.quit() end
end

function love.quit() current:close() end -- LuaJIT has no <close>: free the agents now

local SCALE = 50 -- pixels per metre
local seen = {}  -- ray readings for drawing
local COLOURS = { { 0.95, 0.8, 0.3 }, { 0.4, 0.8, 1 }, { 1, 0.55, 0.8 }, { 0.7, 1, 0.5 },
                  { 1, 0.65, 0.35 }, { 0.75, 0.6, 1 } }

function love.draw()
  local g, ar = love.graphics, current.arena
  g.clear(0.08, 0.08, 0.1)
  g.push()
  g.translate(20 + ar.half * SCALE, 20 + ar.half * SCALE)
  g.scale(SCALE)
  g.setLineWidth(1.5 / SCALE)
  g.setColor(0.16, 0.17, 0.2)
  g.rectangle("fill", -ar.half, -ar.half, 2 * ar.half, 2 * ar.half)
  g.setColor(0.85, 0.2, 0.15, 0.6)
  g.circle("fill", ar.hx, ar.hy, ar.hazard_radius, 48)
  g.setColor(0.55, 0.55, 0.6)
  for _, b in ipairs(ar.solids) do g.rectangle("fill", b.x - b.hx, b.y - b.hy, 2 * b.hx, 2 * b.hy) end
  for i, npc in ipairs(current.npcs) do
    local colour = COLOURS[(i - 1) % #COLOURS + 1]
    if show_rays then -- each ray to where it stops (its full range when it sees nothing), cast anew:
      g.setColor(colour[1], colour[2], colour[3], 0.35) -- the NPC has moved since it sensed
      rays.fan(ar.solids, npc.x, npc.y, npc.a, world.RADIUS, seen)
      for k = 1, rays.COUNT do
        local a, d = npc.a + rays.angle(k), world.RADIUS + seen[k]
        g.line(npc.x, npc.y, npc.x + math.cos(a) * d, npc.y + math.sin(a) * d)
      end
    end
    g.setColor(colour)
    g.circle("line", npc.tx, npc.ty, 0.15, 16) -- its target
    g.circle("fill", npc.x, npc.y, world.RADIUS, 24)
    g.setColor(npc.touching and 1 or 0, 0, 0)
    g.line(npc.x, npc.y, npc.x + math.cos(npc.a) * world.RADIUS, npc.y + math.sin(npc.a) * world.RADIUS)
  end
  g.pop()

  local px, py = 560, 30
  local last = current.history[#current.history]
  g.setColor(1, 1, 1)
  g.print(("driver: %s   seed %d"):format(options.driver, options.seed), px, py)
  g.print(("simulated %d:%02d%s"):format(math.floor(current.steps / world.STEPS_PER_MINUTE),
    math.floor(current.steps % world.STEPS_PER_MINUTE / 10), fast and "  (x20)" or ""), px, py + 20)
  g.print("last simulated minute, per NPC:", px, py + 56)
  if last then
    g.print(("targets   %.2f"):format(last.targets), px, py + 76)
    g.print(("wall      %.1f%% of the time"):format(100 * last.wall), px, py + 94)
    g.print(("hazard    %.1f%% of the time"):format(100 * last.hazard), px, py + 112)
    g.print(("reward    %.2f"):format(last.reward), px, py + 130)
  end
  g.print("circles: each NPC's target\nred heading line: touching", px, py + 170)
  g.print("Space: fast-forward\nR: rays on/off   Esc: quit", px, py + 220)
end
