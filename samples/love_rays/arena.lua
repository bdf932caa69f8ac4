-- arena.lua: where things are, drawn from the seed: walls round a 10 x 10 m floor, a few square
-- boxes, a hazard disc. Plain 2D geometry (the C++ ray-npc scene's layout, docs/scenes.md), so the
-- game needs no love.physics: rays (rays.lua) and bodies (world.lua) only ask it questions.
local arena = {}
arena.__index = arena

local HALF = 5                      -- m; walls at +-HALF on x and y
local BOXES, MIN_HALF, MAX_HALF = 5, 0.3, 0.6
local PASSAGE = 0.9                 -- m kept free between boxes, walls and the hazard: wider than an NPC
local HAZARD_RADIUS = 1.2
local WALL = 0.5                    -- the walls are boxes too, WALL thick, so one ray test fits all

-- Distance from (x, y) to a box's surface; negative inside.
local function box_distance(x, y, b)
  local dx, dy = math.abs(x - b.x) - b.hx, math.abs(y - b.y) - b.hy
  if dx <= 0 and dy <= 0 then return math.max(dx, dy) end
  return math.sqrt(math.max(dx, 0) ^ 2 + math.max(dy, 0) ^ 2)
end
arena.box_distance = box_distance

function arena.new(rng)
  local self = setmetatable({ half = HALF, hazard_radius = HAZARD_RADIUS, boxes = {}, solids = {} }, arena)
  local reach = HALF - HAZARD_RADIUS - PASSAGE -- the way round the hazard stays open
  self.hx, self.hy = rng:random() * 2 * reach - reach, rng:random() * 2 * reach - reach
  while #self.boxes < BOXES do
    local h = MIN_HALF + rng:random() * (MAX_HALF - MIN_HALF)
    local edge = HALF - PASSAGE - h
    local b = { x = rng:random() * 2 * edge - edge, y = rng:random() * 2 * edge - edge, hx = h, hy = h }
    local ok = box_distance(self.hx, self.hy, b) >= HAZARD_RADIUS + PASSAGE
    for _, o in ipairs(self.boxes) do -- apart when the gap along x or along y is a passage wide
      local gap = math.max(math.abs(o.x - b.x) - o.hx - b.hx, math.abs(o.y - b.y) - o.hy - b.hy)
      if gap < PASSAGE then ok = false end
    end
    if ok then self.boxes[#self.boxes + 1] = b end
  end
  local w = HALF + WALL / 2
  local long = HALF + WALL
  self.solids = { { x = w, y = 0, hx = WALL / 2, hy = long }, { x = -w, y = 0, hx = WALL / 2, hy = long },
                  { x = 0, y = w, hx = long, hy = WALL / 2 }, { x = 0, y = -w, hx = long, hy = WALL / 2 } }
  for _, b in ipairs(self.boxes) do self.solids[#self.solids + 1] = b end
  return self
end

function arena:in_hazard(x, y)
  return (x - self.hx) ^ 2 + (y - self.hy) ^ 2 < self.hazard_radius ^ 2
end

-- Distance to the nearest wall or box surface.
function arena:clearance(x, y)
  local d = math.huge
  for _, b in ipairs(self.solids) do d = math.min(d, box_distance(x, y, b)) end
  return d
end

-- A random spot `clear` m from every solid, `gap` m outside the hazard and `apart` m from (ox, oy).
function arena:free_spot(rng, clear, gap, ox, oy, apart)
  local edge = HALF - clear
  for _ = 1, 10000 do
    local x, y = rng:random() * 2 * edge - edge, rng:random() * 2 * edge - edge
    if self:clearance(x, y) >= clear and math.sqrt((x - self.hx) ^ 2 + (y - self.hy) ^ 2) >= self.hazard_radius + gap
        and (not ox or math.sqrt((x - ox) ^ 2 + (y - oy) ^ 2) >= apart) then
      return x, y
    end
  end
  error("arena: no free spot left")
end

-- Pushes a disc of radius r at (x, y) out of every solid; returns the new centre and whether it
-- touched one (a wall contact: the NPC slides along instead of passing through).
function arena:push_out(x, y, r)
  local touched = false
  for _, b in ipairs(self.solids) do
    -- The box's closest point to the centre; inside the box, the nearest face's.
    local cx = math.max(b.x - b.hx, math.min(x, b.x + b.hx))
    local cy = math.max(b.y - b.hy, math.min(y, b.y + b.hy))
    local dx, dy = x - cx, y - cy
    local d = math.sqrt(dx * dx + dy * dy)
    if d < r + 0.01 then -- within 1 cm counts as touching
      touched = true
      if d < r then
        if d > 1e-9 then
          x, y = cx + dx / d * r, cy + dy / d * r
        else -- centre inside the box: out through the nearest face
          local ex, ey = b.hx - math.abs(x - b.x), b.hy - math.abs(y - b.y)
          if ex < ey then x = b.x + (x >= b.x and 1 or -1) * (b.hx + r)
          else y = b.y + (y >= b.y and 1 or -1) * (b.hy + r) end
        end
      end
    end
  end
  return x, y, touched
end

return arena
