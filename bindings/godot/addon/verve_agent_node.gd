# A learning agent as a scene node: its settings in the inspector, its decisions as signals.
# It wraps the GDNative VerveAgent (verve_agent.gdns), kept in `agent` for anything not wrapped
# here (stats, teach, sample_values). Call act() every physics tick: it decides every
# decision_interval seconds of game time and repeats the decision in between (docs/tuning.md).
extends Node

signal action_chosen(action)
signal episode_ended(final_reward, truncated)

const VerveAgent = preload("res://addons/verve/verve_agent.gdns")
const Overlay = preload("res://addons/verve/verve_debug_overlay.gd")

export(int, 1, 64) var actions = 2
export(int, 0, 64) var continuous_sensors = 0          # each reads a value in [-1, 1]
export(PoolIntArray) var circular_sensors = PoolIntArray()  # which continuous sensors wrap (angles)
export(PoolIntArray) var discrete_sensors = PoolIntArray()  # each one's value count
# Below, a negative seed and times of 0 take libverve's defaults (get_options() shows them).
export(int) var random_seed = -1
export(float) var tau_value = 0.0                       # seconds: how fast values are learned
export(float) var tau_discount = 0.0                    # seconds: how far ahead rewards count
export(float) var tau_eligibility = 0.0                 # seconds: how far back credit goes
export(Dictionary) var extra_options = {}               # any other create() option (docs/godot.md)
export(float) var decision_interval = 0.1               # seconds; 0 decides at every act()
export(bool) var learning = true setget set_learning
export(bool) var greedy = false setget set_greedy       # always the most probable action
export(String) var save_path = ""                       # loaded at _ready if it exists, saved on exit
export(bool) var debug_overlay = false setget set_debug_overlay

var agent = null          # the native VerveAgent
var action = -1           # the latest decision, repeated until the next one
var overlay = null        # the debug overlay, while shown
var last_error = ""       # the latest refusal, "" if none
var discrete = PoolIntArray()     # the latest decision's observation (the overlay's slice)
var continuous = PoolRealArray()
var _reward = 0.0         # earned since the latest decision
var _clock = 0.0          # game time since the latest decision


func _ready():
	if create_agent() and debug_overlay:
		set_debug_overlay(true)


func _exit_tree():
	if save_path != "" and agent != null and agent.has_agent():
		save_agent(save_path)


# The create() options the exports give.
func get_create_options():
	var circular = []
	for i in continuous_sensors:
		circular.append(Array(circular_sensors).has(i))
	var options = {"actions": actions, "continuous_sensor_circular": circular,
		"discrete_sensors": Array(discrete_sensors)}
	if random_seed >= 0:
		options["seed"] = random_seed
	for key in ["tau_value", "tau_discount", "tau_eligibility"]:
		if get(key) > 0.0:
			options[key] = get(key)
	for key in extra_options:
		options[key] = extra_options[key]
	return options


# Makes the agent: from save_path if that file exists, else new from the exports. Called by _ready;
# call it again after changing the exports to start over.
func create_agent():
	for i in circular_sensors:
		if i < 0 or i >= continuous_sensors:
			return _refuse("create", "circular_sensors names sensor %d; there are %d continuous sensors" % [i, continuous_sensors])
	agent = VerveAgent.new()
	var made = agent.load(save_path) if save_path != "" and File.new().file_exists(save_path) \
		else agent.create(get_create_options())
	if not made:
		return _fail("create")
	_apply_modes()
	action = -1
	_reward = 0.0
	_clock = 0.0
	return true


# Earns `reward`, lets `dt` of game time pass and returns the action to take: a new decision from the
# observation when decision_interval has passed since the previous one (or none was made since the
# episode began), else the previous one. `mask` (one 0/1 per action) limits the choice. -1 on error.
func act(reward, discrete_values, continuous_values, dt, mask = null):
	_reward += reward
	_clock += dt
	if not _due():
		return action
	if not _has_agent("act"):
		return -1
	var chosen = agent.update(_reward, discrete_values, continuous_values, _clock) if mask == null \
		else agent.update_masked(_reward, discrete_values, continuous_values, _clock, mask)
	if chosen < 0:
		_fail("act")
		return -1
	_decided(chosen, discrete_values, continuous_values)
	return chosen


