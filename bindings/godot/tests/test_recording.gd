# VerveRecording inside the real engine (docs/teaching.md, "Recordings"): demonstrated steps and
# trial ends recorded while an agent is shown them, saved to user:// and to bytes, loaded back and
# replayed into a fresh agent, which must then save byte for byte as the shown agent does. Every
# refused call must return false / -1 / null, give its error in get_last_error() and change nothing.
#   godot3-server --path build/godot/tests --script res://test_recording.gd   (exit code 1 on a failure)
extends "res://checks.gd"

const VerveAgent = preload("res://addons/verve/verve_agent.gdns")
const VerveBrain = preload("res://addons/verve/verve_brain.gdns")
const VerveRecording = preload("res://addons/verve/verve_recording.gdns")
const OPTIONS = {"discrete_sensors": [3], "continuous_sensor_circular": [true, false], "actions": 3, "seed": 7}
const OTHER_ACTIONS = {"discrete_sensors": [3], "continuous_sensor_circular": [true, false], "actions": 4, "seed": 7}
const PATH = "user://recording.vrec"


func new_agent(options = OPTIONS):
	var agent = VerveAgent.new()
	check(agent.create(options), "create(%s): %s" % [options, agent.get_last_error()])
	return agent


func new_recording(agent):
	var rec = VerveRecording.new()
	check(rec.create(agent), "VerveRecording.create: " + rec.get_last_error())
	return rec


# What step i shows: [reward, discrete, continuous, dt, action].
func shown(i):
	return [1.0 if i % 7 == 0 else 0.0, PoolIntArray([i % 3]), PoolRealArray([sin(i * 0.3), cos(i * 0.2)]), 0.1,
		(i / 4) % 3]


# 30 demonstrated steps in three trials (an end, a truncation, an end), each shown to `agent` and
# recorded into `rec` with the same arguments.
func demonstrate(agent, rec):
	for i in range(30):
		var s = shown(i)
		check(agent.update_demonstrated(s[0], s[1], s[2], s[3], s[4]), "update_demonstrated: " + agent.get_last_error())
		check(rec.add_step(s[0], s[1], s[2], s[3], s[4]), "add_step %d: %s" % [i, rec.get_last_error()])
		if i == 9:
			check(agent.end_episode(1.0) and rec.add_end_episode(1.0), "a trial's end: " + rec.get_last_error())
		elif i == 19:
			check(agent.truncate_episode(0.5) and rec.add_truncation(0.5), "a truncation: " + rec.get_last_error())
	check(agent.end_episode(-1.0) and rec.add_end_episode(-1.0), "the last trial's end: " + rec.get_last_error())


# A fresh agent with the shown agent's options, trained by replaying rec: its save must be the shown one's.
func check_replays(rec, shown_agent, what):
	var fresh = new_agent()
	check(fresh.replay(rec), "%s: replay: %s" % [what, fresh.get_last_error()])
	check(fresh.get_last_error() == "", "%s: a successful replay clears the error" % what)
	var expected = shown_agent.save_bytes()
	var got = fresh.save_bytes()
	check(new_agent().save_bytes() != expected, "%s: the demonstrations changed the shown agent" % what)
	check(typeof(got) == TYPE_RAW_ARRAY and got.size() > 100 and got == expected,
		"%s: the replayed agent saves byte for byte as the demonstrated one" % what)


