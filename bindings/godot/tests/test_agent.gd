# The VerveAgent binding inside the real engine: every method, the errors a game script can make
# (each must print a Godot error, return false / -1 / null and change nothing), and persistence.
#   godot3-server --path build/godot/tests --fixed-fps 60 --script res://test_agent.gd
# (exit code 1 on a failure).
extends "res://checks.gd"

const VerveAgent = preload("res://addons/verve/verve_agent.gdns")
const OPTIONS = {"discrete_sensors": [3], "continuous_sensor_circular": [true, false], "actions": 3, "seed": 7}


func new_agent(options = OPTIONS):
	var agent = VerveAgent.new()
	check(agent.create(options), "create(%s): %s" % [options, agent.get_last_error()])
	return agent


# Steps an agent through a fixed sensor sequence; returns its actions.
func drive(agent, steps, first = 0):
	var actions = []
	for i in range(first, first + steps):
		var reward = 1.0 if i % 7 == 0 else 0.0
		actions.append(agent.update(reward, [i % 3], [sin(i * 0.3), cos(i * 0.2)], 0.1))
	return actions


func test_options():
	var agent = VerveAgent.new()
	check(not agent.has_agent(), "a new VerveAgent holds no agent")
	check(agent.create(), "create() with defaults")
	check(agent.get_options().hash() == agent.get_default_options().hash(), "create() takes libverve's defaults")
	check(agent.get_default_options()["tau_value"] > 0.0, "defaults come from libverve")
	var a = new_agent()
	var o = a.get_options()
	check(o["discrete_sensors"] == [3] and o["continuous_sensor_circular"] == [true, false], "sensors round-trip")
	check(o["actions"] == 3 and o["seed"] == 7 and o["rbf_allocation"] == "dynamic", "options round-trip")
	var b = new_agent(o)
	check(b.get_options().hash() == o.hash(), "get_options() feeds create()")
	var every = {"resolution": 8, "rbf_allocation": "full", "tau_value": 0.2, "tau_discount": 2, "tau_eligibility": 0.3,
		"policy_multiplier": 4.0, "trace_threshold": 0.02, "planning": true, "tau_model": 0.5, "max_planning_steps": 4,
		"planning_uncertainty_threshold": 0.4, "curiosity": "progress", "curiosity_factor": 2.0,
		"planning_accumulates_uncertainty": false, "learn_from_real_steps": false, "discrete_prediction": "ordinal"}
	var c = new_agent(every)
	for key in every:
		check(is_equal_approx(float(c.get_options()[key]), float(every[key])) if typeof(every[key]) in [TYPE_INT, TYPE_REAL]
			else c.get_options()[key] == every[key], "option %s round-trips" % key)


func test_bad_options():
	var agent = new_agent()
	var before = agent.get_options().hash()
	check_error(agent, agent.create({"tau_vlaue": 1.0}), false, "unknown option 'tau_vlaue'", "a misspelt option")
	check_error(agent, agent.create({"actions": "3"}), false, "option 'actions' must be a non-negative int", "a String count")
	check_error(agent, agent.create({"seed": -1}), false, "option 'seed'", "a negative seed")
	check_error(agent, agent.create({"tau_value": "fast"}), false, "option 'tau_value' must be a number", "a String time")
	check_error(agent, agent.create({"discrete_sensors": [1.5]}), false, "discrete_sensors[0] must be an int", "a float count")
	check_error(agent, agent.create({"discrete_sensors": [-2]}), false, "not negative", "a negative value count")
	check_error(agent, agent.create({"continuous_sensor_circular": [1]}), false, "must be a bool", "an int circular flag")
	check_error(agent, agent.create({"continuous_sensor_circular": true}), false, "an Array of bools", "a lone bool")
	check_error(agent, agent.create({"curiosity": "lots"}), false, "\"none\", \"novelty\", \"progress\"", "an unknown enum name")
	check_error(agent, agent.create({1: 2}), false, "unknown option '1'", "a non-String key")
	check_error(agent, agent.create([3]), false, "options must be a Dictionary", "an Array for options")
	check_error(agent, agent.create({"actions": 0}), false, "[VERVE_ERROR_INVALID_ARGUMENT]", "no actions (the library says)")
	var many = []
	for i in 65:
		many.append(true)
	check_error(agent, agent.create({"continuous_sensor_circular": many}), false, "at most 64", "65 sensors")
	check(agent.has_agent() and agent.get_options().hash() == before, "a failed create() keeps the agent")


