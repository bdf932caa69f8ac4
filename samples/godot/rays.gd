# Ray-sensing NPCs: each senses the arena through 8 Godot physics raycasts (ray_sensors.gd) and
# acts with two action branches, turn {left, none, right} x move {stop, forward}, every learning
# setting at the library's default. Each fetches its own target (+1), pays -1 per decision step in
# the red hazard zone and -0.1 per step touching a wall or a box (bumping NPCs costs nothing): the
# sensors and rewards of samples/scenes/ray_npc.cpp (docs/scenes.md), in Godot's 2D physics.
#
#   godot3 --path build/godot/sample res://rays.tscn            play (Space: 8x speed)
#   godot3-server --path build/godot/sample --fixed-fps 60 res://rays.tscn --verve-test
#                 headless: per seed, the agents 15 simulated minutes, then the scripted steering
#                 (ray_steering.gd) 3 minutes in the same world; prints per-minute measures and
#                 checks the agents' reward (rays_test.gd). --verve-seeds=4,5 picks other worlds.
#   --verve-progress=2  also rewards 2 per metre an NPC closes on its target in a step (negative
#                 when it walks away; 0 by default): with it the agents learn to fetch, and the
#                 test checks their targets against the script's (docs/godot.md).
extends Node2D

const VerveAgent = preload("res://addons/verve/verve_agent.gdns")
const RaySensors = preload("res://ray_sensors.gd")
const RaySteering = preload("res://ray_steering.gd")
const RayMinutes = preload("res://ray_minutes.gd")

const M = 50.0                      # pixels per metre
const HALF_SIZE = 5.0 * M           # a 10 x 10 m arena around the origin
const HAZARD = Rect2(-1.0 * M, -1.0 * M, 2.0 * M, 2.0 * M)   # the red floor zone in the middle
const BOXES = [Rect2(-3.2 * M, -3.0 * M, 1.0 * M, 1.0 * M), Rect2(2.0 * M, -3.4 * M, 1.2 * M, 0.8 * M),
	Rect2(-3.0 * M, 2.2 * M, 0.8 * M, 1.2 * M), Rect2(2.2 * M, 2.0 * M, 1.0 * M, 1.0 * M),
	Rect2(-0.4 * M, -4.2 * M, 0.8 * M, 0.8 * M)]
const NPC_RADIUS = 0.3 * M
const REACH = 0.5 * M               # from an NPC's centre to its target
const SPEED = 2.0 * M               # pixels per second walking
const TURN_RATE = 3.0               # radians per second turning
const NPCS = 6
const WALL_LAYER = 2                # walls and boxes; NPCs are on layer 1
const DECISION_TICKS = 6            # a decision every 0.1 s at 60 Hz
const DT = DECISION_TICKS / 60.0
const TEST_MINUTES = 15
const SCRIPT_MINUTES = 3

var sensors = RaySensors.new(3.0 * M, NPC_RADIUS, 1.2 * M, 2.0 * sqrt(2.0) * HALF_SIZE)
var touch_query = Physics2DShapeQueryParameters.new()   # "touching a wall": the NPC's circle, 2 px larger
var touch_shape = CircleShape2D.new()                    # kept: the query holds only its RID
var npcs = []       # KinematicBody2D
var agents = []     # one VerveAgent each (none while the script drives)
var targets = []    # one position per NPC
var choices = []    # per NPC: [turn, move]
var speeds = []     # per NPC: forward speed / SPEED in the last physics tick
var rewards = []    # what each NPC's previous decision earned
var distances = []  # per NPC: metres to its target after the previous decision
var progress = 0.0  # reward per metre closed on the target (--verve-progress=)
var ray_view = []  # the yellow NPC's last ray readings, drawn
var rng = RandomNumberGenerator.new()
var ticks = 0
var measures = null
var testing = "--verve-test" in OS.get_cmdline_args()
var test_seeds = [1, 2, 3]
var test = preload("res://rays_test.gd").new()


func _ready():
	for arg in OS.get_cmdline_args():
		if arg.begins_with("--verve-seeds="):
			test_seeds = Array(arg.split("=")[1].split_floats(","))
		if arg.begins_with("--verve-progress="):
			progress = max(0.0, float(arg.split("=")[1]))
	add_box(Rect2(-HALF_SIZE - 20, -HALF_SIZE - 20, 2 * HALF_SIZE + 40, 20))   # the four walls
	add_box(Rect2(-HALF_SIZE - 20, HALF_SIZE, 2 * HALF_SIZE + 40, 20))
	add_box(Rect2(-HALF_SIZE - 20, -HALF_SIZE, 20, 2 * HALF_SIZE))
	add_box(Rect2(HALF_SIZE, -HALF_SIZE, 20, 2 * HALF_SIZE))
	for box in BOXES:
		add_box(box)
	touch_shape.radius = NPC_RADIUS + 2
	touch_query.set_shape(touch_shape)
	touch_query.collision_layer = WALL_LAYER
	position = Vector2(HALF_SIZE + 50, HALF_SIZE + 50)
	test.start(self)


func add_box(rect):
	var body = StaticBody2D.new()
	body.collision_layer = WALL_LAYER
	var shape = CollisionShape2D.new()
	shape.shape = RectangleShape2D.new()
	shape.shape.extents = rect.size / 2
	body.add_child(shape)
	body.position = rect.position + rect.size / 2
	add_child(body)


