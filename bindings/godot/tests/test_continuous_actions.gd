# Continuous actions inside the real engine: the option "continuous_actions" (0 .. 8) reaches
# libverve and comes back in get_options() ("actions" left out: the one trivial discrete action);
# get_continuous_action() gives the latest update's values, each in [-1, 1], the same ones again when
# greedy; saves keep them and their exploration noise, so a loaded agent's next values are the
# saved one's; brains and the VerveAgentNode node (Extra Options) take them; every refusal returns
# false or null with the plugin's or the library's message and changes nothing. A teacher's values
# (update_demonstrated_continuous, VerveRecording.add_step_continuous) are played back, teach the 1-D
# reach, record and replay to the same bytes, and bad ones are refused.
#   godot3-server --path build/godot/tests --script res://test_continuous_actions.gd   (exit code 1 on a failure)
extends "res://checks.gd"

const VerveAgent = preload("res://addons/verve/verve_agent.gdns")
const VerveBrain = preload("res://addons/verve/verve_brain.gdns")
const AgentNode = preload("res://addons/verve/verve_agent_node.gd")
const VerveRecording = preload("res://addons/verve/verve_recording.gdns")
const VerveBatch = preload("res://addons/verve/verve_batch.gdns")


func driver(extra = {}):
	var options = {"continuous_sensor_circular": [true, false], "continuous_actions": 2, "seed": 7}
	for key in extra:
		options[key] = extra[key]
	return options


func readings(step):
	return PoolRealArray([sin(step * 0.37), cos(step * 0.21) * 0.9])



# Element by element: the values are float32 both sides, so equal means bit-identical.
func same(a, b):
	if a == null or b == null or a.size() != b.size():
		return false
	for i in a.size():
		if a[i] != b[i]:
			return false
	return true


func within_bounds(values, n):
	if typeof(values) != TYPE_REAL_ARRAY or values.size() != n:
		return false
	for v in values:
		if v < -1.0 or v > 1.0:
			return false
	return true


func test_options():
	check(VerveAgent.new().get_default_options()["continuous_actions"] == 0, "no continuous actions is the default")
	var agent = new_agent(driver())
	var o = agent.get_options()
	check(o["continuous_actions"] == 2 and o["actions"] == 1, "continuous actions without 'actions': one discrete action (%s)" % o)
	check(new_agent(o).get_options().hash() == o.hash(), "get_options() feeds create()")
	check(new_agent(driver({"actions": 3})).get_options()["actions"] == 3, "'actions' given beside continuous actions")
	var both = new_agent(driver({"action_branches": [3, 2]})).get_options()
	check(both["actions"] == 6 and both["continuous_actions"] == 2, "branches and continuous actions together: %s" % both)
	check(new_agent(driver({"continuous_actions": 8})).get_options()["continuous_actions"] == 8, "8, the most")


func test_values():
	var agent = new_agent(driver())
	check(same(agent.get_continuous_action(), PoolRealArray([0.0, 0.0])), "0s before the first update")
	var bounded = true
	var only_action = true
	var distinct = {}
	for step in 200:
		only_action = only_action and agent.update(0.1 if step % 9 == 0 else 0.0, [], readings(step), 0.1) == 0
		var values = agent.get_continuous_action()
		bounded = bounded and within_bounds(values, 2)
		distinct[values[0]] = true
	check(only_action, "the one discrete action is 0 on every update")
	check(bounded, "two values, each in [-1, 1], after every update")
	check(distinct.size() > 50, "sampled values vary from step to step (%d distinct of 200)" % distinct.size())
	var plain = new_agent({"actions": 3})
	plain.update(0.0, [], [], 0.1)
	var none = plain.get_continuous_action()
	check(typeof(none) == TYPE_REAL_ARRAY and none.size() == 0, "no continuous actions: an empty PoolRealArray")