func test_update():
	var a = new_agent()
	var b = new_agent()
	var actions = drive(a, 50)
	var same = []
	for i in 50:  # the same observations as PoolArrays
		var reward = 1.0 if i % 7 == 0 else 0.0
		same.append(b.update(reward, PoolIntArray([i % 3]), PoolRealArray([sin(i * 0.3), cos(i * 0.2)]), 0.1))
	check(actions == same, "Arrays and PoolArrays give the same actions")
	for action in actions:
		check(action >= 0 and action < 3, "actions are 0 .. actions-1 (got %s)" % action)
	check(a.get_stats()["steps"] == 50, "50 steps counted")
	var steps = a.get_stats()["steps"]
	check_error(a, a.update(0.0, [1], [0.5], 0.1), -1, "continuous", "too few continuous values")
	check_error(a, a.update(0.0, [3], [0.5, 0.5], 0.1), -1, "[VERVE_ERROR_INVALID_ARGUMENT]", "a discrete value out of range")
	check_error(a, a.update(0.0, [1], [NAN, 0.5], 0.1), -1, "[VERVE_ERROR_INVALID_ARGUMENT]", "NaN")
	check_error(a, a.update(INF, [1], [0.5, 0.5], 0.1), -1, "[VERVE_ERROR_INVALID_ARGUMENT]", "an infinite reward")
	check_error(a, a.update(0.0, [1], [0.5, 0.5], 0.0), -1, "[VERVE_ERROR_INVALID_ARGUMENT]", "dt 0")
	check_error(a, a.update(0.0, "1", [0.5, 0.5], 0.1), -1, "discrete must be a PoolIntArray or an Array (got String)", "a String")
	check_error(a, a.update(0.0, [1], ["x", 0.5], 0.1), -1, "continuous[0] must be a number (got String)", "a String value")
	check_error(a, a.update(0.0, [1.0], [0.5, 0.5], 0.1), -1, "discrete[0] must be an int", "a float discrete value")
	check_error(a, a.update("0", [1], [0.5, 0.5], 0.1), -1, "reward must be a number", "a String reward")
	check_error(a, a.update(0.0, [1], PoolRealArray(range(65)), 0.1), -1, "at most 64", "65 values")
	check_error(a, a.update(0.0, [1]), -1, "takes 4 arguments (got 2)", "two arguments")
	check_error(a, a.update(0.0, [1], Vector2(), 0.1), -1, "got Vector2", "a Vector2")
	check(a.get_stats()["steps"] == steps, "refused updates change nothing")
	check(a.update(0.0, [1], [0.5, 0.5], 0.1) >= 0 and a.get_last_error() == "", "a good call clears the error")
	var none = new_agent({"actions": 2})
	check(none.update(0.0, null, null, 0.1) in [0, 1], "null means no sensors")