# New NPCs in a world made from the seed; learning agents, or none when the script drives.
func start_world(world, learning):
	for npc in npcs:
		npc.free()
	npcs.clear()
	agents.clear()
	targets.clear()
	choices.clear()
	speeds.clear()
	rewards.clear()
	distances.clear()
	rng.seed = world
	ticks = 0
	measures = RayMinutes.new(NPCS, int(60 / DT))
	var circular = [false, false, false, false, false, false, false, false, true, false, false, false]
	for i in NPCS:
		var npc = KinematicBody2D.new()
		npc.collision_mask = 1 | WALL_LAYER
		var shape = CollisionShape2D.new()
		shape.shape = CircleShape2D.new()
		shape.shape.radius = NPC_RADIUS
		npc.add_child(shape)
		npc.position = free_spot(Vector2(1e9, 1e9))
		npc.rotation = rng.randf_range(-PI, PI)
		add_child(npc)
		npcs.append(npc)
		targets.append(free_spot(npc.position))
		distances.append(npc.position.distance_to(targets[i]) / M)
		choices.append([1, 0])
		speeds.append(0.0)
		rewards.append(0.0)
		if learning:
			var agent = VerveAgent.new()
			# Only sensors, branches and a seed: every learning setting at the library's default.
			if not agent.create({"discrete_sensors": [3], "continuous_sensor_circular": circular,
					"action_branches": [3, 2], "seed": world * 100 + i}):
				get_tree().quit(1)   # the error is printed already
				return
			agents.append(agent)


# A spot clear of walls, boxes and the hazard, at least 2 m from `away`.
func free_spot(away):
	var edge = HALF_SIZE - 0.5 * M
	while true:
		var p = Vector2(rng.randf_range(-edge, edge), rng.randf_range(-edge, edge))
		var clear = not HAZARD.grow(0.5 * M).has_point(p) and p.distance_to(away) > 2.0 * M
		for box in BOXES:
			clear = clear and not box.grow(0.5 * M).has_point(p)
		if clear:
			return p


func touching_wall(npc):
	touch_query.transform = Transform2D(0, npc.global_position)
	return not get_world_2d().direct_space_state.intersect_shape(touch_query, 1).empty()


func _physics_process(delta):
	if measures == null:
		return
	if ticks % DECISION_TICKS == 0:
		decide()
	for i in NPCS:
		var npc = npcs[i]
		npc.rotation += (choices[i][0] - 1) * TURN_RATE * delta   # turn 0: left (counter-clockwise on screen)
		var heading = Vector2.RIGHT.rotated(npc.rotation)
		var velocity = Vector2.ZERO
		if choices[i][1] == 1:
			velocity = npc.move_and_slide(heading * SPEED)
		speeds[i] = velocity.dot(heading) / SPEED
	ticks += 1
	if testing:
		test.progress(self)
	else:
		update()


# Rewards what the last decision led to, then every NPC senses and decides again.
func decide():
	var space = get_world_2d().direct_space_state
	for i in NPCS:
		var npc = npcs[i]
		var distance = npc.position.distance_to(targets[i]) / M
		var fetched = distance < REACH / M
		var wall = touching_wall(npc)
		var hazard = HAZARD.has_point(npc.position)
		if ticks > 0:
			# Progress: its sum over any walk depends only on the walk's ends, so circling earns nothing.
			var closed = progress * (distances[i] - distance)
			rewards[i] = clamp(closed + int(fetched) - int(hazard) - 0.1 * int(wall), -1.0, 1.0)
			measures.add(int((ticks - 1) / 3600), fetched, wall, hazard, rewards[i])
		distances[i] = distance
		if fetched:
			targets[i] = free_spot(npc.position)
			distances[i] = npc.position.distance_to(targets[i]) / M   # a new target counts from here
		var sensed = sensors.read(space, npc, targets[i], HAZARD, speeds[i], 1 - choices[i][0])
		if i == 0:
			ray_view = sensed[1].slice(0, RaySensors.RAYS - 1)
		if agents.empty():
			choices[i] = RaySteering.choose(sensed)
		else:
			var action = agents[i].update(rewards[i], sensed[0], sensed[1], DT)
			if action < 0:
				get_tree().quit(1)
				return
			choices[i] = agents[i].split_action(action)


func _unhandled_input(event):
	if event.is_action_pressed("ui_accept"):
		var fast = Engine.time_scale == 1.0
		Engine.time_scale = 8.0 if fast else 1.0
		Engine.iterations_per_second = 480 if fast else 60


func _draw():
	draw_rect(Rect2(-HALF_SIZE, -HALF_SIZE, 2 * HALF_SIZE, 2 * HALF_SIZE), Color(0.2, 0.22, 0.25))
	draw_rect(HAZARD, Color(0.75, 0.2, 0.15))
	for box in BOXES:
		draw_rect(box, Color(0.55, 0.5, 0.45))
	for i in NPCS:
		var npc = npcs[i]
		var heading = Vector2.RIGHT.rotated(npc.rotation)
		for r in (ray_view.size() if i == 0 else 0):   # the yellow NPC's rays as it last saw them
			var d = RaySensors.to_left(heading, RaySensors.ray_angle(r))
			var from = npc.position + d * NPC_RADIUS
			draw_line(from, from + d * (ray_view[r] + 1.0) / 2.0 * sensors.ray_range, Color(1, 1, 1, 0.3))
		var colour = Color(1.0, 0.85, 0.3) if i == 0 else Color(0.35, 0.6, 1.0)
		draw_circle(targets[i], 7, colour.darkened(0.3))
		draw_circle(npc.position, NPC_RADIUS, colour)
		draw_line(npc.position, npc.position + heading * NPC_RADIUS * 1.6, colour, 3)
