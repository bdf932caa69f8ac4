# Crowds inside the real engine: VerveBrain (one learner, many VerveAgent bodies) and VerveBatch
# (many agents stepped in one call on libverve's threads). A batch must act on separate agents
# exactly as one update per agent in array order, and on every agent alike for any number of
# threads (a brain's bodies act in phases, docs/crowds.md), so every check drives a twin crowd,
# made from the same options, with single updates or a batch of another worker count, and compares. Every refused call must return null / false, give its error in
# get_last_error() and change nothing (the twin still agrees afterwards).
#   godot3-server --path build/godot/tests --script res://test_crowd.gd   (exit code 1 on a failure)
extends "res://checks.gd"

const VerveAgent = preload("res://addons/verve/verve_agent.gdns")
const VerveBrain = preload("res://addons/verve/verve_brain.gdns")
const VerveBatch = preload("res://addons/verve/verve_batch.gdns")
const OtherAgent = preload("res://other_agent.gdns")  # the same plugin loaded as another library

# Two shapes: two continuous sensors (one circular); one discrete sensor of 3 values and one continuous.
const WALKER = {"continuous_sensor_circular": [true, false], "actions": 3, "seed": 11}
const SNIFFER = {"discrete_sensors": [3], "continuous_sensor_circular": [false], "actions": 2, "seed": 5}
const DT = 0.1

# A copy one value shorter (PoolRealArray has no subarray in Godot 3.2).
func shorter(values):
	var copy = PoolRealArray(values)
	copy.resize(copy.size() - 1)
	return copy


func new_agent(options):
	var agent = VerveAgent.new()
	check(agent.create(options), "create: " + agent.get_last_error())
	return agent


func new_brain(options):
	var brain = VerveBrain.new()
	check(brain.create(options), "VerveBrain.create: " + brain.get_last_error())
	return brain


# Separate agents and bodies of two brains, mixed; the discrete-sensor kind among both.
# {"agents": [...], "brains": [...], "last": previous actions}
func new_crowd():
	var walkers = new_brain(WALKER)
	var sniffers = new_brain(SNIFFER)
	var agents = [walkers.create_body(), new_agent(WALKER), walkers.create_body(), new_agent(SNIFFER),
		sniffers.create_body(), walkers.create_body(), sniffers.create_body(), new_agent(WALKER)]
	var last = []
	for a in agents:
		check(a != null and a.has_agent(), "a crowd member: " + walkers.get_last_error() + sniffers.get_last_error())
		last.append(0)
	return {"agents": agents, "brains": [walkers, sniffers], "last": last}


# What agent i of a crowd sees and earns at step t: a reward for the action the step asks for, so
# the actions steer what the agents learn.
func reward(crowd, i, t):
	return 1.0 if crowd["last"][i] == (t + i) % 3 else -0.1


func discrete_of(agent, i, t):
	return [(t / 4 + i) % 3] if agent.get_options()["discrete_sensors"].size() > 0 else []


func continuous_of(agent, i, t):
	if agent.get_options()["continuous_sensor_circular"].size() == 1:
		return [cos(t * 0.21 + i)]
	return [sin(t * 0.3 + i), cos(t * 0.17 + 2 * i)]


func step_single(crowd, t):
	var actions = []
	var agents = crowd["agents"]
	for i in agents.size():
		actions.append(agents[i].update(reward(crowd, i, t), discrete_of(agents[i], i, t), continuous_of(agents[i], i, t), DT))
	crowd["last"] = actions
	return PoolIntArray(actions)


# The batch's packed arrays for step t: [rewards, discrete, continuous].
func packed(crowd, t):
	var rewards = PoolRealArray()
	var discrete = PoolIntArray()
	var continuous = PoolRealArray()
	var agents = crowd["agents"]
	for i in agents.size():
		rewards.append(reward(crowd, i, t))
		discrete.append_array(PoolIntArray(discrete_of(agents[i], i, t)))
		continuous.append_array(PoolRealArray(continuous_of(agents[i], i, t)))
	return [rewards, discrete, continuous]