# As act(), but the player or a scripted AI took `demonstrated` (docs/teaching.md): at a decision
# the agent learns from it and is pulled towards it. `continuous_action`, with continuous actions:
# the values played (one per continuous action, each in [-1, 1]; null plays the policy's means).
# Returns false on error.
func demonstrate(reward, discrete_values, continuous_values, dt, demonstrated, continuous_action = null):
	_reward += reward
	_clock += dt
	if not _due():
		return true
	if not _has_agent("demonstrate"):
		return false
	var shown = agent.update_demonstrated(_reward, discrete_values, continuous_values, _clock, demonstrated) \
		if continuous_action == null else agent.update_demonstrated_continuous(_reward, discrete_values, \
			continuous_values, _clock, demonstrated, continuous_action)
	if not shown:
		return _fail("demonstrate")
	_decided(demonstrated, discrete_values, continuous_values)
	return true


# The trial really ended (goal reached, death): the reward earned since the latest decision plus
# `final_reward` is its last. The next act() decides at once.
func end_episode(final_reward):
	return _end(final_reward, false)


# A time limit cut the trial off; it could have gone on.
func truncate_episode(reward):
	return _end(reward, true)


func save_agent(path = save_path):
	if not _has_agent("save"):
		return false
	return agent.save(path) or _fail("save to '%s'" % path)


# Replaces the agent by a saved one (on success only).
func load_agent(path = save_path):
	if agent == null:
		agent = VerveAgent.new()
	if not agent.load(path):
		return _fail("load from '%s'" % path)
	_apply_modes()
	action = -1
	return true


# The agent's options, libverve's defaults filled in; null without an agent.
func get_options():
	return agent.get_options() if _has_agent("get_options") else null


func set_learning(value):
	learning = value
	if agent != null and agent.has_agent():
		agent.learning = value


func set_greedy(value):
	greedy = value
	if agent != null and agent.has_agent():
		agent.greedy = value


func set_debug_overlay(value):
	debug_overlay = value
	if not is_inside_tree():
		return  # _ready shows it
	if value and overlay == null:
		overlay = Overlay.new()
		overlay.node = self
		add_child(overlay)
	elif not value and overlay != null:
		overlay.queue_free()
		overlay = null


func _due():
	return action < 0 or _clock + 1e-6 >= decision_interval  # 1e-6: six ticks of 1/60 s make 0.1 s


func _decided(chosen, discrete_values, continuous_values):
	action = chosen
	discrete = PoolIntArray(discrete_values if discrete_values != null else [])
	continuous = PoolRealArray(continuous_values if continuous_values != null else [])
	var dt = _clock
	_reward = 0.0
	_clock = 0.0
	if overlay != null:
		overlay.refresh(dt)
	emit_signal("action_chosen", chosen)


func _end(reward, truncated):
	if not _has_agent("end_episode" if not truncated else "truncate_episode"):
		return false
	var ok = agent.truncate_episode(_reward + reward) if truncated else agent.end_episode(_reward + reward)
	if not ok:
		return _fail("truncate_episode" if truncated else "end_episode")
	_reward = 0.0
	_clock = 0.0
	action = -1
	emit_signal("episode_ended", reward, truncated)
	return true


func _apply_modes():
	agent.learning = learning
	agent.greedy = greedy


func _has_agent(what):
	return agent != null and agent.has_agent() or _refuse(what, "no agent (create_agent() failed or was not called)")


func _fail(what):
	return _refuse(what, agent.get_last_error())


# Every refusal: kept in last_error and pushed as a Godot error naming this node.
func _refuse(what, message):
	last_error = "%s: %s" % [what, message]
	push_error("VerveAgentNode '%s' %s" % [name, last_error])
	return false
