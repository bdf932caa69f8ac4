# Action branches inside the real engine: the option "action_branches" ([3, 2]: choices per branch)
# reaches libverve and comes back in get_options(); masks hold one 0/1 per choice of each branch,
# branch after branch, and get_action_probabilities() one value per choice, each branch summing to 1;
# split_action()/join_action() convert a combined action (from 0, branch 0 fastest); saves keep the
# branches; every refusal returns false, -1 or null with the library's or the plugin's message and
# changes nothing.
#   godot3-server --path build/godot/tests --script res://test_action_branches.gd   (exit code 1 on a failure)
extends "res://checks.gd"

const VerveAgent = preload("res://addons/verve/verve_agent.gdns")
const VerveBrain = preload("res://addons/verve/verve_brain.gdns")
const AgentNode = preload("res://addons/verve/verve_agent_node.gd")


func npc(extra = {}):
	var options = {"continuous_sensor_circular": [false, false], "action_branches": [3, 2], "seed": 5}
	for key in extra:
		options[key] = extra[key]
	return options


func readings(step):
	return PoolRealArray([sin(step * 0.37), cos(step * 0.21) * 0.9])



func test_options():
	check(VerveAgent.new().get_default_options()["action_branches"] == [], "one action set is the default")
	var agent = new_agent(npc())
	var o = agent.get_options()
	check(o["actions"] == 6 and o["action_branches"] == [3, 2], "branches without actions: their product (%s)" % o)
	var twin = new_agent(o)
	check(twin.get_options().hash() == o.hash(), "get_options() feeds create()")
	check(new_agent(npc({"actions": 6, "action_branches": PoolIntArray([3, 2])})).get_options()["actions"] == 6,
		"actions given equal to the product, branches as a PoolIntArray")


func test_masks_and_probabilities():
	var agent = new_agent(npc())
	var mask = PoolIntArray([1, 0, 1, 0, 1])  # branch 0: choices 0 and 2; branch 1: choice 1 only
	var held = true
	for step in 200:
		var a = agent.update_masked(1.0 if step % 5 == 0 else 0.0, [], readings(step), 0.1, mask)
		var c = agent.split_action(a)
		held = held and a >= 0 and a < 6 and c.size() == 2 and c[0] in [0, 2] and c[1] == 1
	check(held, "every chosen action keeps to the per-branch mask")
	var p = agent.get_action_probabilities()
	check(p.size() == 5, "one probability per choice of each branch (got %d)" % p.size())
	check(abs(p[0] + p[1] + p[2] - 1.0) < 1e-5 and abs(p[3] + p[4] - 1.0) < 1e-5, "each branch sums to 1: %s" % p)
	check(p[1] == 0.0 and p[3] == 0.0, "masked choices have probability 0: %s" % p)


func test_split_join():
	var agent = new_agent(npc())
	var round_trip = true
	for a in 6:
		round_trip = round_trip and agent.join_action(agent.split_action(a)) == a
	check(round_trip, "split then join gives the action back")
	check(agent.split_action(1) == [1, 0] and agent.split_action(3) == [0, 1], "branch 0 varies fastest")
	check(agent.join_action([2, 1]) == 5 and agent.join_action(PoolIntArray([2, 1])) == 5, "join_action([2, 1])")
	var plain = new_agent({"actions": 4})
	check(plain.split_action(3) == [3] and plain.join_action([3]) == 3, "one action set: one choice")