func test_greedy():
	var agent = new_agent(driver())
	for step in 200:
		agent.update(0.5 if step % 4 == 0 else -0.1, [], readings(step), 0.1)
	agent.greedy = true
	agent.learning = false  # so that the weights, hence the mean, stay as they are
	agent.update(0.0, [], readings(3), 0.1)
	var first = agent.get_continuous_action()
	agent.update(0.0, [], readings(50), 0.1)
	var elsewhere = agent.get_continuous_action()
	agent.update(0.0, [], readings(3), 0.1)
	check(within_bounds(first, 2) and same(agent.get_continuous_action(), first),
		"greedy: the same observation gives the same values (%s, then %s)" % [first, agent.get_continuous_action()])
	check(not same(elsewhere, first), "greedy values follow the observation")
	var copy = VerveAgent.new()
	check(copy.load_bytes(agent.save_bytes()), "load_bytes: " + copy.get_last_error())
	copy.greedy = true
	copy.learning = false
	copy.update(0.0, [], readings(3), 0.1)
	check(same(copy.get_continuous_action(), first), "a loaded copy's greedy values are the same")


func test_saves_and_brains():
	var a = new_agent(driver())
	for step in 100:
		a.update(1.0 if step % 7 == 0 else 0.0, [], readings(step), 0.1)
	var copy = VerveAgent.new()
	check(copy.load_bytes(a.save_bytes()), "load_bytes: " + copy.get_last_error())
	var from_file = VerveAgent.new()
	check(a.save("user://test_continuous_actions.xml") and from_file.load("user://test_continuous_actions.xml"),
		"save/load: " + a.get_last_error() + from_file.get_last_error())
	for loaded in [copy, from_file]:
		check(loaded.get_options()["continuous_actions"] == 2, "a save keeps the continuous actions")
		check(same(loaded.get_continuous_action(), a.get_continuous_action()), "a save keeps the latest values")
	var same_next = true
	for step in range(100, 140):
		a.update(0.0, [], readings(step), 0.1)
		var values = a.get_continuous_action()
		for loaded in [copy, from_file]:
			loaded.update(0.0, [], readings(step), 0.1)
			same_next = same_next and same(loaded.get_continuous_action(), values)
	check(same_next, "loaded agents sample the same next values as the saved one (noise and generator saved)")
	var brain = VerveBrain.new()
	check(brain.create(driver()), "VerveBrain.create: " + brain.get_last_error())
	var body = brain.create_body()
	check(body.update(0.0, [], readings(0), 0.1) == 0 and within_bounds(body.get_continuous_action(), 2),
		"a body of a brain with continuous actions: %s" % [body.get_continuous_action()])
	var binary = VerveBrain.new()
	check(binary.load_bytes(brain.save_binary_bytes()), "VerveBrain.load_bytes: " + binary.get_last_error())
	check(binary.create_body().get_options()["continuous_actions"] == 2, "a binary brain save keeps them")

	# The node, as docs/godot.md says: Actions at 1, the continuous actions through extra_options.
	var node = AgentNode.new()
	node.actions = 1
	node.continuous_sensors = 2
	node.extra_options = {"continuous_actions": 2}
	root.add_child(node)
	check(node.get_options()["continuous_actions"] == 2, "a node's continuous actions through extra_options: %s" % node.last_error)
	check(node.act(0.0, [], readings(0), 0.1) == 0 and within_bounds(node.agent.get_continuous_action(), 2),
		"a node's decision reads its continuous values from node.agent")
	node.queue_free()


# docs/godot.md, "Continuous actions", as written there.
func test_doc_driver():
	var reward = 0.0
	var dt = 0.1
	var readings = PoolRealArray([0.3, -0.8])  # bearing to the target (wraps), distance
	var agent = VerveAgent.new()
	var max_steer = 0.6
	var max_force = 40.0
	# steer and throttle, each in [-1, 1]; no discrete choice ("actions" left out: 1)
	check(agent.create({"continuous_sensor_circular": [true, false], "continuous_actions": 2}), agent.get_last_error())
	agent.update(reward, [], readings, dt)  # the one discrete action, 0
	var act = agent.get_continuous_action()     # [steer, throttle]
	var steering = act[0] * max_steer
	var engine_force = act[1] * max_force
	check(abs(steering) <= max_steer and abs(engine_force) <= max_force, "the doc's driver: %s" % [act])


