# An NPC between two walls that learns to walk to its target: a Node2D with a VerveAgentNode
# child named Brain (inspector: Actions 2, Continuous Sensors 1).
extends Node2D

var target_x = 250.0
var trial_time = 0.0
var rng = RandomNumberGenerator.new()
onready var brain = $Brain

func _physics_process(delta):
	# One sensor: where the target is, from -1 (500 px to the left) to 1 (500 px to the right).
	var offset = clamp((target_x - position.x) / 500.0, -1.0, 1.0)
	match brain.act(0.0, [], [offset], delta):       # decides every 0.1 s
		0: position.x = max(position.x - 100.0 * delta, 0.0)   # walls at 0 and 500
		1: position.x = min(position.x + 100.0 * delta, 500.0)
	trial_time += delta
	if abs(target_x - position.x) < 10.0:
		brain.end_episode(1.0)       # reached: the trial's reward
		new_trial()
	elif trial_time > 10.0:
		brain.truncate_episode(0.0)  # too slow: cut off, though it could have gone on
		new_trial()

func new_trial():
	target_x = rng.randf_range(0.0, 500.0)
	trial_time = 0.0