func test_record_save_load_replay():
	var shown_agent = new_agent()
	var rec = new_recording(shown_agent)
	check(rec.has_recording() and rec.get_size() == 0, "a new recording is empty")
	demonstrate(shown_agent, rec)
	check(rec.get_size() == 33, "30 steps and 3 trial ends are 33 entries (got %s)" % rec.get_size())
	check_replays(rec, shown_agent, "the recording in memory")

	Directory.new().remove(PATH)
	check(rec.save(PATH), "save %s: %s" % [PATH, rec.get_last_error()])
	var from_file = VerveRecording.new()
	check(from_file.load(PATH), "load %s: %s" % [PATH, from_file.get_last_error()])
	check(from_file.get_size() == 33, "a loaded file has every entry")
	check_replays(from_file, shown_agent, "the recording from user://")
	Directory.new().remove(PATH)

	var bytes = rec.save_bytes()
	check(typeof(bytes) == TYPE_RAW_ARRAY and bytes.size() > 32, "save_bytes: " + rec.get_last_error())
	var from_bytes = VerveRecording.new()
	check(from_bytes.load_bytes(bytes), "load_bytes: " + from_bytes.get_last_error())
	check(from_bytes.get_size() == 33, "loaded bytes have every entry")
	check(from_bytes.save_bytes() == bytes, "loaded bytes save as they were")
	check_replays(from_bytes, shown_agent, "the recording from bytes")

	# A body of a shared brain takes a recording as a separate agent does.
	var brain = VerveBrain.new()
	check(brain.create(OPTIONS), "VerveBrain.create: " + brain.get_last_error())
	var body = brain.create_body()
	check(body != null and body.replay(rec) and body.get_stats()["steps"] > 0, "a brain's body replays: " + body.get_last_error())
	var from_body = VerveRecording.new()
	check(from_body.create(body) and from_body.get_size() == 0, "a recording shaped like a body: " + from_body.get_last_error())


func test_refused_entries():
	var agent = new_agent()
	var rec = new_recording(agent)
	check(rec.add_step(0.0, [1], [0.2, -0.3], 0.1, 2), "a good step")
	check_error(rec, rec.add_step(0.0, [1], [0.2, -0.3], 0.1, 3), false, "[VERVE_ERROR_INVALID_ARGUMENT]", "an action out of range")
	check_error(rec, rec.add_step(0.0, [1], [0.2, -0.3], 0.1, -1), false, "action must be 0 .. actions-1", "a negative action")
	check_error(rec, rec.add_step(0.0, [1], [0.2, -0.3], 0.1, 1.5), false, "action must be an int", "an action that is not an int")
	check_error(rec, rec.add_step(0.0, [1, 2], [0.2, -0.3], 0.1, 0), false, "[VERVE_ERROR_INVALID_ARGUMENT]", "two discrete values for one sensor")
	check_error(rec, rec.add_step(0.0, [1], [0.2], 0.1, 0), false, "[VERVE_ERROR_INVALID_ARGUMENT]", "one continuous value for two sensors")
	check_error(rec, rec.add_step(0.0, [5], [0.2, -0.3], 0.1, 0), false, "[VERVE_ERROR", "a discrete value out of range")
	check_error(rec, rec.add_step(0.0, [1], [NAN, -0.3], 0.1, 0), false, "[VERVE_ERROR", "a NaN sensor")
	check_error(rec, rec.add_step("a lot", [1], [0.2, -0.3], 0.1, 0), false, "reward must be", "a String reward")
	check_error(rec, rec.add_step(0.0, "1", [0.2, -0.3], 0.1, 0), false, "discrete must be", "a String for discrete")
	check_error(rec, rec.add_step(0.0, [1], [0.2, -0.3], 0.1), false, "takes 5 arguments", "a missing action")
	check_error(rec, rec.add_end_episode("won"), false, "final_reward must be", "a String final reward")
	check_error(rec, rec.add_truncation(NAN), false, "[VERVE_ERROR", "a NaN truncation reward")
	check(rec.get_size() == 1, "refused entries are not recorded (size %s)" % rec.get_size())
	check(rec.add_end_episode(0.0) and rec.get_last_error() == "", "a success clears the error")