func test_refusals():
	var agent = new_agent(driver())
	agent.update(0.0, [], readings(0), 0.1)
	var before = agent.get_options().hash()
	var bad = [
		[{"continuous_actions": 9}, "option 'continuous_actions' must be an int from 0 to 8 (got 9)"],
		[{"continuous_actions": -1}, "option 'continuous_actions' must be an int from 0 to 8 (got -1)"],
		[{"continuous_actions": 1.5}, "option 'continuous_actions' must be an int from 0 to 8 (got float)"],
		[{"continuous_actions": [2]}, "option 'continuous_actions' must be an int from 0 to 8 (got Array)"],
		[{"planning": true}, "planning needs discrete actions only"],
	]
	for case in bad:
		check_error(agent, agent.create(driver(case[0])), false, case[1], "create(%s)" % [case[0]])
	check(agent.has_agent() and agent.get_options().hash() == before, "a refused create() keeps the agent")
	check_error(agent, agent.get_continuous_action(1), null, "takes 0 arguments (got 1)", "get_continuous_action(1)")
	var empty = VerveAgent.new()
	check_error(empty, empty.get_continuous_action(), null, "has no agent", "continuous_action without an agent")
	check(within_bounds(agent.get_continuous_action(), 2), "the agent still answers")


# The reach: x moves by 0.1 a, every step costs |x|; a driver steers back to 0 (a = -10 x within [-1, 1]).
func test_demonstrated_values():
	var options = {"continuous_sensor_circular": [false], "continuous_actions": 1, "seed": 1}
	var shown = new_agent(options)
	var rec = VerveRecording.new()
	check(rec.create(shown), "VerveRecording.create: " + rec.get_last_error())
	var start = 0.37
	for episode in range(10):
		start = fmod(start * 7.13 + 0.41, 1.0)
		var x = start * 2.0 - 1.0
		var reward = 0.0
		for t in range(100):
			var a = PoolRealArray([clamp(-10.0 * x, -1.0, 1.0)])
			check(shown.update_demonstrated_continuous(reward, [], PoolRealArray([x]), 0.05, 0, a),
				"update_demonstrated_continuous: " + shown.get_last_error())
			check(rec.add_step_continuous(reward, [], PoolRealArray([x]), 0.05, 0, a), "add_step_continuous: " + rec.get_last_error())
			check(same(shown.get_continuous_action(), a), "the teacher's value is played back")
			x = clamp(x + 0.1 * a[0], -1.0, 1.0)
			reward = -abs(x)
		shown.truncate_episode(reward)
		rec.add_truncation(reward)
	var replayed = new_agent(options)
	var copy = VerveRecording.new()
	check(copy.load_bytes(rec.save_bytes()), "load_bytes: " + copy.get_last_error())
	check(replayed.replay(copy), "replay: " + replayed.get_last_error())
	check(replayed.save_bytes() == shown.save_bytes(), "a replayed recording trains the same agent")

	var before = replayed.save_bytes()
	for bad in [[PoolRealArray([1.5]), "within [-1, 1]"], [PoolRealArray([0.1, 0.2]), "has 2 values, the agent has 1"]]:
		check_error(replayed, replayed.update_demonstrated_continuous(0.0, [], PoolRealArray([0.0]), 0.05, 0, bad[0]), false,
			bad[1], "update_demonstrated_continuous(%s)" % [bad[0]])
		check_error(rec, rec.add_step_continuous(0.0, [], PoolRealArray([0.0]), 0.05, 0, bad[0]), false, bad[1],
			"add_step_continuous(%s)" % [bad[0]])
	check_error(replayed, replayed.update_demonstrated_continuous(0.0, [], PoolRealArray([0.0]), 0.05, 0), false,
		"takes 6 to 7 arguments", "update_demonstrated_continuous without values")
	check(replayed.save_bytes() == before, "refused calls change nothing")

	shown.learning = false
	shown.greedy = true
	var greedy = []
	for x in [-0.6, 0.6]:
		shown.reset_short_term_memory()
		shown.update(0.0, [], PoolRealArray([x]), 0.05)
		greedy.append(shown.get_continuous_action()[0])
	print("  after 10 demonstrated episodes: greedy %.3f at x = -0.6, %.3f at +0.6" % greedy)
	check(greedy[0] > 0.5 and greedy[1] < -0.5, "the demonstrations taught the reach: %s" % [greedy])


