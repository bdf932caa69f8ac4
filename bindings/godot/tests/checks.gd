# What both engine test scripts (test_agent.gd, test_crowd.gd) check with: a failure count and
# the exit code it gives.
extends SceneTree

var failures = 0


# A new agent made from `options`, its creation checked (scripts with default options override it).
func new_agent(options):
	var agent = preload("res://addons/verve/verve_agent.gdns").new()
	check(agent.create(options), "create(%s): %s" % [options, agent.get_last_error()])
	return agent


func check(condition, what):
	if not condition:
		failures += 1
		print("FAIL: ", what)


# The call failed the way the binding promises: the expected return and a message naming it.
func check_error(object, result, expected, message_part, what):
	check(typeof(result) == typeof(expected) and result == expected, "%s returns %s (got %s)" % [what, expected, result])
	check(message_part in object.get_last_error(), "%s: '%s' in '%s'" % [what, message_part, object.get_last_error()])


# Prints the count under `name` and sets the exit code: 1 on any failure.
func report(name):
	print("%s: %d failures" % [name, failures])
	OS.exit_code = 0 if failures == 0 else 1