func step_batch(batch, crowd, t):
	var p = packed(crowd, t)
	var actions = batch.update(crowd["agents"], p[0], p[1], p[2], DT)
	check(typeof(actions) == TYPE_INT_ARRAY, "batch.update returns a PoolIntArray: " + batch.get_last_error())
	if typeof(actions) == TYPE_INT_ARRAY:
		crowd["last"] = Array(actions)
	return actions


# Both crowds in the same state: the same stats, weights (values) and RBFs, member by member.
func check_same(a, b, what):
	for i in a["agents"].size():
		var sa = a["agents"][i].get_stats()
		var sb = b["agents"][i].get_stats()
		check(sa.hash() == sb.hash(), "%s: agents[%d] has the same stats (%s vs %s)" % [what, i, sa, sb])
	for k in a["brains"].size():
		check(a["brains"][k].get_rbf_count() == b["brains"][k].get_rbf_count(), "%s: brain %d's RBFs" % [what, k])


func test_brain_bodies():
	var brain = new_brain(WALKER)
	check(brain.has_brain() and brain.get_rbf_count() == 0, "a new brain has no RBFs yet")
	var first = brain.create_body()
	var second = brain.create_body()
	check(first is Reference and first.get_options().hash() == new_agent(WALKER).get_options().hash(),
		"a body is a VerveAgent with the brain's options")
	for t in 100:
		first.update(1.0 if t % 5 == 0 else 0.0, [], [sin(t * 0.3), cos(t * 0.2)], DT)
	check(first.get_stats()["steps"] == 100 and second.get_stats()["steps"] == 0, "each body counts its own steps")
	var rbfs = brain.get_rbf_count()
	check(rbfs > 0 and first.get_rbf_count() == rbfs, "one body's RBFs are the brain's (%d)" % rbfs)
	check(second.get_rbf_count() == rbfs, "a body that never updated sees the RBFs the other made")
	# Learned into one brain: a new body values a state as the trained one does.
	first.learning = false
	var late = brain.create_body()
	late.learning = false
	for t in 30:
		first.update(1.0 if t % 5 == 0 else 0.0, [], [0.4, -0.2], DT)
		late.update(1.0 if t % 5 == 0 else 0.0, [], [0.4, -0.2], DT)
	check(late.get_value() == first.get_value() and late.get_value() != 0.0,
		"bodies share the weights: V %s vs %s" % [late.get_value(), first.get_value()])
	var own = new_agent(WALKER)
	own.update(0.0, [], [0.4, -0.2], DT)
	check(own.get_value() != first.get_value(), "a separate agent has its own weights")
	# The brain lives on in its bodies.
	brain.close()
	check(not brain.has_brain(), "close() lets go of the brain")
	check(first.update(0.0, [], [0.1, 0.1], DT) >= 0, "a body keeps its brain alive: " + first.get_last_error())
	check_error(brain, brain.create_body(), null, "has no brain", "create_body after close()")
	check_error(brain, brain.get_rbf_count(), null, "has no brain", "get_rbf_count after close()")
	check_error(brain, brain.save_bytes(), null, "has no brain", "save_bytes after close()")
	check_error(brain, brain.save("user://x.xml"), false, "has no brain", "save after close()")
	check_error(brain, brain.create({"actoins": 3}), false, "unknown option 'actoins'", "a misspelt option")
	check_error(brain, brain.create({"actions": 0}), false, "[VERVE_ERROR_INVALID_ARGUMENT]", "no actions")
	check(not brain.has_brain(), "a failed create() makes no brain")
	check_error(brain, brain.create_body(1), null, "takes 0 arguments (got 1)", "create_body(1)")


