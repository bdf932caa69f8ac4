-- world.lua: NPCs in the arena: their bodies (a disc that walks forward and turns, drag-limited),
-- their sensors, their rewards and the measures a minute of play is judged by. Who decides is a
-- `driver`: the NPCs' own Verve agents, the scripted steering (steering.lua) or a random policy.
local arena = require "arena"
local rays = require "rays"

local world = {}
world.__index = world

world.NPCS = 6
world.STEP, world.SUBSTEPS = 0.1, 5        -- s per decision; movement steps per decision
world.STEPS_PER_MINUTE = 600
world.RADIUS, world.REACH = 0.3, 0.5       -- m: an NPC's disc; centre to target that counts as reached
local SPEED, TURN_RATE, DRAG = 2, 3, 4.6   -- m/s, rad/s reached at full thrust / torque; 1/s
local AHEAD = 1.2                          -- m; where the hazard sensor looks
local WALL_PENALTY = 0.1                   -- per step touching: 10 s of scraping costs one target
world.SPEED, world.TURN_RATE = SPEED, TURN_RATE
world.LEFT, world.NONE, world.RIGHT = 1, 2, 3 -- branch 1, turn
world.STOP, world.FORWARD = 1, 2              -- branch 2, move
world.CLEAR, world.HAZARD_AHEAD, world.INSIDE = 1, 2, 3

-- The sensors and the two action branches; every learning setting at the library's default.
function world.descriptor(seed)
  local continuous = {}
  for i = 1, rays.COUNT do continuous[i] = {} end           -- rays, right to left: neighbours
  continuous[#continuous + 1] = { circular = true }         -- bearing to the target
  for _ = 1, 3 do continuous[#continuous + 1] = {} end      -- distance to it, speed, turn rate
  return { discrete = { 3 }, continuous = continuous, action_branches = { 3, 2 }, seed = seed }
end

-- `driver(world, i, npc)` returns the turn and move choices; `new_agent(i)`, if given, makes NPC
-- i's agent (the world closes them). The seed decides the arena, the starts and the targets.
-- `progress` (default 0): reward per metre an NPC closes on its target in a step, negative when it
-- walks away; its sum over any walk depends only on where the walk began and ended, so circling
-- earns nothing. What a designer adds when arrival alone is too rare to learn from (docs/lua.md).
function world.new(seed, driver, new_agent, progress)
  local self = setmetatable({ rng = love.math.newRandomGenerator(seed), driver = driver, npcs = {},
                              history = {}, steps = 0, progress = progress or 0 }, world)
  self.arena = arena.new(self.rng)
  self.diagonal = 2 * math.sqrt(2) * self.arena.half
  for i = 1, world.NPCS do
    local x, y = self.arena:free_spot(self.rng, world.RADIUS + 0.3, 0.5)
    local npc = { x = x, y = y, a = self.rng:random() * 2 * math.pi, v = 0, w = 0, reward = 0,
                  turn = world.NONE, move = world.STOP, hits = {},
                  obs = { discrete = { 1 }, continuous = {} } }
    npc.agent = new_agent and new_agent(i)
    npc.tx, npc.ty = self.arena:free_spot(self.rng, 0.5, 0.3, x, y, 2)
    npc.distance = math.sqrt((npc.tx - x) ^ 2 + (npc.ty - y) ^ 2)
    self.npcs[i] = npc
  end
  self:clear_minute()
  return self
end

function world:clear_minute() self.minute = { targets = 0, wall = 0, hazard = 0, reward = 0 } end

-- Sensors, each in [-1, 1]: hazard (discrete), 8 rays, bearing, distance, speed, turn rate.
function world:sense(npc)
  local ar = self.arena
  local ca, sa = math.cos(npc.a), math.sin(npc.a)
  npc.obs.discrete[1] = ar:in_hazard(npc.x, npc.y) and world.INSIDE
    or ar:in_hazard(npc.x + ca * AHEAD, npc.y + sa * AHEAD) and world.HAZARD_AHEAD or world.CLEAR
  local c = npc.obs.continuous
  rays.fan(ar.solids, npc.x, npc.y, npc.a, world.RADIUS, npc.hits)
  for i = 1, rays.COUNT do c[i] = 2 * npc.hits[i] / rays.RANGE - 1 end
  local dx, dy = npc.tx - npc.x, npc.ty - npc.y
  local n = rays.COUNT
  c[n + 1] = math.atan2(ca * dy - sa * dx, ca * dx + sa * dy) / math.pi -- positive: to the left
  c[n + 2] = 2 * math.sqrt(dx * dx + dy * dy) / self.diagonal - 1
  c[n + 3] = math.max(-1, math.min(1, npc.v / SPEED))
  c[n + 4] = math.max(-1, math.min(1, npc.w / TURN_RATE))
end

-- One decision for every NPC: sense, decide, move, reward.
function world:step()
  local m, ar, dt = self.minute, self.arena, world.STEP / world.SUBSTEPS
  local keep = math.exp(-DRAG * dt) -- drag: what is left of the gap to full speed after dt
  for i, npc in ipairs(self.npcs) do
    self:sense(npc)
    npc.turn, npc.move = self.driver(self, i, npc)
  end
  for _, npc in ipairs(self.npcs) do
    local v_goal = npc.move == world.FORWARD and SPEED or 0
    local w_goal = npc.turn == world.LEFT and TURN_RATE or npc.turn == world.RIGHT and -TURN_RATE or 0
    local touched = false
    for _ = 1, world.SUBSTEPS do
      npc.v = v_goal + (npc.v - v_goal) * keep
      npc.w = w_goal + (npc.w - w_goal) * keep
      npc.a = npc.a + npc.w * dt
      local t
      npc.x, npc.y, t = ar:push_out(npc.x + math.cos(npc.a) * npc.v * dt, npc.y + math.sin(npc.a) * npc.v * dt,
                                    world.RADIUS)
      touched = touched or t
    end
    local distance = math.sqrt((npc.tx - npc.x) ^ 2 + (npc.ty - npc.y) ^ 2)
    local r = self.progress * (npc.distance - distance)
    if distance < world.REACH then
      npc.tx, npc.ty = ar:free_spot(self.rng, 0.5, 0.3, npc.x, npc.y, 2) -- a new one, a walk away
      m.targets, r = m.targets + 1, r + 1
      distance = math.sqrt((npc.tx - npc.x) ^ 2 + (npc.ty - npc.y) ^ 2) -- the new one counts from here
    end
    npc.distance = distance
    if ar:in_hazard(npc.x, npc.y) then m.hazard, r = m.hazard + world.STEP, r - 1 end
    if touched then m.wall, r = m.wall + world.STEP, r - WALL_PENALTY end
    npc.reward = math.max(-1, math.min(1, r)) -- the agent gets it with its next decision
    npc.touching = touched
    m.reward = m.reward + npc.reward
  end
  self.steps = self.steps + 1
  if self.steps % world.STEPS_PER_MINUTE == 0 then
    local n = world.NPCS
    self.history[#self.history + 1] = { targets = m.targets / n, wall = m.wall / (60 * n),
                                        hazard = m.hazard / (60 * n), reward = m.reward / n }
    self:clear_minute()
  end
end

function world:close()
  for _, npc in ipairs(self.npcs) do if npc.agent then npc.agent:close() end end
end

return world