# A crowd shown its values in one VerveBatch.update (continuous_actions packed agent after agent, read
# for the agents shown an action only) and a node's demonstrate() with values: the same agents as
# single update_demonstrated_continuous calls.
func test_demonstrated_values_in_a_batch_and_a_node():
	var batched = [new_agent(driver({"seed": 1})), new_agent(driver({"seed": 2}))]
	var alone = [new_agent(driver({"seed": 1})), new_agent(driver({"seed": 2}))]
	var batch = VerveBatch.new()
	check(batch.create(2), "VerveBatch.create: " + batch.get_last_error())
	var node = AgentNode.new()
	node.actions = 1
	node.continuous_sensors = 2
	node.decision_interval = 0.0
	node.random_seed = 1
	node.circular_sensors = PoolIntArray([0])
	node.extra_options = {"continuous_actions": 2}
	root.add_child(node)
	var twin = new_agent(driver({"seed": 1}))
	for step in 40:
		var values = PoolRealArray([0.5, -0.25 * (step % 4), 9.0, 9.0])  # agent 1's pair unread
		var sensors = readings(step)
		sensors.append_array(readings(step + 50))
		var actions = batch.update(batched, PoolRealArray([0.1, -0.1]), null, sensors, 0.1, PoolIntArray([0, -1]), values)
		check(actions != null, "VerveBatch.update with continuous_actions: " + batch.get_last_error())
		var mine = PoolRealArray([values[0], values[1]])
		alone[0].update_demonstrated_continuous(0.1, [], readings(step), 0.1, 0, mine)
		alone[1].update(-0.1, [], readings(step + 50), 0.1)
		check(same(batched[0].get_continuous_action(), mine), "the batch's agent plays the teacher's values back")
		check(node.demonstrate(0.1, [], readings(step), 0.1, 0, mine), "node.demonstrate with values: " + node.last_error)
		twin.update_demonstrated_continuous(0.1, [], readings(step), 0.1, 0, mine)
	for i in 2:
		check(batched[i].save_bytes() == alone[i].save_bytes(), "a batch's agent %d is its single calls' twin" % i)
	check(node.agent.save_bytes() == twin.save_bytes(), "node.demonstrate(..., values) is update_demonstrated_continuous")
	var before = batched[0].save_bytes()
	var sensors = readings(0)
	sensors.append_array(readings(50))
	check_error(batch, batch.update(batched, PoolRealArray([0.0, 0.0]), null, sensors, 0.1, PoolIntArray([0, -1]),
		PoolRealArray([0.5, 0.5])), null, "continuous_actions has 2 values; the agents' continuous actions take 4",
		"VerveBatch.update with too few continuous_actions")
	check_error(batch, batch.update(batched, PoolRealArray([0.0, 0.0]), null, sensors, 0.1, PoolIntArray([0, -1]),
		PoolRealArray([1.5, 0.0, 0.0, 0.0])), null, "within [-1, 1]", "VerveBatch.update with a value out of range")
	check(batched[0].save_bytes() == before, "refused batch calls change nothing")
	node.queue_free()


func _init():
	test_options()
	test_values()
	test_greedy()
	test_saves_and_brains()
	test_doc_driver()
	test_refusals()
	test_demonstrated_values()
	test_demonstrated_values_in_a_batch_and_a_node()
	report("verve godot continuous actions")
	quit()