# Save and load a trained brain through files (XML and binary) and bytes (XML and binary): each copy
# has the brain's RBFs and weights, and a brain's save loads as an agent too.
func test_brain_persistence():
	var brain = new_brain(WALKER)
	var bodies = [brain.create_body(), brain.create_body()]
	for t in 200:
		for i in 2:
			bodies[i].update(1.0 if (t + i) % 6 == 0 else 0.0, [], [sin(t * 0.3 + i), cos(t * 0.2)], DT)
	var copies = []
	check(brain.save("user://crowd_brain.xml"), "save: " + brain.get_last_error())
	check(brain.save_binary("res://crowd_brain.bin"), "save_binary: " + brain.get_last_error())
	var xml = brain.save_bytes()
	var binary = brain.save_binary_bytes()
	check(typeof(xml) == TYPE_RAW_ARRAY and xml.size() > 100, "save_bytes")
	check(typeof(binary) == TYPE_RAW_ARRAY and binary.size() > 100 and binary.size() < xml.size(),
		"save_binary_bytes is smaller than the XML")
	for source in ["user://crowd_brain.xml", "res://crowd_brain.bin", xml, binary]:
		var copy = VerveBrain.new()
		var ok = copy.load(source) if typeof(source) == TYPE_STRING else copy.load_bytes(source)
		check(ok, "load %s: %s" % [typeof(source), copy.get_last_error()])
		copies.append(copy)
	var as_agent = VerveAgent.new()
	check(as_agent.load("user://crowd_brain.xml"), "a brain's save loads as an agent: " + as_agent.get_last_error())
	var as_agent_binary = VerveAgent.new()
	check(as_agent_binary.load_bytes(binary), "a brain's binary save loads as an agent: " + as_agent_binary.get_last_error())
	var from_agent = VerveBrain.new()
	check(from_agent.load_bytes(bodies[0].save_bytes()), "a body's save loads as a brain: " + from_agent.get_last_error())
	copies.append(from_agent)
	Directory.new().remove("user://crowd_brain.xml")
	Directory.new().remove("res://crowd_brain.bin")
	# The same weights: a body of the original and of each copy value one state alike.
	var probe = brain.create_body()
	probe.learning = false
	probe.update(0.0, [], [0.3, 0.6], DT)
	var expected = probe.get_value()
	check(expected != 0.0, "the trained brain values the probe state")
	var readers = [as_agent, as_agent_binary]
	for copy in copies:
		check(copy.get_rbf_count() == brain.get_rbf_count(), "a loaded brain has the saved RBFs")
		readers.append(copy.create_body())
	for reader in readers:
		reader.learning = false
		reader.update(0.0, [], [0.3, 0.6], DT)
		check(reader.get_value() == expected, "a loaded copy has the saved weights (%s vs %s)" % [reader.get_value(), expected])
	check(as_agent.get_rbf_count() == brain.get_rbf_count(), "the agent loaded from a brain has its RBFs")
	# Failed loads keep the brain.
	var kept = copies[0]
	var rbfs = kept.get_rbf_count()
	check_error(kept, kept.load("user://no_such_brain.xml"), false, "[VERVE_ERROR_IO]", "a missing file")
	check_error(kept, kept.load_bytes(xml.subarray(0, xml.size() / 2)), false, "[VERVE_ERROR_FORMAT]", "a truncated save")
	check_error(kept, kept.load_bytes(PoolByteArray()), false, "[VERVE_ERROR", "no bytes")
	check_error(kept, kept.load_bytes("<brain/>"), false, "data must be a PoolByteArray", "a String for bytes")
	check_error(kept, kept.load(3), false, "path must be a String", "an int path")
	check_error(kept, kept.save_binary("res://no/such/folder/b.bin"), false, "[VERVE_ERROR_IO]", "no such folder")
	check(kept.has_brain() and kept.get_rbf_count() == rbfs, "failed loads keep the brain")


