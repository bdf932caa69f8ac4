-- main.lua: NPCs that learn, in LÖVE 11 (love.physics is Box2D).
-- Eight round NPCs share a walled 10 x 10 m arena with three pieces of food and a hazard disc in
-- the middle. Each NPC has its own Verve agent and is never told how to steer: it senses the
-- hazard (clear / ahead / inside), the bearing and the distance to the nearest food, and picks one
-- of three actions: thrust forward, turn one way, turn the other. Eating earns +1, each step inside
-- the hazard -1. In 20 simulated minutes they come to eat about four times as often.
--
-- The right panel is the selected NPC's value function V(bearing, distance) with the hazard
-- clear: what it expects to earn from there (red high, blue low), redrawn every second.
-- Keys: Tab selects the next NPC, Space fast-forwards (x20), Esc quits. The brains are saved in
-- the save directory on quit and loaded on start, so a restarted game continues.
--
-- Ship it as docs/lua.md says: verve.so and libverve.so.0 beside verve-npcs.love, then
--   love verve-npcs.love [--headless] [--minutes N] [--fresh] [--seed N] [--screenshot FILE]
-- --headless     no window (conf.lua); with --minutes, trains as fast as the machine goes
-- --minutes N    run N simulated minutes flat out, print food per NPC-minute, save and quit
-- --fresh        start from new brains even if saved ones exist
-- --seed N       decides starts, food places and each agent's random stream (default 1)
-- --screenshot F at the end of --minutes, save the window as F in the save directory

-- Native modules cannot load from inside a .love archive: verve.so (verve.dll) ships beside it.
local base = love.filesystem.getSourceBaseDirectory()
package.cpath = base .. "/?.so;" .. base .. "/?.dll;" .. package.cpath
local verve = require "verve"

local ARENA = 10                        -- m, walls all round; the origin is the centre
local NPCS, FOOD = 8, 3
local NPC_RADIUS, EAT_RADIUS = 0.3, 0.5 -- m
local HAZARD_RADIUS, AHEAD = 1.6, 1.2   -- m; the hazard sensor looks AHEAD metres forward
local SPEED, TURN_RATE = 2, 3           -- m/s and rad/s that full thrust and torque reach
local DRAG = 4.6                        -- 1/s, Box2D damping: it balances full thrust at SPEED
local STEP, SUBSTEPS = 0.1, 5           -- s per decision; physics steps per decision
local STEPS_PER_MINUTE = 600
local SCALE, MAP = 50, 32               -- pixels per metre; value-map samples per axis

local options = { seed = 1 }
local world, rng
local npcs, food = {}, {}
local selected, fast = 1, false
local steps, pending = 0, 0             -- decisions taken; real seconds not simulated yet
local minute = { food = 0, hazard = 0 } -- this simulated minute, summed over the NPCs
local history = {}                      -- per finished minute: { food = per NPC, hazard = share }
local heat = {}                         -- the value map: ImageData, Image and its range

-- The map sweeps bearing (x) and distance (y) with the hazard sensor reading "clear".
local MAP_AXES = { { kind = "continuous", index = 1, samples = MAP },
                   { kind = "continuous", index = 2, samples = MAP } }
local MAP_BASE = { discrete = { 1 }, continuous = { 0, 0 } }

local function in_hazard(x, y) return x * x + y * y < HAZARD_RADIUS ^ 2 end

local function free_spot()
  local edge = ARENA / 2 - 0.5
  while true do
    local x, y = rng:random() * 2 * edge - edge, rng:random() * 2 * edge - edge
    if math.sqrt(x * x + y * y) > HAZARD_RADIUS + 0.5 then return x, y end
  end
end

local function nearest_food(x, y)
  local best, best_d = nil, math.huge
  for _, f in ipairs(food) do
    local d = math.sqrt((f.x - x) ^ 2 + (f.y - y) ^ 2)
    if d < best_d then best, best_d = f, d end
  end
  return best, best_d
end

