# An NPC that learns, while the game runs, to walk to a target: attach to a KinematicBody2D.
extends KinematicBody2D

const VerveAgent = preload("res://addons/verve/verve_agent.gdns")
export var target_path: NodePath     # any Node2D: food, the player, a door
var agent = VerveAgent.new()
var action = 0
var reward = 0.0                     # earned by the current action, handed over at the next update
var clock = 0.0

func _ready():
	# Two continuous sensors in [-1, 1]: bearing (circular: -1 and 1 both mean "behind") and
	# distance. Three actions: 0 walk, 1 turn left, 2 turn right.
	if not agent.load("user://npc.xml"):  # a saved brain continues learning; else a new one
		agent.create({"continuous_sensor_circular": [true, false], "actions": 3, "seed": 1})

func _physics_process(delta):
	var target = get_node(target_path)
	clock += delta
	if clock >= 0.1:                 # decide 10 times a second
		var to_target = target.position - position
		var bearing = Vector2.RIGHT.rotated(rotation).angle_to(to_target) / PI
		var distance = min(to_target.length() / 500.0, 1.0) * 2.0 - 1.0
		action = agent.update(reward, [], [bearing, distance], clock)
		reward = 0.0
		clock = 0.0
	match action:
		0: move_and_slide(Vector2.RIGHT.rotated(rotation) * 100.0)
		1: rotation -= 3.0 * delta
		2: rotation += 3.0 * delta
	if position.distance_to(target.position) < 20.0:
		reward = 1.0
		target.position = Vector2(randf(), randf()) * 500.0

func _exit_tree():
	agent.save("user://npc.xml")