# Three identical crowds, stepped by a 2-worker batch, a 1-worker batch and single updates: the
# two batches take the same actions at every step and leave the same state; the separate agents
# (not bodies of a brain) act as their single updates do.
func test_batch_equals_single_updates():
	var batch = VerveBatch.new()
	check(batch.create(2) and batch.get_worker_count() == 2, "a batch of 2 workers: " + batch.get_last_error())
	var one = VerveBatch.new()
	check(one.create(1), "a batch of 1 worker: " + one.get_last_error())
	var batched = new_crowd()
	var single = new_crowd()
	var twin = new_crowd()
	var differ = 0
	var separate_differ = 0
	for t in 300:
		var a = step_batch(batch, batched, t)
		var b = step_single(single, t)
		if a != step_batch(one, twin, t):
			differ += 1
		for i in [1, 3, 7]:  # the separate agents of new_crowd()
			if a[i] != b[i]:
				separate_differ += 1
	check(differ == 0, "a batch's actions are the same on 1 and 2 workers (%d of 300 steps differ)" % differ)
	check(separate_differ == 0, "separate agents act as single updates (%d actions differ)" % separate_differ)
	check_same(batched, twin, "after 300 steps")
	check(batched["brains"][0].get_rbf_count() > 0, "the batch trained the brains")
	var seen = {}
	for action in batched["last"]:
		seen[action] = true
	check(seen.size() > 1, "the crowd does not act as one")
	# One agent listed twice: two updates in a row, as two single calls.
	var twice = new_agent(WALKER)
	var solo = new_agent(WALKER)
	var actions = batch.update([twice, twice], PoolRealArray([0.5, 0.0]), null, PoolRealArray([0.1, 0.2, 0.3, 0.4]), DT)
	var expected = PoolIntArray([solo.update(0.5, [], [0.1, 0.2], DT), solo.update(0.0, [], [0.3, 0.4], DT)])
	check(actions == expected and twice.get_stats().hash() == solo.get_stats().hash(), "an agent listed twice steps twice")
	var empty = batch.update([], PoolRealArray(), null, null, DT)
	check(typeof(empty) == TYPE_INT_ARRAY and empty.size() == 0, "no agents: no actions")
	var auto = VerveBatch.new()
	check(auto.create() and auto.get_worker_count() >= 1, "create() takes one worker per hardware thread")


# A batch where some members are shown what to do: the actions and learning of update_demonstrated
# for them and update for the rest, in array order (a brain with a body shown what to do steps its
# bodies in order; here both brains have one).
func test_batch_demonstrated():
	var batch = VerveBatch.new()
	check(batch.create(2), "a batch: " + batch.get_last_error())
	var batched = new_crowd()
	var single = new_crowd()
	var differ = 0
	for t in 60:
		var shown = PoolIntArray()
		for i in batched["agents"].size():
			shown.append(t % 2 if i % 2 == 0 else -1)
		var p = packed(batched, t)
		var actions = batch.update(batched["agents"], p[0], p[1], p[2], DT, shown)
		check(typeof(actions) == TYPE_INT_ARRAY, "a demonstrated batch returns actions: " + batch.get_last_error())
		var agents = single["agents"]
		var expected = []
		for i in agents.size():
			if shown[i] >= 0:
				agents[i].update_demonstrated(reward(single, i, t), discrete_of(agents[i], i, t), continuous_of(agents[i], i, t), DT, shown[i])
				expected.append(shown[i])
			else:
				expected.append(agents[i].update(reward(single, i, t), discrete_of(agents[i], i, t), continuous_of(agents[i], i, t), DT))
		single["last"] = expected
		batched["last"] = Array(actions)
		if actions != PoolIntArray(expected):
			differ += 1
	check(differ == 0, "a demonstrated batch is update_demonstrated and update in order (%d of 60 steps differ)" % differ)
	check_same(batched, single, "after 60 demonstrated steps")
	var p = packed(batched, 0)
	check_error(batch, batch.update(batched["agents"], p[0], p[1], p[2], DT, PoolIntArray([0])), null, "demonstrated actions",
		"a demonstrated list of the wrong size")
	var too_big = PoolIntArray()
	for i in batched["agents"].size():
		too_big.append(7)
	check_error(batch, batch.update(batched["agents"], p[0], p[1], p[2], DT, too_big), null, "out of range",
		"a demonstrated action out of range")


