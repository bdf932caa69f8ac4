# Sensor groups inside the real engine: the options "grouping" ("auto", "joint", "custom") and
# "sensor_groups" ([[0, 1], [2]]: continuous sensor indices from 0) reach libverve, come back in
# get_options(), survive saves, work for brains and the VerveAgentNode node, and every refusal names
# the group and the sensor, returns false and changes nothing. Full allocation makes the lattices'
# sizes visible: resolution^(sensors in the group) RBFs per group, created with the agent.
#   godot3-server --path build/godot/tests --script res://test_sensor_groups.gd   (exit code 1 on a failure)
extends "res://checks.gd"

const VerveAgent = preload("res://addons/verve/verve_agent.gdns")
const VerveBrain = preload("res://addons/verve/verve_brain.gdns")
const AgentNode = preload("res://addons/verve/verve_agent_node.gd")


# n plain continuous sensors, 4 actions, and `extra` on top.
func npc(n, extra = {}):
	var circular = []
	for i in n:
		circular.append(false)
	var options = {"continuous_sensor_circular": circular, "actions": 4, "seed": 3}
	for key in extra:
		options[key] = extra[key]
	return options


func readings(step, n):
	var r = PoolRealArray()
	for i in n:
		r.append(sin(step * (0.31 + 0.17 * (i + 1)) + i + 1))
	return r



func test_auto_and_joint():
	var defaults = VerveAgent.new().get_default_options()
	check(defaults["grouping"] == "auto" and defaults["sensor_groups"] == [], "auto with no groups is the default")
	var auto = new_agent(npc(12, {"rbf_allocation": "full", "resolution": 10}))
	check(auto.get_rbf_count() == 12 * 10 + 11 * 10 * 10,
		"auto: a lattice per sensor and per neighbouring pair (got %d RBFs)" % auto.get_rbf_count())
	check(auto.get_options()["grouping"] == "auto" and auto.get_options()["sensor_groups"] == [], "auto comes back")
	var refused = VerveAgent.new()
	check_error(refused, refused.create(npc(12, {"grouping": "joint", "rbf_allocation": "full"})), false,
		"[VERVE_ERROR_INVALID_ARGUMENT]", "one joint lattice over 12 sensors, in full")
	var sizes = {}
	for grouping in ["auto", "joint"]:
		var agent = new_agent(npc(12, {"grouping": grouping}))
		check(agent.get_options()["grouping"] == grouping, "%s comes back" % grouping)
		for step in 3000:
			agent.update(0.0, [], readings(step, 12), 0.1)
		sizes[grouping] = agent.get_rbf_count()
	check(sizes["auto"] <= 12 * 10 + 11 * 10 * 10 and sizes["joint"] > 2 * sizes["auto"],
		"auto stays bounded where one joint lattice keeps growing: %s" % sizes)


func test_custom():
	var groups = []
	for i in 12:
		groups.append([i])
	groups.append(PoolIntArray([1, 0]))  # any order, Array or PoolIntArray
	var agent = new_agent(npc(12, {"rbf_allocation": "full", "resolution": 10, "sensor_groups": groups}))
	check(agent.get_rbf_count() == 12 * 10 + 10 * 10, "custom groups: %d RBFs" % agent.get_rbf_count())
	var o = agent.get_options()
	check(o["grouping"] == "custom", "sensor_groups alone mean grouping \"custom\"")
	check(o["sensor_groups"].size() == 13 and o["sensor_groups"][5] == [5] and o["sensor_groups"][12] == [0, 1],
		"the groups come back: %s" % [o["sensor_groups"]])
	var twin = new_agent(o)
	check(twin.get_options().hash() == o.hash() and twin.get_rbf_count() == agent.get_rbf_count(), "get_options() feeds create()")
	var explicit = new_agent(npc(2, {"grouping": "custom", "sensor_groups": [[0, 1]]}))
	check(explicit.get_options()["sensor_groups"] == [[0, 1]], "grouping \"custom\" given too")