-- Sensors, all in the agent's range: a discrete value 1..3 and two continuous ones in [-1, 1].
local function sense(npc)
  local x, y = npc.body:getPosition()
  local a = npc.body:getAngle()
  local hx, hy = math.cos(a), math.sin(a)
  local f, d = nearest_food(x, y)
  local tx, ty = f.x - x, f.y - y
  npc.obs.discrete[1] = in_hazard(x, y) and 3 or in_hazard(x + hx * AHEAD, y + hy * AHEAD) and 2 or 1
  -- Bearing: the signed angle from the heading to the food, scaled to [-1, 1]; the sensor is
  -- circular, so food just behind on either side (-1 and 1) reads as neighbours.
  npc.obs.continuous[1] = math.atan2(hx * ty - hy * tx, hx * tx + hy * ty) / math.pi
  npc.obs.continuous[2] = 2 * d / (ARENA * math.sqrt(2)) - 1 -- 0 .. the diagonal
end

local function brain_file(i) return ("npc%d.xml"):format(i) end

-- A saved brain, or nil: love.filesystem reads from the save directory.
local function load_brain(i)
  local xml = love.filesystem.read(brain_file(i))
  if not xml then return nil end
  local ok, agent = pcall(verve.load_string, xml)
  if ok then return agent end
  print(("%s is not a usable brain (%s): this NPC starts fresh"):format(brain_file(i), agent))
end

local function save_brains()
  for i, npc in ipairs(npcs) do
    local ok, err = love.filesystem.write(brain_file(i), npc.agent:save_string())
    if not ok then print("saving " .. brain_file(i) .. " failed: " .. tostring(err)) end
  end
end

local function new_world()
  love.physics.setMeter(1) -- Box2D units are metres
  world = love.physics.newWorld(0, 0, true) -- seen from above: no gravity
  local h = ARENA / 2
  local walls = love.physics.newBody(world, 0, 0, "static")
  love.physics.newFixture(walls, love.physics.newChainShape(true, -h, -h, h, -h, h, h, -h, h))

  local loaded = 0
  for i = 1, NPCS do
    local x, y = free_spot()
    local body = love.physics.newBody(world, x, y, "dynamic")
    love.physics.newFixture(body, love.physics.newCircleShape(NPC_RADIUS))
    body:setAngle(rng:random() * 2 * math.pi)
    body:setLinearDamping(DRAG)
    body:setAngularDamping(DRAG)
    local agent = not options.fresh and load_brain(i)
    if agent then
      loaded = loaded + 1
    else
      agent = verve.agent {
        discrete = { 3 },                       -- hazard: clear, ahead, inside
        continuous = { { circular = true }, {} }, -- bearing to the nearest food, distance to it
        actions = 3,                            -- forward, turn, turn the other way
        resolution = 8,
        tau_discount = 2,    -- food is seconds away: look further ahead than the default 1 s
        tau_eligibility = 0.3,
        seed = options.seed * 1000 + i,
      }
    end
    npcs[i] = { body = body, agent = agent, reward = 0, action = 1,
                obs = { discrete = { 1 }, continuous = { 0, 0 } } }
  end
  for i = 1, FOOD do
    local x, y = free_spot()
    food[i] = { x = x, y = y }
  end
  print(("verve %s on %s: %d NPCs, %d brains loaded from %s"):format(verve.version(), jit and jit.version
    or _VERSION, NPCS, loaded, love.filesystem.getSaveDirectory()))
end