# Every refused batch call: null, the error in get_last_error(), and no agent changed (the twin
# crowd, stepped alike by a 1-worker batch before and after, still agrees).
func test_batch_errors():
	var batch = VerveBatch.new()
	check_error(batch, batch.update([], PoolRealArray(), null, null, DT), null, "has no batch", "update before create()")
	check_error(batch, batch.get_worker_count(), null, "has no batch", "get_worker_count before create()")
	check_error(batch, batch.create(-1), false, "worker_count must be 0", "a negative worker count")
	check_error(batch, batch.create("2"), false, "worker_count must be an int (got String)", "a String worker count")
	check_error(batch, batch.create(5000), false, "above 1024", "5000 workers (the library says)")
	check(not batch.has_batch(), "failed creates make no batch")
	check(batch.create(2), "create(2)")
	var one = VerveBatch.new()
	check(one.create(1), "a batch of 1 worker: " + one.get_last_error())
	var crowd = new_crowd()
	var twin = new_crowd()
	for t in 40:
		step_batch(batch, crowd, t)
		step_batch(one, twin, t)
	var agents = crowd["agents"]
	var n = agents.size()
	check_same(crowd, twin, "before the errors")
	# Step 41's arrays, good ones, each call below spoils one thing.
	var p = packed(crowd, 41)
	var rewards = p[0]
	var discrete = p[1]
	var continuous = p[2]

	var node = Node.new()
	var freed = Node.new()
	freed.free()
	var closed = new_agent(WALKER)
	closed.close()
	var foreign = OtherAgent.new()
	check(foreign.create(WALKER), "the other library's VerveAgent works on its own: " + foreign.get_last_error())
	var not_agents = {"null": null, "an int": 3, "a String": "npc", "a Node": node, "a freed object": freed,
		"a VerveBrain": crowd["brains"][0], "a VerveBatch": batch, "another library's VerveAgent": foreign}
	for what in not_agents:
		var bad = agents.duplicate()
		bad[3] = not_agents[what]
		check_error(batch, batch.update(bad, rewards, discrete, continuous, DT), null, "agents[3] is not a VerveAgent",
			what + " among the agents")
	var with_closed = agents.duplicate()
	with_closed[5] = closed
	check_error(batch, batch.update(with_closed, rewards, discrete, continuous, DT), null,
		"agents[5] is a VerveAgent without an agent", "a closed VerveAgent")
	check_error(batch, batch.update(agents, shorter(rewards), discrete, continuous, DT), null,
		"%d agents need %d rewards (got %d)" % [n, n, n - 1], "one reward too few")
	var more_rewards = PoolRealArray(rewards)
	more_rewards.append(0.0)
	check_error(batch, batch.update(agents, more_rewards, discrete, continuous, DT), null,
		"need %d rewards (got %d)" % [n, n + 1], "one reward too many")
	check_error(batch, batch.update(agents, rewards, discrete, shorter(continuous), DT), null,
		"continuous has %d values; the agents' continuous sensors take %d" % [continuous.size() - 1, continuous.size()],
		"one continuous value too few")
	var more = PoolRealArray(continuous)
	more.append(0.0)
	check_error(batch, batch.update(agents, rewards, discrete, more, DT), null, "continuous has %d values" % more.size(),
		"one continuous value too many")
	check_error(batch, batch.update(agents, rewards, null, continuous, DT), null,
		"discrete has 0 values; the agents' discrete sensors take %d" % discrete.size(), "no discrete values")
	check_error(batch, batch.update(agents, rewards, discrete, null, DT), null, "continuous has 0 values", "no continuous values")
	var nan = PoolRealArray(continuous)
	nan[6] = NAN  # agent 3's one continuous value, after 2 + 2 + 2 of the walkers before it
	check_error(batch, batch.update(agents, rewards, discrete, nan, DT), null, "[VERVE_ERROR_INVALID_ARGUMENT]", "NaN")
	check("agents[3]:" in batch.get_last_error(), "the library's error names the agent: " + batch.get_last_error())
	var out_of_range = PoolIntArray(discrete)
	out_of_range[1] = 3
	check_error(batch, batch.update(agents, rewards, out_of_range, continuous, DT), null, "agents[4]:",
		"a discrete value out of range (agent 4's)")
	var infinite = PoolRealArray(rewards)
	infinite[6] = INF
	check_error(batch, batch.update(agents, infinite, discrete, continuous, DT), null, "agents[6]:", "an infinite reward")
	check_error(batch, batch.update(agents, rewards, discrete, continuous, 0.0), null, "[VERVE_ERROR_INVALID_ARGUMENT]", "dt 0")
	check_error(batch, batch.update(agents, Array(rewards), discrete, continuous, DT), null,
		"rewards must be a PoolRealArray (got Array)", "an Array of rewards")
	check_error(batch, batch.update(agents, rewards, Array(discrete), continuous, DT), null,
		"discrete must be a PoolIntArray or null (got Array)", "an Array of discrete values")
	check_error(batch, batch.update(agents, rewards, discrete, "0.5", DT), null,
		"continuous must be a PoolRealArray or null (got String)", "a String of continuous values")
	check_error(batch, batch.update(agents[0], rewards, discrete, continuous, DT), null, "agents must be an Array",
		"one agent instead of an Array")
	check_error(batch, batch.update(agents, rewards, discrete, continuous, "fast"), null, "dt must be a number", "a String dt")
	check_error(batch, batch.update(agents, rewards, discrete, continuous), null, "takes 5 to 7 arguments (got 4)", "4 arguments")
	# An absurd crowd: refused at its first element, nothing allocated beyond the Array itself.
	var huge = []
	huge.resize(200000)
	check_error(batch, batch.update(huge, rewards, discrete, continuous, DT), null, "agents[0] is not a VerveAgent", "200000 nulls")
	node.free()

	# Nothing changed: both crowds take the same steps again and still agree.
	var differ = 0
	for t in range(41, 101):  # from the very step the refused calls tried
		if step_batch(batch, crowd, t) != step_batch(one, twin, t):
			differ += 1
	check(differ == 0, "after the refused calls the crowds still act alike (%d of 60 steps differ)" % differ)
	check_same(crowd, twin, "after the errors")
	check(batch.update(agents, packed(crowd, 101)[0], packed(crowd, 101)[1], packed(crowd, 101)[2], DT) != null and
		batch.get_last_error() == "", "a good call clears the error")
	batch.close()
	check(not batch.has_batch(), "close() ends the batch")
	check_error(batch, batch.update(agents, rewards, discrete, continuous, DT), null, "has no batch", "update after close()")


