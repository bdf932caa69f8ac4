-- steering.lua: the baseline, context steering as a designer would script it over the same sensors
-- and actions (the C++ ray-npc scene's script, samples/scenes/ray_npc_steering.cpp): head for the
-- target when the rays either side of its bearing are free, else along the free ray closest to
-- it, else turn to the most open ray; turn in place to a target behind; veer off the hazard ahead;
-- shy away from a wall brushing a side. One addition: a box between an NPC and its target traps
-- pure context steering (turn to the open side, turn back to the target, again), so a blocked NPC
-- commits to the more open side for DETOUR steps, as a designer's script would.
local rays = require "rays"
local world = require "world"

local CLEAR = 1.0                      -- m: a ray this open is a way to walk
local TURN_IN_PLACE = math.rad(50)     -- beyond this, walking would only circle
local STRAIGHT = math.rad(10)
local BRUSH = 0.2                      -- m: this close at the side is a scrape coming
local BLOCKED, DETOUR = 0.1, 20        -- m ahead that blocks; steps (0.1 s) of a detour
local L, N, R, STOP, GO = world.LEFT, world.NONE, world.RIGHT, world.STOP, world.FORWARD

return function(w, _, npc)
  local c, hits, n = npc.obs.continuous, npc.hits, rays.COUNT
  local bearing = c[n + 1] * math.pi
  local distance = (c[n + 2] + 1) / 2 * w.diagonal
  local function free(i) return hits[i] >= math.min(CLEAR, distance - world.REACH) end

  local desired, boxed_in = bearing, false
  if math.abs(bearing) <= rays.ARC / 2 then
    local best, open = nil, 1
    for i = 1, n do
      if hits[i] > hits[open] then open = i end
      if free(i) and (not best or math.cos(rays.angle(i) - bearing) > math.cos(rays.angle(best) - bearing)) then
        best = i
      end
    end
    local below = 1 -- the rays either side of the bearing: below and below + 1
    while below + 1 < n and rays.angle(below + 1) < bearing do below = below + 1 end
    if free(below) and free(below + 1) then desired = bearing
    elseif best then desired = rays.angle(best)
    else desired, boxed_in = rays.angle(open), true end
  end
  -- Blocked ahead (the two middle rays): pick the more open side once, and keep to it a while.
  if not npc.detour and math.min(hits[n / 2], hits[n / 2 + 1]) < BLOCKED then
    local left, right = 0, 0
    for i = 1, n / 2 do right, left = right + hits[i], left + hits[n + 1 - i] end
    npc.detour, npc.detour_side = DETOUR, left > right and 1 or -1
  end
  if npc.detour then
    local best -- the most open ray on the chosen side
    for i = 1, n do
      if rays.angle(i) * npc.detour_side > 0 and (not best or hits[i] > hits[best]) then best = i end
    end
    desired, boxed_in = rays.angle(best), false
    npc.detour = npc.detour > 1 and npc.detour - 1 or nil
  end

  local hazard = npc.obs.discrete[1]
  if hazard == world.INSIDE then -- keep walking: stopping to turn only keeps it inside longer
    if math.abs(desired) < STRAIGHT then return N, GO end
    return desired > 0 and L or R, GO
  end
  if hazard == world.HAZARD_AHEAD then -- turn off to the target's side: in place at speed (brakes)
    local side = bearing < -STRAIGHT and R or L
    return side, c[n + 3] > 0.3 and STOP or GO
  end
  if boxed_in or math.abs(desired) > TURN_IN_PLACE then return desired > 0 and L or R, STOP end
  local near_left, near_right = rays.RANGE, rays.RANGE
  for i = 1, n do
    local a = rays.angle(i)
    if a > STRAIGHT then near_left = math.min(near_left, hits[i]) end
    if a < -STRAIGHT then near_right = math.min(near_right, hits[i]) end
  end
  if near_right < BRUSH and near_right < near_left and desired <= STRAIGHT then return L, GO end
  if near_left < BRUSH and near_left < near_right and desired >= -STRAIGHT then return R, GO end
  if math.abs(desired) > STRAIGHT then return desired > 0 and L or R, GO end
  return N, GO
end