func test_episode_learning_readouts():
	var a = new_agent()
	drive(a, 20)
	check(a.end_episode(1.0), "end_episode")
	drive(a, 5)
	check(a.truncate_episode(-0.5), "truncate_episode")
	check(a.reset_short_term_memory(), "reset_short_term_memory")
	check_error(a, a.end_episode("win"), false, "final_reward must be a number", "a String final reward")
	check_error(a, a.truncate_episode("late"), false, "reward must be a number", "a String truncation reward")
	var budget = new_agent({"actions": 2, "max_rbfs": 5, "policy_weight_bound": 4.0})
	check(budget.get_options()["max_rbfs"] == 5 and budget.get_options()["policy_weight_bound"] == 4.0,
		"max_rbfs and policy_weight_bound reach the agent")
	check(a.learning == true, "learning by default")
	a.learning = false
	check(a.learning == false, "learning can be switched off")
	a.learning = 1
	check("learning must be a bool" in a.get_last_error() and a.learning == false, "learning takes bools only")
	a.learning = true
	drive(a, 5)
	var p = a.get_action_probabilities()
	check(typeof(p) == TYPE_REAL_ARRAY and p.size() == a.get_options()["actions"], "one probability per action")
	var total = 0.0
	for x in p:
		total += x
	check(abs(total - 1.0) < 1e-4, "the probabilities sum to 1")
	check(a.greedy == false, "sampling by default")
	a.greedy = true
	check(a.greedy == true, "greedy play can be switched on")
	a.learning = false  # the same weights for both updates below
	a.update(0.0, [1], [0.2, -0.3], 0.1)
	p = a.get_action_probabilities()
	var best = 0
	for i in range(p.size()):
		if p[i] > p[best]:
			best = i
	check(a.update(0.0, [1], [0.2, -0.3], 0.1) == best, "greedy plays the most probable action")
	a.learning = true
	for i in range(30):
		var masked = a.update_masked(0.0, [i % 3], [sin(i * 0.3), 0.1], 0.1, [1, 0, 1])
		check(masked == 0 or masked == 2, "a masked action is never chosen")
	check(a.get_action_probabilities()[1] == 0.0, "a masked action has probability 0")
	check_error(a, a.update_masked(0.0, [1], [0.2, -0.3], 0.1, [0, 0, 0]), -1, "allows no action", "a mask that allows nothing")
	check_error(a, a.update_masked(0.0, [1], [0.2, -0.3], 0.1, [1, 2, 0]), -1, "mask[1] must be 0 or 1 (got 2)",
		"a mask flag that is not 0 or 1")
	check_error(a, a.update_masked(0.0, [1], [0.2, -0.3], 0.1, [1, 1]), -1, "has 2 flags, the agent has 3 actions", "a mask of the wrong size")
	for i in range(10):
		check(a.update_demonstrated(0.0, [2], [0.5, 0.5], 0.1, 1), "a demonstrated step")
	a.update(0.0, [2], [0.5, 0.5], 0.1)
	check(a.get_action_probabilities()[1] > 0.5, "demonstrations pull the policy towards the shown action")
	check_error(a, a.update_demonstrated(0.0, [2], [0.5, 0.5], 0.1, 3), false, "out of range", "a demonstrated action out of range")
	check_error(a, a.update_demonstrated(0.0, [2], [0.5, 0.5], 0.1, -1), false, "action must be 0 .. actions-1", "a negative demonstrated action")
	check_error(a, a.update_demonstrated(0.0, [2], [0.5, 0.5], 0.1, 1.5), false, "action must be an int", "a demonstrated action that is not an int")
	check(a.update_demonstrated(0.0, [2], [0.5, 0.5], 0.1, 2, [0, 0, 1]), "a demonstrated step under a mask")
	check_error(a, a.update_demonstrated(0.0, [2], [0.5, 0.5], 0.1, 0, [0, 1, 1]), false, "forbids", "a demonstrated action the mask forbids")
	check_error(a, a.update_demonstrated(0.0, [2], [0.5, 0.5], 0.1, 0, [1, 2, 1]), false, "mask[1] must be 0 or 1", "a bad mask flag")
	check(a.teach(0.0) and a.teach(1.0), "a teacher's judgements")
	check_error(a, a.teach(1.5), false, "[-1, 1]", "praise beyond [-1, 1]")
	a.greedy = "yes"
	check("greedy must be a bool" in a.get_last_error() and a.greedy == true, "greedy takes bools only")
	a.greedy = false
	check(typeof(a.get_value()) == TYPE_REAL and typeof(a.get_td_error()) == TYPE_REAL, "value and TD error")
	check(a.get_rbf_count() > 0 and a.get_rbf_count() == a.get_stats()["rbf_count"], "rbf count")
	for key in ["steps", "rbf_count", "live_traces", "value", "td_error", "model_error", "predicted_uncertainty",
			"planning_steps", "curiosity_reward", "rbf_budget_hits", "clamped_rewards"]:
		check(a.get_stats().has(key), "stats has " + key)


