# The scripted baseline: context steering a designer would write over the agents' own sensors and
# action branches (turn 0 left, 1 none, 2 right; move 0 stop, 1 forward), so both are measured
# alike; a simpler cousin of samples/scenes/ray_npc_steering.cpp.
extends Reference

const RaySensors = preload("res://ray_sensors.gd")
const LEFT = 0
const STRAIGHT = 1
const RIGHT = 2
const STOP = 0
const FORWARD = 1
const FREE = -1.0 / 3.0     # a ray reading: nothing within 1 m of a 3 m range
const SIDE = -0.85          # a side ray this close (about 0.2 m): shy away


# sensors: [[hazard], [8 rays right to left, bearing (/ PI, + left), distance, speed, turn]].
static func choose(sensors):
	var hazard = sensors[0][0]
	var s = sensors[1]
	if hazard == RaySensors.IN_HAZARD:         # walk out the way it faces
		return [STRAIGHT, FORWARD]
	if hazard == RaySensors.HAZARD_AHEAD:      # veer away from the target's side, walking on: turning
		return [RIGHT if s[8] > 0 else LEFT, FORWARD]   # in place here deadlocks against boxes
	var bearing = s[8] * PI
	if abs(bearing) > PI / 2:                 # the target is behind: turn in place
		return [LEFT if bearing > 0 else RIGHT, STOP]
	# The free ray closest to the target's bearing (either neighbour of it blocked: not straight there).
	var best = null
	for i in RaySensors.RAYS:
		var a = RaySensors.ray_angle(i)
		if s[i] > FREE and (best == null or abs(a - bearing) < abs(best - bearing)):
			best = a
	var step = PI / (RaySensors.RAYS - 1)
	var i = clamp(int(floor((bearing + PI / 2) / step)), 0, RaySensors.RAYS - 2)
	if s[i] > FREE and s[i + 1] > FREE:
		best = bearing
	if best == null:                           # boxed in: turn in place towards the open side
		return [LEFT if s[4] + s[5] + s[6] + s[7] > s[0] + s[1] + s[2] + s[3] else RIGHT, STOP]
	if s[0] < SIDE:
		best += 0.3
	elif s[7] < SIDE:
		best -= 0.3
	var turn = STRAIGHT
	if abs(best) > 0.1:
		turn = LEFT if best > 0 else RIGHT
	return [turn, FORWARD if abs(best) < 0.6 else STOP]