local function finish_minute()
  history[#history + 1] = { food = minute.food / NPCS, hazard = minute.hazard / (NPCS * 60) }
  minute.food, minute.hazard = 0, 0
  if options.minutes then
    local m = history[#history]
    print(("minute %3d  food per NPC-minute %5.2f  time in hazard %5.1f%%"):format(#history, m.food,
      100 * m.hazard))
  end
end

-- One decision for every NPC: sense, act, simulate, reward.
local function step()
  for _, npc in ipairs(npcs) do
    sense(npc)
    npc.action = npc.agent:update(npc.reward, npc.obs, STEP) -- the reward the last action earned
  end
  for _ = 1, SUBSTEPS do -- Box2D clears forces after each step: push again every sub-step
    for _, npc in ipairs(npcs) do
      local b = npc.body
      if npc.action == 1 then
        local a, f = b:getAngle(), b:getMass() * DRAG * SPEED
        b:applyForce(f * math.cos(a), f * math.sin(a))
      else
        b:applyTorque((npc.action == 2 and -1 or 1) * b:getInertia() * DRAG * TURN_RATE)
      end
    end
    world:update(STEP / SUBSTEPS)
  end
  for _, npc in ipairs(npcs) do
    local x, y = npc.body:getPosition()
    local f, d = nearest_food(x, y)
    npc.reward = 0
    if d < EAT_RADIUS then
      f.x, f.y = free_spot() -- eaten: it reappears elsewhere
      npc.reward = 1
      minute.food = minute.food + 1
    end
    if in_hazard(x, y) then
      npc.reward = -1
      minute.hazard = minute.hazard + STEP
    end
  end
  steps = steps + 1
  if steps % STEPS_PER_MINUTE == 0 then finish_minute() end
end

-- Samples the selected NPC's V over bearing x distance into the heat-map image.
local function refresh_value_map()
  if not love.graphics then return end
  local v = npcs[selected].agent:sample_values(MAP_AXES, MAP_BASE)
  local lo, hi = math.huge, -math.huge
  for i = 1, MAP do
    for j = 1, MAP do lo, hi = math.min(lo, v[i][j]), math.max(hi, v[i][j]) end
  end
  for i = 1, MAP do
    for j = 1, MAP do
      local t = hi > lo and (v[i][j] - lo) / (hi - lo) or 0.5
      heat.data:setPixel(i - 1, MAP - j, t, 0.25 * (1 - math.abs(2 * t - 1)), 1 - t, 1) -- near at the bottom
    end
  end
  heat.image:replacePixels(heat.data)
  heat.lo, heat.hi = lo, hi
end

local function mean(from, to, field)
  local sum = 0
  for m = from, to do sum = sum + history[m][field] end
  return sum / (to - from + 1)
end

-- The --minutes report: learning shows as more food and less hazard late than early.
local function report()
  local n = #history
  local k = math.max(1, math.floor(n / 4)) -- the first and the last quarter
  print(("food per NPC-minute: minutes 1-%d %.2f, minutes %d-%d %.2f, all %d %.2f"):format(k,
    mean(1, k, "food"), n - k + 1, n, mean(n - k + 1, n, "food"), n, mean(1, n, "food")))
  print(("time in hazard %%: minutes 1-%d %.1f, minutes %d-%d %.1f, all %d %.1f"):format(k,
    100 * mean(1, k, "hazard"), n - k + 1, n, 100 * mean(n - k + 1, n, "hazard"), n, 100 * mean(1, n, "hazard")))
end

-- The end of a --minutes run: report, save, and quit (after the screenshot, if one is wanted).
local function finish_run()
  report()
  save_brains()
  if not options.screenshot then return love.event.quit(0) end
  love.graphics.captureScreenshot(function(image) -- called once the next frame is drawn
    image:encode("png", options.screenshot)
    print("screenshot: " .. love.filesystem.getSaveDirectory() .. "/" .. options.screenshot)
    love.event.quit(0)
  end)
end

function love.load(args)
  local i = 1
  while args[i] do
    local a, value = args[i], tonumber(args[i + 1])
    if a == "--minutes" and value then options.minutes, i = math.floor(value), i + 1
    elseif a == "--seed" and value then options.seed, i = math.floor(value), i + 1
    elseif a == "--screenshot" and args[i + 1] then options.screenshot, i = args[i + 1], i + 1
    elseif a == "--fresh" then options.fresh = true
    elseif a ~= "--headless" then error("unknown argument " .. a .. " (see the top of main.lua)") end
    i = i + 1
  end
  if not love.graphics and not options.minutes then error("--headless needs --minutes N") end
  rng = love.math.newRandomGenerator(options.seed)
  new_world()
  if love.graphics then
    heat.data = love.image.newImageData(MAP, MAP)
    heat.image = love.graphics.newImage(heat.data)
    heat.image:setFilter("linear", "nearest")
    refresh_value_map()
  end
end

function love.update(dt)
  if options.minutes then -- flat out: one simulated minute per frame
    if #history < options.minutes then
      for _ = 1, STEPS_PER_MINUTE do step() end
      refresh_value_map()
      if #history == options.minutes then finish_run() end
    end
    return
  end
  pending = math.min(pending + dt * (fast and 20 or 1), 1) -- never more than 1 s behind
  while pending >= STEP do
    step()
    pending = pending - STEP
    if steps % 10 == 0 then refresh_value_map() end
  end
end

function love.keypressed(key)
  if key == "tab" then selected = selected % NPCS + 1; refresh_value_map()
  elseif key == "space" then fast = not fast
  elseif key == "escape" then love.event.quit() end
end

function love.quit()
  if not options.minutes then save_brains() end -- --minutes saved already
  for _, npc in ipairs(npcs) do npc.agent:close() end -- LuaJIT has no <close>: free them now
end

local COLOURS = { { 0.95, 0.8, 0.3 }, { 0.4, 0.8, 1 }, { 1, 0.55, 0.8 }, { 0.7, 1, 0.5 },
                  { 1, 0.65, 0.35 }, { 0.75, 0.6, 1 }, { 0.5, 1, 0.9 }, { 1, 1, 1 } }

function love.draw()
  local g = love.graphics
  g.clear(0.08, 0.08, 0.1)
  g.push()
  g.translate(10 + ARENA / 2 * SCALE, 10 + ARENA / 2 * SCALE)
  g.scale(SCALE)
  g.setLineWidth(2 / SCALE)
  g.setColor(0.16, 0.17, 0.2)
  g.rectangle("fill", -ARENA / 2, -ARENA / 2, ARENA, ARENA)
  g.setColor(0.85, 0.2, 0.15, 0.6)
  g.circle("fill", 0, 0, HAZARD_RADIUS, 48)
  g.setColor(0.3, 0.9, 0.3)
  for _, f in ipairs(food) do g.circle("fill", f.x, f.y, 0.15, 16) end
  for i, npc in ipairs(npcs) do
    local x, y = npc.body:getPosition()
    local a = npc.body:getAngle()
    g.setColor(COLOURS[(i - 1) % #COLOURS + 1])
    g.circle("fill", x, y, NPC_RADIUS, 24)
    g.setColor(0, 0, 0)
    g.line(x, y, x + math.cos(a) * NPC_RADIUS, y + math.sin(a) * NPC_RADIUS)
    if i == selected then
      g.setColor(1, 1, 1)
      g.circle("line", x, y, NPC_RADIUS + 0.12, 24)
    end
  end
  g.pop()

  local px, py, size = 540, 30, 256
  g.setColor(1, 1, 1)
  g.print(("NPC %d: value V(bearing, distance)"):format(selected), px, py - 22)
  g.draw(heat.image, px, py, 0, size / MAP, size / MAP)
  g.print("food: behind  left   ahead   right  behind", px, py + size + 4)
  g.print("distance: near (bottom) to far (top)", px, py + size + 22)
  g.print(("V from %.2f (blue) to %.2f (red)"):format(heat.lo or 0, heat.hi or 0), px, py + size + 40)
  local last = history[#history]
  g.print(("simulated %d:%02d%s"):format(math.floor(steps / STEPS_PER_MINUTE),
    math.floor(steps % STEPS_PER_MINUTE / 10),
    fast and "  (fast-forward)" or ""), px, py + size + 76)
  g.print(("food per NPC-minute, last minute: %s"):format(last and ("%.2f"):format(last.food) or "-"),
    px, py + size + 94)
  g.print(("time in hazard, last minute: %s"):format(last and ("%.1f%%"):format(100 * last.hazard) or "-"),
    px, py + size + 112)
  g.print("Tab: next NPC   Space: fast-forward   Esc: quit", px, py + size + 148)
end
