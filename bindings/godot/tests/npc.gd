# The line NPC without the node: VerveAgent itself, the decision rule written out. Attach to a Node2D.
extends Node2D

const VerveAgent = preload("res://addons/verve/verve_agent.gdns")
const SAVE = "user://line_npc.xml"
signal trial_ended(reached)          # true: got there; false: cut off (a score, a test)
var agent = VerveAgent.new()
var action = -1                      # -1: a trial starts, decide at the next tick
var reward = 0.0                     # earned since the last decision, handed over at the next one
var clock = 0.0                      # game time since the last decision
var target_x = 250.0
var trial_time = 0.0
var rng = RandomNumberGenerator.new()

func _ready():
	# One sensor (where the target is) and two actions (walk left, walk right). A saved brain
	# goes on learning; the first run, with no save yet, makes a new one.
	if not (File.new().file_exists(SAVE) and agent.load(SAVE)):
		agent.create({"continuous_sensor_circular": [false], "actions": 2})

func _physics_process(delta):
	clock += delta
	if action < 0 or clock >= 0.1:   # decide every 0.1 s of game time, repeat the action between
		var offset = clamp((target_x - position.x) / 500.0, -1.0, 1.0)   # as with the node
		action = agent.update(reward, [], [offset], clock)
		reward = 0.0
		clock = 0.0
	match action:
		0: position.x = max(position.x - 100.0 * delta, 0.0)   # walls at 0 and 500
		1: position.x = min(position.x + 100.0 * delta, 500.0)
	trial_time += delta
	if abs(target_x - position.x) < 10.0:
		agent.end_episode(reward + 1.0)   # reached: the trial's reward
		new_trial(true)
	elif trial_time > 10.0:
		agent.truncate_episode(reward)    # too slow: cut off, though it could have gone on
		new_trial(false)

func new_trial(reached):
	emit_signal("trial_ended", reached)
	target_x = rng.randf_range(0.0, 500.0)
	trial_time = 0.0
	reward = 0.0
	clock = 0.0
	action = -1

func _exit_tree():
	agent.save(SAVE)
