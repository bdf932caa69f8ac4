# What a ray NPC senses, as samples/scenes/ray_npc.cpp does it, through Godot's own physics: 8 ray
# distances over the front half (right to left), bearing and distance to its target, forward speed,
# turn rate, and a discrete hazard flag (a floor zone the rays cannot see, so it has its own sensor).
extends Reference

const RAYS = 8
enum { CLEAR, HAZARD_AHEAD, IN_HAZARD }

var ray_range       # pixels from the NPC's surface
var npc_radius
var look_ahead      # where the hazard flag looks
var diagonal        # the arena's diagonal: distances divide by it


func _init(range_px, radius, ahead, arena_diagonal):
	ray_range = range_px
	npc_radius = radius
	look_ahead = ahead
	diagonal = arena_diagonal


# Ray i's angle from the heading, positive to the left: -90 deg (right) .. +90 deg (left).
static func ray_angle(i):
	return -PI / 2 + i * PI / (RAYS - 1)


# A direction `angle` to the left of the heading. Godot's y points down, so left is a negative rotation.
static func to_left(heading, angle):
	return heading.rotated(-angle)


# Distance from the NPC's surface to the first body (wall, box or NPC) along the ray, at most the
# range. Cast from the centre: a ray that starts inside a shape (an NPC against a wall) misses it.
# The space works in global coordinates (the arena's node is moved to the screen's centre).
func cast(space, npc, direction):
	var from = npc.global_position
	var hit = space.intersect_ray(from, from + direction * (npc_radius + ray_range), [npc])
	if hit.empty():
		return ray_range
	return clamp(from.distance_to(hit.position) - npc_radius, 0.0, ray_range)


# [[hazard], [8 rays, bearing, distance, speed, turn]], each continuous value in [-1, 1].
# speed: forward pixels per second / top speed; turn: +1 turning left, -1 right.
func read(space, npc, target, hazard, speed, turn):
	var heading = Vector2.RIGHT.rotated(npc.rotation)
	var continuous = []
	for i in RAYS:
		continuous.append(2.0 * cast(space, npc, to_left(heading, ray_angle(i))) / ray_range - 1.0)
	var to_target = target - npc.position
	continuous.append(-heading.angle_to(to_target) / PI)   # circular: -1 and 1 both mean "behind"
	continuous.append(2.0 * to_target.length() / diagonal - 1.0)
	continuous.append(clamp(speed, -1.0, 1.0))
	continuous.append(turn)
	var flag = CLEAR
	if hazard.has_point(npc.position):
		flag = IN_HAZARD
	elif hazard.has_point(npc.position + heading * look_ahead):
		flag = HAZARD_AHEAD
	return [[flag], continuous]