# clamped_rewards and rbf_budget_hits in get_stats(), and libverve's warnings through take_warnings()
# (also printed in the engine's output as they come: the two WARNING lines in this test's log).
func test_warnings():
	var a = new_agent()
	a.take_warnings()
	check(a.take_warnings().size() == 0, "no warnings while nothing is wrong")
	var b = new_agent({"discrete_sensors": [3], "actions": 2})
	b.update(0.0, [0], [], 0.1)
	b.update(6.5, [1], [], 0.1)
	b.update(-8.0, [2], [], 0.1)
	check(b.get_stats()["clamped_rewards"] == 2, "clamped_rewards counts both: %s" % b.get_stats())
	check(b.get_stats()["rbf_budget_hits"] == 0, "no budget hits")
	var w = a.take_warnings()
	check(typeof(w) == TYPE_STRING_ARRAY and w.size() == 1 and "a reward of 6.5 was clamped to [-1, 1]" in w[0],
		"one clamp warning per agent: %s" % [w])
	check(a.take_warnings().size() == 0, "a second read returns what came since the first")
	var c = new_agent({"continuous_sensor_circular": [false], "actions": 2, "max_rbfs": 2})
	for i in range(21):
		c.update(0.0, [], [-1.0 + 0.1 * i], 0.1)
	check(c.get_stats()["rbf_count"] <= 2 and c.get_stats()["rbf_budget_hits"] > 0, "budget hits: %s" % c.get_stats())
	w = c.take_warnings()
	check(w.size() == 1 and "the RBF budget (max_rbfs = 2) is reached" in w[0], "one budget warning: %s" % [w])


func test_sample_values():
	var a = new_agent()
	drive(a, 200)
	var line = a.sample_values([{"kind": "continuous", "index": 0, "samples": 8}])
	check(typeof(line) == TYPE_REAL_ARRAY and line.size() == 8, "one axis: 8 values")
	var grid = a.sample_values([{"kind": "continuous", "index": 1, "samples": 5}, {"kind": "discrete", "index": 0}],
		[2], [0.1, 0.0])
	check(grid.size() == 15, "continuous 5 x discrete 3 = 15 values (got %s)" % grid.size())
	var v = a.sample_values([{"kind": "discrete", "index": 0}], [0], [0.1, 0.2])
	var changed = false
	for x in v:
		changed = changed or x != 0.0
	check(changed, "a trained agent's values are not all zero")
	check_error(a, a.sample_values([]), null, "give 1 or 2 axes (got 0)", "no axes")
	var axis = {"kind": "continuous", "index": 0, "samples": 2}
	check_error(a, a.sample_values([axis, axis, axis]), null, "give 1 or 2 axes (got 3)", "three axes")
	check_error(a, a.sample_values([{"kind": "angle", "index": 0, "samples": 2}]), null, "kind must be", "a bad kind")
	check_error(a, a.sample_values([{"kind": "continuous", "index": 0, "size": 2}]), null, "unknown axis key 'size'", "a bad key")
	check_error(a, a.sample_values([{"kind": "continuous", "index": 5, "samples": 2}]), null, "[VERVE_ERROR", "no sensor 5")
	check_error(a, a.sample_values([{"kind": "continuous", "index": 0, "samples": 0}]), null, "samples must be", "0 samples")
	check_error(a, a.sample_values([axis], [0, 0]), null, "[VERVE_ERROR_INVALID_ARGUMENT]", "a base of the wrong size")
	check_error(a, a.sample_values("all"), null, "axes must be an Array", "a String for axes")


