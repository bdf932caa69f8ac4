-- rays.lua: an NPC's eyes, as a game casts them: a fan of rays over the front half, each the
-- distance from the NPC's surface to the first wall or box (the slab test against each
-- axis-aligned box). Other NPCs are not seen: they cost nothing to bump into.
local rays = {}

rays.COUNT, rays.ARC, rays.RANGE = 8, math.pi, 3 -- 8 rays over 180 degrees (25.7 apart), 3 m

-- Ray i's angle from the heading, right (-90 degrees) to left (+90), ends included.
function rays.angle(i)
  return -rays.ARC / 2 + (i - 1) * rays.ARC / (rays.COUNT - 1)
end

-- The distance t >= 0 along the unit direction (dx, dy) from (x, y) to box b, or nil if missed.
local function hit_box(x, y, dx, dy, b)
  local near, far = 0, math.huge
  for axis = 1, 2 do
    local o, d, c, h
    if axis == 1 then o, d, c, h = x, dx, b.x, b.hx else o, d, c, h = y, dy, b.y, b.hy end
    if math.abs(d) < 1e-12 then
      if math.abs(o - c) > h then return nil end -- parallel and outside this slab
    else
      local t1, t2 = (c - h - o) / d, (c + h - o) / d
      if t1 > t2 then t1, t2 = t2, t1 end
      near, far = math.max(near, t1), math.min(far, t2)
      if near > far then return nil end
    end
  end
  return near
end
rays.hit_box = hit_box

-- Distance from the surface of a disc of `radius` at (x, y) along angle a, at most RANGE.
function rays.cast(solids, x, y, a, radius)
  local dx, dy = math.cos(a), math.sin(a)
  local best = radius + rays.RANGE
  for _, b in ipairs(solids) do
    local t = hit_box(x, y, dx, dy, b)
    if t and t < best then best = t end
  end
  return math.max(0, best - radius)
end

-- All COUNT readings into `out` (metres), for an NPC heading at angle `heading`.
function rays.fan(solids, x, y, heading, radius, out)
  for i = 1, rays.COUNT do out[i] = rays.cast(solids, x, y, heading + rays.angle(i), radius) end
  return out
end

return rays
