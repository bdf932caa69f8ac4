# The VerveAgentNode addon node in the real engine: exports reach the native agent, signals fire,
# refusals surface, the debug overlay draws, and docs/godot.md's line NPC learns, with the node
# (line_npc.gd) and without it (npc.gd).
#   godot3-server --path build/godot/tests --fixed-fps 60 --script res://test_node.gd
# (exit code 1 on a failure).
extends "res://checks.gd"

const VerveAgent = preload("res://addons/verve/verve_agent.gdns")
const AgentNode = preload("res://addons/verve/verve_agent_node.gd")
const TICK = 1.0 / 60.0
const MINUTES = 5
# Measured over seeds 1-3, minute 5: 23.0 targets per minute learning, 1.8 not learning; over the
# triples of seeds up to 18: 21.0-31.3 learning, 1.8-3.1 not (docs/godot.md).
const LEARNED_MIN = 15.0
const RATIO_MIN = 5.0

var SEEDS = [1, 2, 3]      # other worlds: --verve-seeds=4,5,6
var npcs = []             # with the node learning, then frozen, then without the node; one per seed
var reached = []          # per NPC, targets reached in each simulated minute
var overlaid              # an NPC whose brain shows the debug overlay
var pair                  # a node with 2 continuous sensors: a 2-D heat map
var wide                  # a node with 3 continuous sensors: bars, no heat map
var frames = 0


func new_node(settings = {}):
	var node = AgentNode.new()
	for key in settings:
		node.set(key, settings[key])
	root.add_child(node)  # _ready creates the agent
	return node


func test_settings():
	var node = new_node({"actions": 3, "continuous_sensors": 2, "circular_sensors": PoolIntArray([1]),
		"discrete_sensors": PoolIntArray([4]), "random_seed": 5, "tau_value": 0.3, "tau_eligibility": 0.2,
		"extra_options": {"planning": true}, "learning": false, "greedy": true})
	var o = node.get_options()
	check(o["actions"] == 3 and o["continuous_sensor_circular"] == [false, true] and o["discrete_sensors"] == [4],
		"the sensors and actions reach the agent (%s)" % o)
	check(o["seed"] == 5 and is_equal_approx(o["tau_value"], 0.3) and is_equal_approx(o["tau_eligibility"], 0.2)
		and o["planning"] == true, "seed, times and extra options reach the agent")
	check(node.agent.learning == false and node.agent.greedy == true, "learning and greedy reach the agent")
	node.learning = true
	check(node.agent.learning == true, "setting learning later reaches the agent")
	var defaults = VerveAgent.new().get_default_options()
	var plain = new_node().get_options()
	for key in ["seed", "tau_value", "tau_discount", "tau_eligibility"]:
		check(plain[key] == defaults[key], "an unset %s is libverve's default (%s, got %s)" % [key, defaults[key], plain[key]])
	node.queue_free()


func test_signals():
	var node = new_node({"actions": 2, "continuous_sensors": 1})
	var chosen = []
	var ended = []
	node.connect("action_chosen", self, "_append", [chosen])
	node.connect("episode_ended", self, "_append_pair", [ended])
	var returned = []
	for i in 13:  # decides at once, then every 6 ticks of 1/60 s: ticks 1, 7, 13
		returned.append(node.act(0.0, [], [0.5], TICK))
	check(chosen.size() == 3 and node.agent.get_stats()["steps"] == 3, "3 decisions in 13 ticks (signalled %d)" % chosen.size())
	check(returned[0] == chosen[0] and returned[6] == chosen[1] and returned[12] == chosen[2] and returned[5] == chosen[0],
		"act() returns the decision and repeats it in between")
	check(node.end_episode(1.0) and ended == [[1.0, false]], "end_episode signals (got %s)" % [ended])
	node.act(0.0, [], [0.5], TICK)
	check(chosen.size() == 4, "after an episode the next act() decides at once")
	check(node.truncate_episode(0.5) and ended[1] == [0.5, true], "truncate_episode signals truncated")
	check(node.demonstrate(0.0, [], [0.1], TICK, 1) and chosen[4] == 1 and node.action == 1,
		"demonstrate() records the demonstrated action as the decision")
	var masked = []
	for i in 60:
		masked.append(node.act(0.0, [], [0.2], TICK, [0, 1]))
	check(not 0 in masked and node.agent.get_stats()["steps"] == 15, "a mask limits the choice (%s)" % [masked])
	node.queue_free()