func test_damaged_bytes():
	var agent = new_agent()
	var rec = new_recording(agent)
	demonstrate(agent, rec)
	var bytes = rec.save_bytes()
	var damaged = PoolByteArray(bytes)
	damaged[bytes.size() - 5] = damaged[bytes.size() - 5] ^ 0x40
	var target = VerveRecording.new()
	check(target.load_bytes(bytes), "load_bytes: " + target.get_last_error())
	check_error(target, target.load_bytes(damaged), false, "checksum", "a flipped byte")
	check_error(target, target.load_bytes(bytes.subarray(0, bytes.size() / 2)), false, "[VERVE_ERROR_FORMAT]", "truncated bytes")
	check_error(target, target.load_bytes(PoolByteArray()), false, "[VERVE_ERROR", "no bytes")
	check_error(target, target.load_bytes("VERVEREC"), false, "data must be a PoolByteArray", "a String for bytes")
	check_error(target, target.load("user://no_such_recording.vrec"), false, "[VERVE_ERROR_IO]", "a missing file")
	check_error(target, target.load(3), false, "path must be a String", "an int path")
	check_error(rec, rec.save("user://no/such/folder/rec.vrec"), false, "[VERVE_ERROR_IO]", "a folder that does not exist")
	check(target.has_recording() and target.save_bytes() == bytes, "failed loads keep the recording")
	check_error(agent, agent.load_bytes(bytes), false, "[VERVE_ERROR", "a recording is not an agent save")


func test_replay_refusals():
	var shown_agent = new_agent()
	var rec = new_recording(shown_agent)
	demonstrate(shown_agent, rec)
	var other = new_agent(OTHER_ACTIONS)
	var before = other.save_bytes()
	check_error(other, other.replay(rec), false, "[VERVE_ERROR_INVALID_ARGUMENT]", "a replay into an agent with other actions")
	check(other.save_bytes() == before, "a refused replay changes nothing")
	var fewer = new_agent({"continuous_sensor_circular": [true, false], "actions": 3, "seed": 7})
	var fewer_before = fewer.save_bytes()
	check_error(fewer, fewer.replay(rec), false, "[VERVE_ERROR_INVALID_ARGUMENT]", "a replay into an agent with other sensors")
	check(fewer.save_bytes() == fewer_before, "a refused replay changes no agent")
	var a = new_agent()
	var a_before = a.save_bytes()
	check_error(a, a.replay(VerveRecording.new()), false, "without a recording", "an empty VerveRecording")
	check_error(a, a.replay(a), false, "recording must be a VerveRecording (got a VerveAgent)", "a VerveAgent for a recording")
	check_error(a, a.replay(null), false, "recording must be a VerveRecording (got null)", "null for a recording")
	check_error(a, a.replay("rec"), false, "recording must be a VerveRecording", "a String for a recording")
	check(a.save_bytes() == a_before, "refused replays change nothing")
	var closed = VerveAgent.new()
	check_error(closed, closed.replay(rec), false, "has no agent", "a replay into no agent")
	var bad = VerveRecording.new()
	check_error(bad, bad.create(closed), false, "without an agent", "create from a VerveAgent with no agent")
	check_error(bad, bad.create(rec), false, "agent must be a VerveAgent (got a VerveRecording)", "create from a VerveRecording")
	check_error(bad, bad.create(null), false, "agent must be a VerveAgent (got null)", "create from null")
	check_error(bad, bad.create(), false, "takes 1 arguments", "create without an agent")
	check(not bad.has_recording(), "failed creates make no recording")


func test_empty_recording():
	var empty = VerveRecording.new()
	var closed = new_recording(new_agent())
	closed.close()
	for rec in [empty, closed]:
		check(not rec.has_recording(), "has_recording() is false")
		check_error(rec, rec.add_step(0.0, [1], [0.2, -0.3], 0.1, 0), false, "has no recording", "add_step without a recording")
		check_error(rec, rec.add_end_episode(0.0), false, "has no recording", "add_end_episode without a recording")
		check_error(rec, rec.add_truncation(0.0), false, "has no recording", "add_truncation without a recording")
		check_error(rec, rec.get_size(), -1, "has no recording", "get_size without a recording")
		check_error(rec, rec.save("user://x.vrec"), false, "has no recording", "save without a recording")
		check_error(rec, rec.save_bytes(), null, "has no recording", "save_bytes without a recording")
	closed.close()  # twice is fine
	check(closed.create(new_agent()) and closed.has_recording(), "a closed VerveRecording can create again")


func _init():
	test_record_save_load_replay()
	test_refused_entries()
	test_damaged_bytes()
	test_replay_refusals()
	test_empty_recording()
	report("verve godot recording")
	quit()