func test_persistence():
	var a = new_agent()
	drive(a, 300)
	var copies = []
	for path in ["res://saved_agent.xml", "user://saved_agent.xml"]:
		check(a.save(path), "save %s: %s" % [path, a.get_last_error()])
		var copy = VerveAgent.new()
		check(copy.load(path), "load %s: %s" % [path, copy.get_last_error()])
		copies.append(copy)
		Directory.new().remove(path)
	var bytes = a.save_bytes()
	check(typeof(bytes) == TYPE_RAW_ARRAY and bytes.size() > 100, "save_bytes")
	var from_bytes = VerveAgent.new()
	check(from_bytes.load_bytes(bytes), "load_bytes: " + from_bytes.get_last_error())
	copies.append(from_bytes)
	var expected = drive(a, 300, 300)
	for copy in copies:
		check(drive(copy, 300, 300) == expected, "a loaded agent acts as the saved one did")
		check(copy.get_options().hash() == a.get_options().hash(), "a loaded agent has the saved options")
	var kept = a.get_stats()["steps"]
	check_error(a, a.load("user://no_such_agent.xml"), false, "[VERVE_ERROR_IO]", "a missing file")
	check_error(a, a.load_bytes(bytes.subarray(0, bytes.size() / 2)), false, "[VERVE_ERROR_FORMAT]", "a truncated save")
	check_error(a, a.load_bytes(PoolByteArray()), false, "[VERVE_ERROR", "no bytes")
	check_error(a, a.load_bytes("<agent/>"), false, "data must be a PoolByteArray", "a String for bytes")
	check_error(a, a.load(3), false, "path must be a String", "an int path")
	check_error(a, a.save("res://no/such/folder/agent.xml"), false, "[VERVE_ERROR_IO]", "a folder that does not exist")
	check(a.get_stats()["steps"] == kept, "failed loads keep the agent")


func test_no_agent():
	var a = VerveAgent.new()
	var closed = new_agent()
	closed.close()
	for agent in [a, closed]:
		check_error(agent, agent.update(0.0, [0], [0.0, 0.0], 0.1), -1, "has no agent", "update without an agent")
		check_error(agent, agent.end_episode(0.0), false, "has no agent", "end_episode without an agent")
		check_error(agent, agent.reset_short_term_memory(), false, "has no agent", "reset without an agent")
		check_error(agent, agent.get_value(), null, "has no agent", "get_value without an agent")
		check_error(agent, agent.get_stats(), null, "has no agent", "get_stats without an agent")
		check_error(agent, agent.get_options(), null, "has no agent", "get_options without an agent")
		check_error(agent, agent.save_bytes(), null, "has no agent", "save_bytes without an agent")
		check_error(agent, agent.save("user://x.xml"), false, "has no agent", "save without an agent")
		check_error(agent, agent.sample_values([]), null, "has no agent", "sample_values without an agent")
		check(agent.learning == null and "has no agent" in agent.get_last_error(), "learning without an agent")
		check(not agent.has_agent(), "has_agent() is false")
	closed.close()  # twice is fine
	check(closed.create(OPTIONS) and closed.has_agent(), "a closed VerveAgent can create again")


# The node-less NPC script of docs/godot.md (npc.gd), in a scene: a fresh start makes its agent
# without an error, it decides every 0.1 s of game time (and at once when a trial starts), and it
# saves on exit. test_node.gd checks that it learns.
var npc
var trials = 0
var frames = 0


func start_doc_npc():
	Directory.new().remove("user://line_npc.xml")
	npc = Node2D.new()
	npc.set_script(load("res://npc.gd"))
	npc.connect("trial_ended", self, "_on_trial_ended")
	root.add_child(npc)  # _ready: no save yet, so a new agent
	check(npc.agent.has_agent() and npc.agent.get_last_error() == "", "the doc's NPC starts fresh without an error")


func _on_trial_ended(_reached):
	trials += 1


# SceneTree calls _idle every frame (with --fixed-fps 60: 1/60 s of game time each).
func _idle(_delta):
	frames += 1
	if frames != 20 * 60:
		return
	# 20 s: 200 decisions, plus at most one for each trial that started between two of them.
	var steps = npc.agent.get_stats()["steps"]
	check(steps >= 200 and steps <= 200 + trials, "the doc's NPC decided 10 times a second (%d decisions, %d trials)" % [steps, trials])
	npc.queue_free()  # saves
	quit()


func _finalize():
	var saved = VerveAgent.new()
	check(saved.load("user://line_npc.xml") and saved.get_stats()["steps"] >= 200, "the doc's NPC saved its agent")
	Directory.new().remove("user://line_npc.xml")
	report("verve godot binding")


func _init():
	test_options()
	test_bad_options()
	test_update()
	test_episode_learning_readouts()
	test_warnings()
	test_sample_values()
	test_persistence()
	test_no_agent()
	start_doc_npc()  # runs frame by frame: _idle, then _finalize
