# --verve-test for rays.gd: per seed, the learning agents for TEST_MINUTES, then the scripted
# steering for SCRIPT_MINUTES in the same world (it does not learn: a few minutes measure it).
# Compares the agents' last 3 minutes with their first 3 and with the script, on every seed.
extends Reference

const RayMinutes = preload("res://ray_minutes.gd")

var seed_index = 0
var learning = true
var results = []     # per seed: [seed, early, late, script], each RayMinutes.mean()


func start(game):
	game.start_world(int(game.test_seeds[0]), true)


func progress(game):
	var limit = game.TEST_MINUTES if learning else game.SCRIPT_MINUTES
	if game.ticks != limit * 3600:
		return
	var world = int(game.test_seeds[seed_index])
	var m = game.measures
	print("seed %d, %s, per NPC-minute:\n%s" % [world, "agents" if learning else "script", m.table()])
	if learning:
		results.append([world, m.mean(0, 3), m.mean(limit - 3, limit), null])
		learning = false
		game.start_world(world, false)
		return
	results.back()[3] = m.mean(0, limit)
	learning = true
	seed_index += 1
	if seed_index < game.test_seeds.size():
		game.start_world(int(game.test_seeds[seed_index]), true)
		return
	game.get_tree().quit(0 if report(game.progress) else 1)


# One line per seed, then the checks; true when they hold on every seed. Measured on seeds 1-12
# (docs/godot.md): reward per NPC-minute early -39.8 .. -31.3, late -2.9 .. +0.1, the script's
# -43.6 .. -23.8. Not checked: targets. The agents learn to keep out of the hazard and off the
# walls, not to fetch (0-0.28 targets per NPC-minute late, the script 7.7-15.8): a known gap.
# Paid for progress too (--verve-progress=2), they fetch, and the checks are: late targets half the
# script's or more, and reward 15 or more above early. Measured on seeds 1-6: late targets 9.44 ..
# 13.33, 0.67-0.84 of the script's 14.11 .. 15.83; reward -16.4 .. 5.2 early, 80.6 .. 122.0 late
# (the script 93.4 .. 113.8: out-earned on seeds 5 and 6).
func report(progress_reward):
	var ok = true
	for r in results:
		print("seed %d: agents minutes 1-3: %s" % [r[0], RayMinutes.text(r[1])])
		print("seed %d: agents last 3:      %s" % [r[0], RayMinutes.text(r[2])])
		print("seed %d: script:             %s" % [r[0], RayMinutes.text(r[3])])
		var early = r[1][3]
		var late = r[2][3]
		var script = r[3][3]
		if progress_reward > 0.0:
			ok = ok and r[2][0] >= 0.5 * r[3][0] and late > early + 15.0
		else:
			ok = ok and late > early + 15.0 and late > -5.0 and late > script + 10.0
	print("verve godot rays: ", "PASS" if ok else "FAIL")
	return ok