func test_saves_and_brains():
	var a = new_agent(npc())
	for step in 100:
		a.update(1.0 if step % 7 == 0 else 0.0, [], readings(step), 0.1)
	var copy = VerveAgent.new()
	check(copy.load_bytes(a.save_bytes()), "load_bytes: " + copy.get_last_error())
	var from_file = VerveAgent.new()
	check(a.save("user://test_action_branches.xml") and from_file.load("user://test_action_branches.xml"),
		"save/load: " + a.get_last_error() + from_file.get_last_error())
	for loaded in [copy, from_file]:
		check(loaded.get_options()["action_branches"] == [3, 2] and loaded.get_options()["actions"] == 6,
			"a save keeps the branches")
	var same = true
	for step in range(100, 140):
		var action = a.update(0.0, [], readings(step), 0.1)
		same = same and copy.update(0.0, [], readings(step), 0.1) == action
		same = same and from_file.update(0.0, [], readings(step), 0.1) == action
	check(same, "loaded agents act as the saved one does")
	var brain = VerveBrain.new()
	check(brain.create(npc()), "VerveBrain.create: " + brain.get_last_error())
	var body = brain.create_body()
	var c = body.split_action(body.update_masked(0.0, [], readings(0), 0.1, [0, 1, 0, 1, 1]))
	check(c != null and c[0] == 1, "a body of a branched brain keeps to its mask: %s" % [c])
	var binary = VerveBrain.new()
	check(binary.load_bytes(brain.save_binary_bytes()), "VerveBrain.load_bytes: " + binary.get_last_error())
	check(binary.create_body().get_options()["action_branches"] == [3, 2], "a binary brain save keeps the branches")

	# The node, as docs/godot.md says: Actions at the product, the branches through extra_options.
	var node = AgentNode.new()
	node.actions = 6
	node.continuous_sensors = 2
	node.extra_options = {"action_branches": [3, 2]}
	root.add_child(node)
	check(node.get_options()["action_branches"] == [3, 2], "a node's branches through extra_options: %s" % node.last_error)
	node.queue_free()


# docs/godot.md, "Action branches", as written there.
func test_doc_npc():
	var reward = 0.0
	var dt = 0.1
	var readings = PoolRealArray([0.2, -0.5])
	var agent = VerveAgent.new()
	# move: 0 left, 1 stay, 2 right; turn: 0 left, 1 none, 2 right; use: 0 no, 1 yes
	check(agent.create({"continuous_sensor_circular": [false, false], "action_branches": [3, 3, 2]}), agent.get_last_error())
	var allowed = PoolIntArray([1, 1, 1,  1, 1, 1,  1, 0])  # "use" is not ready yet
	var action = agent.update_masked(reward, [], readings, dt, allowed)
	var choice = agent.split_action(action)  # [move, turn, use]
	check(choice[2] == 0 and choice[0] in [0, 1, 2] and choice[1] in [0, 1, 2], "the doc's NPC: %s" % [choice])
	check(agent.join_action(choice) == action and agent.get_options()["actions"] == 18, "the doc's NPC joins back")
	check(agent.get_action_probabilities().size() == 3 + 3 + 2, "the doc's NPC's probabilities")


func test_refusals():
	var agent = new_agent(npc())
	var before = agent.get_options().hash()
	var bad = [
		[{"action_branches": 3}, "option 'action_branches' must be an Array of choice counts, one per branch, like [3, 3, 2] (got int)"],
		[{"action_branches": [3, 0]}, "option 'action_branches'[1] must be a number of choices, at least 1 (got 0)"],
		[{"action_branches": [3, 0.5]}, "option 'action_branches'[1] must be an int (got float)"],
		[{"action_branches": [2, 2, 2, 2, 2, 2, 2, 2, 2]}, "option 'action_branches' has 9 values"],
		[{"actions": 5}, "product"],
	]
	for case in bad:
		check_error(agent, agent.create(npc(case[0])), false, case[1], "create(%s)" % [case[0]])
	check(agent.has_agent() and agent.get_options().hash() == before, "a refused create() keeps the agent")
	check_error(agent, agent.update_masked(0.0, [], readings(0), 0.1, [1, 1, 1, 1, 1, 1]), -1,
		"[VERVE_ERROR_INVALID_ARGUMENT]", "a mask with one flag per combined action")
	check_error(agent, agent.update_masked(0.0, [], readings(0), 0.1, [1, 1, 1, 0, 0]), -1,
		"[VERVE_ERROR_INVALID_ARGUMENT]", "a mask allowing nothing in branch 1")
	check_error(agent, agent.split_action(6), null, "out of range", "split_action(6)")
	check_error(agent, agent.split_action(-1), null, "action must be 0 .. actions-1 (got -1)", "split_action(-1)")
	check_error(agent, agent.join_action([3, 0]), -1, "out of range", "join_action([3, 0])")
	check_error(agent, agent.join_action([1, 1, 1]), -1, "one per branch", "join_action with 3 choices")
	check_error(agent, agent.join_action([1, -1]), -1, "choices[1] must be a choice from 0 (got -1)", "join_action([1, -1])")
	check(agent.update(0.0, [], readings(1), 0.1) in [0, 1, 2, 3, 4, 5], "the agent still acts")


func _init():
	test_options()
	test_masks_and_probabilities()
	test_split_join()
	test_saves_and_brains()
	test_doc_npc()
	test_refusals()
	report("verve godot action branches")
	quit()