func test_saves_and_brains():
	var options = npc(6, {"seed": 11, "sensor_groups": [[0, 1], [2, 3, 4], [5], [0, 5]]})
	var a = new_agent(options)
	for step in 200:
		a.update(1.0 if step % 7 == 0 else 0.0, [], readings(step, 6), 0.1)
	var copy = VerveAgent.new()
	check(copy.load_bytes(a.save_bytes()), "load_bytes: " + copy.get_last_error())
	check(copy.get_options()["sensor_groups"] == [[0, 1], [2, 3, 4], [5], [0, 5]], "a save keeps the groups")
	check(copy.get_options().hash() == a.get_options().hash(), "a loaded agent has the saved options")
	var same = true
	for step in range(200, 260):
		same = same and a.update(0.0, [], readings(step, 6), 0.1) == copy.update(0.0, [], readings(step, 6), 0.1)
	check(same, "a loaded agent acts as the saved one did")

	var brain = VerveBrain.new()
	check(brain.create(npc(3, {"sensor_groups": [[0, 1], [2]]})), "VerveBrain.create: " + brain.get_last_error())
	var body = brain.create_body()
	check(body.update(0.0, [], [0.1, 0.2, 0.3], 0.1) >= 0, "a body of a grouped brain acts")
	check(body.get_options()["sensor_groups"] == [[0, 1], [2]], "a body has its brain's groups")
	var bad_brain = VerveBrain.new()
	check_error(bad_brain, bad_brain.create(npc(3, {"sensor_groups": [[0, 1]]})), false,
		"continuous sensor 2 is in none of option 'sensor_groups'", "a brain with a sensor in no group")

	# The node: 12 continuous sensors at the default grouping, or groups through extra_options.
	var node = AgentNode.new()
	node.actions = 4
	node.continuous_sensors = 12
	root.add_child(node)
	check(node.get_options()["grouping"] == "auto" and node.get_options()["continuous_sensor_circular"].size() == 12,
		"a node with 12 sensors: %s" % node.last_error)
	var grouped = AgentNode.new()
	grouped.continuous_sensors = 3
	grouped.extra_options = {"sensor_groups": [[0, 1], [1, 2]]}
	root.add_child(grouped)
	check(grouped.get_options()["sensor_groups"] == [[0, 1], [1, 2]], "a node's groups through extra_options: %s" % grouped.last_error)
	node.queue_free()
	grouped.queue_free()


# docs/godot.md, "Many sensors", as written there.
func test_doc_npcs():
	var agent = VerveAgent.new()
	var circular = []
	for i in 12:
		circular.append(false)
	check(agent.create({"continuous_sensor_circular": circular, "actions": 4}), agent.get_last_error())  # "auto": 12 single lattices, 11 pairs
	check(agent.get_options()["grouping"] == "auto", "the doc's NPC is auto")
	var groups = []
	for i in 12:
		groups.append([i])          # each sensor alone
	for i in 7:
		groups.append([i, i + 1])   # neighbouring rays
	groups.append([7, 0])           # the ring closes: ray 7 beside ray 0
	groups.append([8, 9])           # bearing with distance
	check(agent.create({"continuous_sensor_circular": circular, "actions": 4, "sensor_groups": groups}), agent.get_last_error())  # "custom"
	check(agent.get_options()["grouping"] == "custom" and agent.get_options()["sensor_groups"].size() == 12 + 7 + 2,
		"the doc's custom NPC: %s" % [agent.get_options()["sensor_groups"]])
	check(agent.update(0.0, [], readings(1, 12), 0.1) in [0, 1, 2, 3], "the doc's custom NPC acts")


