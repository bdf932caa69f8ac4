# A crowd of NPCs that learn together: one brain, many bodies, one batch update per decision.
extends Node

const VerveBrain = preload("res://addons/verve/verve_brain.gdns")
const VerveBatch = preload("res://addons/verve/verve_batch.gdns")
const COUNT = 100
var brain = VerveBrain.new()
var batch = VerveBatch.new()
var npcs = []                        # VerveAgents: bodies of the brain
var positions = PoolVector2Array()   # draw them however the game does
var headings = PoolRealArray()
var rewards = PoolRealArray()        # earned by each NPC's current action
var actions = PoolIntArray()
var target = Vector2(250, 250)
var clock = 0.0

func _ready():
	if not brain.load("user://crowd.xml"):  # the saved brain continues learning; else a new one
		brain.create({"continuous_sensor_circular": [true, false], "actions": 3, "seed": 1})
	batch.create(2)                  # 2 threads, the calling one included (0: one per core)
	for i in COUNT:
		npcs.append(brain.create_body())
		positions.append(Vector2(randf(), randf()) * 500.0)
		headings.append(randf() * TAU)
		rewards.append(0.0)
		actions.append(0)

func _physics_process(delta):
	clock += delta
	if clock >= 0.1:                 # all NPCs decide, 10 times a second, in one call
		var sensors = PoolRealArray()  # bearing and distance to the target, NPC after NPC
		for i in COUNT:
			var to_target = target - positions[i]
			sensors.append(Vector2.RIGHT.rotated(headings[i]).angle_to(to_target) / PI)
			sensors.append(min(to_target.length() / 500.0, 1.0) * 2.0 - 1.0)
		var chosen = batch.update(npcs, rewards, null, sensors, clock)
		if chosen != null:           # null: an error was printed, nothing changed
			actions = chosen
		for i in COUNT:
			rewards[i] = 0.0
		clock = 0.0
	for i in COUNT:
		match actions[i]:
			0: positions[i] += Vector2.RIGHT.rotated(headings[i]) * 100.0 * delta
			1: headings[i] -= 3.0 * delta
			2: headings[i] += 3.0 * delta
		if positions[i].distance_to(target) < 20.0:
			rewards[i] = 1.0
			positions[i] = Vector2(randf(), randf()) * 500.0

func _exit_tree():
	brain.save("user://crowd.xml")
