# Per simulated minute, summed over the NPCs: targets fetched, decision steps touching a wall or box,
# steps in the hazard, reward. Reported per NPC-minute (and as % of the time for the two contacts).
extends Reference

var npcs
var steps_per_minute   # decisions one NPC makes in a minute
var minutes = []       # [targets, wall steps, hazard steps, reward]


func _init(npc_count, decisions_per_minute):
	npcs = npc_count
	steps_per_minute = decisions_per_minute


func add(minute, target, wall, hazard, reward):
	while minutes.size() <= minute:
		minutes.append([0, 0, 0, 0.0])
	var m = minutes[minute]
	m[0] += int(target)
	m[1] += int(wall)
	m[2] += int(hazard)
	m[3] += reward


# Means over minutes [from, to): [targets / NPC-min, wall %, hazard %, reward / NPC-min].
func mean(from, to):
	var sum = [0.0, 0.0, 0.0, 0.0]
	for m in minutes.slice(from, to - 1):
		for k in 4:
			sum[k] += m[k]
	var n = float(npcs * (to - from))
	return [sum[0] / n, 100.0 * sum[1] / (n * steps_per_minute), 100.0 * sum[2] / (n * steps_per_minute), sum[3] / n]


static func text(measures):
	return "targets %.2f, wall %.1f%%, hazard %.1f%%, reward %.2f" % measures


func table():
	var lines = []
	for i in minutes.size():
		lines.append("  minute %2d: %s" % [i + 1, text(mean(i, i + 1))])
	return PoolStringArray(lines).join("\n")