func test_refusals():
	var agent = new_agent(npc(4))
	var before = agent.get_options().hash()
	var bad = [
		[{"grouping": "pairs"}, "option 'grouping' must be one of \"auto\", \"joint\", \"custom\" (got String)"],
		[{"grouping": 2}, "option 'grouping' must be one of"],
		[{"sensor_groups": 3}, "option 'sensor_groups' must be an Array of groups of continuous sensor indices"],
		[{"sensor_groups": [1, 2]}, "option 'sensor_groups'[0] must be an Array of continuous sensor indices (got int)"],
		[{"sensor_groups": [[0, 1], []]}, "option 'sensor_groups'[1] is empty"],
		[{"sensor_groups": [[0, -1]]}, "option 'sensor_groups'[0][1] must be a continuous sensor index from 0 to 63 (got -1)"],
		[{"sensor_groups": [[64]]}, "from 0 to 63 (got 64)"],
		[{"sensor_groups": [[0.5]]}, "option 'sensor_groups'[0][0] must be an int (got float)"],
		[{"sensor_groups": [[0, 1, 0]]}, "option 'sensor_groups'[0] lists continuous sensor 0 twice"],
		[{"sensor_groups": [[0, 1], [2, 3, 4]]}, "option 'sensor_groups'[1] lists continuous sensor 4, but the agent has 4"],
		[{"sensor_groups": [[0, 1], [2]]}, "continuous sensor 3 is in none of option 'sensor_groups'"],
		[{"grouping": "custom"}, "option 'grouping' \"custom\" needs 'sensor_groups' covering every continuous sensor"],
		[{"grouping": "joint", "sensor_groups": [[0, 1, 2, 3]]},
			"option 'sensor_groups' is only used with 'grouping' \"custom\" (got \"joint\")"],
	]
	var many = []
	for i in 65:
		many.append([0])
	bad.append([{"sensor_groups": many}, "option 'sensor_groups' has 65 groups; at most 64"])
	for case in bad:
		check_error(agent, agent.create(npc(4, case[0])), false, case[1], "create(%s)" % [case[0]])
	check(agent.has_agent() and agent.get_options().hash() == before, "a refused create() keeps the agent")
	many.resize(64)
	new_agent(npc(1, {"sensor_groups": many}))  # 64 groups, repeated: allowed
	new_agent({"discrete_sensors": [3], "grouping": "custom"})  # no continuous sensors: no group needed


# 32 sensors of each kind (up to 64): the options there and back, a save that acts the same, and
# the lattice limit (one joint lattice over more than 16 sensors is refused).
func test_32_sensors():
	var discrete = []
	var circular = []
	for i in 32:
		discrete.append(2 if i % 8 == 0 else 1)
		circular.append(i % 5 == 0)
	var options = {"discrete_sensors": discrete, "continuous_sensor_circular": circular, "actions": 4, "seed": 5}
	var a = new_agent(options)
	var o = a.get_options()
	check(o["discrete_sensors"] == discrete and o["continuous_sensor_circular"] == circular,
		"32 sensors of each kind come back")
	var d = []
	for i in 32:
		d.append(0)
	for step in 200:
		d[0] = (step / 3) % 2
		a.update(sin(0.05 * step), d, readings(step, 32), 0.1)
	check(a.get_rbf_count() >= 63, "auto: a lattice per sensor and per pair (%d RBFs)" % a.get_rbf_count())
	var copy = VerveAgent.new()
	check(copy.load_bytes(a.save_bytes()), "load_bytes: " + copy.get_last_error())
	var same = true
	for step in range(200, 260):
		same = same and a.update(0.0, d, readings(step, 32), 0.1) == copy.update(0.0, d, readings(step, 32), 0.1)
	check(same, "a loaded 32-sensor agent acts the same")
	var joint = VerveAgent.new()
	options["grouping"] = "joint"
	check_error(joint, joint.create(options), false, "which spans at most 16", "one joint lattice over 32 sensors")
	var too_many = []
	for i in 65:
		too_many.append(false)
	check_error(joint, joint.create({"continuous_sensor_circular": too_many}), false,
		"has 65 sensors; an agent has at most 64", "65 continuous sensors")


func _init():
	test_32_sensors()
	test_auto_and_joint()
	test_custom()
	test_saves_and_brains()
	test_doc_npcs()
	test_refusals()
	report("verve godot sensor groups")
	quit()