func _append(value, into):
	into.append(value)


func _append_pair(a, b, into):
	into.append([a, b])


func test_refusals():
	var node = new_node({"actions": 2, "continuous_sensors": 1})
	check(node.act(0.0, [], [0.1, 0.2], TICK) == -1 and "act:" in node.last_error and "continuous" in node.last_error,
		"a wrong sensor count is refused with the native message (%s)" % node.last_error)
	check(node.act(0.0, [], [0.1], TICK) >= 0, "the node acts again after a refusal")
	var bad = new_node({"extra_options": {"tau_vlaue": 1.0}})
	check(bad.agent.has_agent() == false and "unknown option 'tau_vlaue'" in bad.last_error, "a misspelt extra option is refused")
	check(bad.act(0.0, [], [], TICK) == -1 and "no agent" in bad.last_error, "a node without an agent refuses act()")
	var circle = new_node({"continuous_sensors": 1, "circular_sensors": PoolIntArray([1])})
	check(circle.agent == null and "circular_sensors names sensor 1" in circle.last_error, "a circular index past the sensors")
	check(not node.load_agent("user://no such file.xml") and node.agent.has_agent(), "a failed load keeps the agent")
	check(not node.save_agent("/no such dir/x.xml") and "save" in node.last_error, "a failed save is refused")
	for n in [node, bad, circle]:
		n.queue_free()


func test_save_load():
	var path = "user://verve_node_test.xml"
	Directory.new().remove(path)
	var node = new_node({"actions": 3, "continuous_sensors": 1, "random_seed": 4, "save_path": path})
	for i in 60:
		node.act(0.1 if i % 10 == 0 else 0.0, [], [sin(i * 0.2)], TICK)
	var options = node.get_options()
	node.free()  # _exit_tree saves
	check(File.new().file_exists(path), "a node with save_path saves on exit")
	var again = new_node({"actions": 2, "save_path": path})  # the save, not the exports, decides
	check(again.get_options().hash() == options.hash() and again.agent.get_stats()["steps"] == 10,
		"a node with save_path loads it at _ready")
	again.save_path = ""
	again.queue_free()
	Directory.new().remove(path)


# The doc's NPC: a Node2D with a VerveAgentNode child named Brain, set as the doc's inspector says.
func new_npc(world_seed, learns):
	var npc = Node2D.new()
	var brain = AgentNode.new()
	brain.name = "Brain"
	brain.actions = 2
	brain.continuous_sensors = 1
	brain.random_seed = world_seed
	brain.learning = learns
	npc.add_child(brain)
	npc.set_script(load("res://line_npc.gd"))
	npc.rng.seed = world_seed
	npc.position.x = npc.rng.randf_range(0.0, 500.0)
	root.add_child(npc)
	var counts = []
	counts.resize(MINUTES)
	for m in MINUTES:
		counts[m] = 0
	reached.append(counts)
	brain.connect("episode_ended", self, "_on_episode_ended", [reached.size() - 1])
	return npc


func _on_episode_ended(_final_reward, truncated, index):
	if not truncated:
		reached[index][min(frames / 3600, MINUTES - 1)] += 1


# The same NPC without the node (npc.gd, the doc's second script): its own agent, seeded as the
# node's is; its trial_ended signal counts the targets reached.
func new_plain_npc(world_seed):
	var npc = Node2D.new()
	npc.set_script(load("res://npc.gd"))
	npc.rng.seed = world_seed
	npc.position.x = npc.rng.randf_range(0.0, 500.0)
	root.add_child(npc)  # _ready: no save (removed below), so a new agent
	npc.agent.create({"continuous_sensor_circular": [false], "actions": 2, "seed": world_seed})
	var counts = []
	counts.resize(MINUTES)
	for m in MINUTES:
		counts[m] = 0
	reached.append(counts)
	npc.connect("trial_ended", self, "_on_trial_ended", [reached.size() - 1])
	return npc


func _on_trial_ended(got_there, index):
	_on_episode_ended(1.0, not got_there, index)