# The crowd script of docs/godot.md, its frames called by hand: 60 s of game time, then it saves.
func test_doc_crowd():
	Directory.new().remove("user://crowd.xml")
	var crowd = load("res://crowd.gd").new()
	crowd._ready()
	for frame in 60 * 60:
		crowd._physics_process(1.0 / 60)
	var steps = crowd.npcs[0].get_stats()["steps"]
	check(steps >= 500 and steps <= 600, "the doc's crowd decided every 6 or 7 frames (%d steps)" % steps)
	check(crowd.npcs[99].get_stats()["steps"] == steps and crowd.batch.get_last_error() == "", "in one call for all")
	var actions = {}
	for action in crowd.actions:
		actions[action] = true
	check(actions.size() > 1, "the crowd's NPCs act on their own observations")
	crowd._exit_tree()
	var saved = VerveBrain.new()
	check(saved.load("user://crowd.xml") and saved.get_rbf_count() == crowd.brain.get_rbf_count(),
		"the doc's crowd saved its brain: " + saved.get_last_error())
	Directory.new().remove("user://crowd.xml")
	crowd.free()


func _init():
	test_doc_crowd()
	test_brain_bodies()
	test_brain_persistence()
	test_batch_equals_single_updates()
	test_batch_demonstrated()
	test_batch_errors()
	report("verve godot crowd")
	quit()