func start_npcs():
	for arg in OS.get_cmdline_args():
		if arg.begins_with("--verve-seeds="):
			SEEDS = Array(arg.split("=")[1].split(","))
			for i in SEEDS.size():
				SEEDS[i] = int(SEEDS[i])
	for learns in [true, false]:
		for s in SEEDS:
			npcs.append(new_npc(s, learns))
	Directory.new().remove("user://line_npc.xml")
	for s in SEEDS:
		npcs.append(new_plain_npc(s))
	overlaid = npcs[0].get_node("Brain")
	overlaid.debug_overlay = true
	pair = new_node({"actions": 3, "continuous_sensors": 2, "debug_overlay": true})
	wide = new_node({"actions": 4, "continuous_sensors": 3, "debug_overlay": true})


# Targets per minute over the seeds: learning NPCs in `minute`, and frozen ones over all minutes.
func rate(first, minute):
	var sum = 0.0
	for i in range(first, first + SEEDS.size()):
		if minute >= 0:
			sum += reached[i][minute]
		else:
			for m in MINUTES:
				sum += reached[i][m] / float(MINUTES)
	return sum / SEEDS.size()


# SceneTree calls _idle every frame (with --fixed-fps 60: 1/60 s of game time each).
func _idle(_delta):
	frames += 1
	pair.act(0.0, [], [sin(frames * 0.01), cos(frames * 0.013)], TICK)
	wide.act(0.0, [], [0.1, -0.2, 0.3], TICK)
	if frames < MINUTES * 3600:
		return
	var first = rate(0, 0)
	var last = rate(0, MINUTES - 1)
	var frozen = rate(SEEDS.size(), -1)
	print("line NPC, targets per minute over seeds %s: learning, minute 1 %.2f, minute %d %.2f; not learning %.2f"
		% [SEEDS, first, MINUTES, last, frozen])
	for i in reached.size():
		print("  ", ["learning", "frozen", "without the node"][i / SEEDS.size()], " seed ", SEEDS[i % SEEDS.size()], ": ", reached[i])
	check(last > LEARNED_MIN, "the line NPC learns: more than %.1f targets per minute in minute %d (got %.2f)" % [LEARNED_MIN, MINUTES, last])
	check(last > RATIO_MIN * frozen, "more than %.1f times an NPC that does not learn (%.2f vs %.2f)" % [RATIO_MIN, last, frozen])
	var plain_first = rate(2 * SEEDS.size(), 0)
	var plain = rate(2 * SEEDS.size(), MINUTES - 1)
	print("line NPC without the node: minute 1 %.2f, minute %d %.2f" % [plain_first, MINUTES, plain])
	check(plain > LEARNED_MIN and plain > RATIO_MIN * frozen,
		"the line NPC without the node learns as well: more than %.1f targets per minute in minute %d and %.1f times one that does not learn (got %.2f)"
		% [LEARNED_MIN, MINUTES, RATIO_MIN, plain])
	var overlay = overlaid.overlay
	check(overlay != null and overlay.draws > 0 and overlay.rows == 1 and overlay.values.size() == overlay.COLUMNS,
		"the overlay draws a 1-row heat map for 1 sensor")
	check(pair.overlay.draws > 0 and pair.overlay.rows == pair.overlay.HEAT_ROWS
		and pair.overlay.values.size() == pair.overlay.COLUMNS * pair.overlay.HEAT_ROWS, "a 2-D heat map for 2 sensors")
	check(wide.overlay.draws > 0 and wide.overlay.rows == 0 and wide.overlay.probabilities.size() == 4,
		"with 3 sensors the overlay draws the bars only")
	var shown = wide.overlay
	wide.debug_overlay = false
	check(wide.overlay == null and shown.is_queued_for_deletion(), "turning debug_overlay off removes the overlay")
	for i in range(2 * SEEDS.size(), npcs.size()):
		npcs[i].queue_free()  # they save on exit; _finalize removes the save
	quit()


func _finalize():
	Directory.new().remove("user://line_npc.xml")  # the NPCs without the node saved on exit
	report("verve godot node")


func _init():
	test_settings()
	test_signals()
	test_refusals()
	test_save_load()
	start_npcs()  # runs frame by frame: _idle
