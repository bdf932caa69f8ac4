# Teach a pet a trick, in Godot 3: the port of samples/love_pet (docs/teaching.md), the same game.
# The pet lives in a 7 x 7 yard. Its trick: walk to the ball and sit on it; then it gets a treat
# (+1, the only reward the game gives) and the ball lands somewhere else. It senses where the ball
# is from where it stands and chooses one of five actions: a step north, east, south or west, or sit.
# Alone it finds the trick by chance, slowly. You can help:
#   arrow keys, S   take the controls: the step you press is a demonstrated step, learned from as
#                   if the pet had chosen it (VerveAgent.update_demonstrated); let go and it acts
#   G / B           "good" / "bad": praise or scold what it did over the last moments (teach)
#   Space           fast-forward (x20)   Esc quit
#
#   godot3 --path build/godot/pet                                     play
#   godot3-server --path build/godot/pet --fixed-fps 60 --verve-test  headless, the scripted teacher
#
# --verve-test: a scripted teacher plays your part over seeds 1-10 in three modes, as samples/love_pet
# does headless, and the run reports after how many trials the pet learned the trick (five trials in
# a row within 6 steps of the shortest way; trials counted including the shown ones):
#   shown     the teacher takes the controls for the first 30 trials
#   praised   for the first 40 trials the teacher clicks "good" half a second after the pet sits on
#             the ball and "bad" after it sits anywhere else
#   alone     no teacher
# It passes when every shown and praised run learns, and alone takes at least 3x the trials of shown
# and 1.3x those of praised.
extends Node2D

const VerveAgent = preload("res://addons/verve/verve_agent.gdns")

const SIZE = 7                   # cells a side
const STEP = 0.1                 # seconds per decision
const CAP = 100                  # steps before a trial is cut
enum { NORTH, EAST, SOUTH, WEST, SIT }   # the pet's actions, 0 .. 4
const MOVES = [Vector2(0, -1), Vector2(1, 0), Vector2(0, 1), Vector2(-1, 0)]
const PRAISE_DELAY = 0.5
const PRAISE_TRIALS = 40
const MAX_TRIALS = 2000
const CELL = 56
const TEST_SEEDS = 10
const TEST_SHOWN = 30
const TEST_MODES = ["alone", "shown", "praised"]

var testing = "--verve-test" in OS.get_cmdline_args()
var shown_unlearned = false   # a run of that mode never learned the trick
var praised_unlearned = false
var rng = RandomNumberGenerator.new()
var agent = null
var seed_number = 1
var shown_trials = 0    # the scripted teacher drives the first shown_trials trials (headless)
var praising = false    # the scripted teacher clicks good / bad after each sit (headless)
var scripted = false    # a scripted teacher, not the player
var pet = Vector2()
var ball = Vector2()
var trial = 1
var trial_steps = 0
var trial_shortest = 0
var reward = 0.0
var treats = 0
var in_a_row = 0
var learned_at = 0      # 0: not yet
var clicks = []         # scripted praise waiting: [due seconds, +1 or -1]
var clock = 0.0
var held = -1           # the action the player holds, -1: none
var pending = 0.0
var fast = false
var test_run = 0        # --verve-test: runs done, seed after seed, mode after mode
var sums = {"alone": 0.0, "shown": 0.0, "praised": 0.0}
var failed = false
var unlearned = []     # the runs that did not learn within MAX_TRIALS
var finished = false    # quit asked: Godot quits at the end of the frame
var hud = null          # the text beside the yard (not made in --verve-test)


func _ready():
	if testing:
		return  # _process runs the test, a run a frame
	hud = Label.new()
	hud.rect_position = Vector2(SIZE * CELL + 40, 30)
	add_child(hud)
	start(1, 0, false, false)


# A new pet with a new agent; the same seed gives the same yard.
func start(seed_value, shown, praise, script):
	seed_number = seed_value
	shown_trials = shown
	praising = praise
	scripted = script
	rng.seed = seed_value
	agent = VerveAgent.new()
	if not agent.create({"continuous_sensor_circular": [false, false], "actions": 5, "seed": seed_value}):
		get_tree().quit(1)  # the error is printed already
		return false
	agent.teach(0.0)  # remember what it does, for the player's (or the script's) praise
	trial = 1
	treats = 0
	in_a_row = 0
	learned_at = 0
	clicks.clear()
	clock = 0.0
	new_trial()
	return true


# The ball's offset from the pet, scaled into [-1, 1]: the trick is the same wherever the ball is.
func sensors():
	return PoolRealArray([(ball.x - pet.x) / (SIZE - 1), (ball.y - pet.y) / (SIZE - 1)])


func new_trial():
	pet = Vector2(rng.randi_range(0, SIZE - 1), rng.randi_range(0, SIZE - 1))
	ball = pet
	while ball == pet:
		ball = Vector2(rng.randi_range(0, SIZE - 1), rng.randi_range(0, SIZE - 1))
	trial_steps = 0
	reward = 0.0
	trial_shortest = int(abs(ball.x - pet.x) + abs(ball.y - pet.y)) + 1


# The scripted teacher's choice: a shortest way to the ball, then sit.
func teacher_action():
	if pet == ball:
		return SIT
	var d = ball - pet
	if d.x != 0 and (d.y == 0 or rng.randf() < 0.5):
		return EAST if d.x > 0 else WEST
	return SOUTH if d.y > 0 else NORTH


func end_trial(done):
	if done:
		agent.end_episode(1.0)
		treats += 1
	else:
		agent.truncate_episode(0.0)
	var alone = trial > shown_trials and held < 0
	in_a_row = in_a_row + 1 if alone and done and trial_steps <= trial_shortest + 6 else 0
	if in_a_row == 5 and learned_at == 0:
		learned_at = trial
	trial += 1
	new_trial()


func step():
	clock += STEP
	var shown = held
	if scripted and trial <= shown_trials:
		shown = teacher_action()
	var action = shown
	if shown >= 0:
		agent.update_demonstrated(reward, PoolIntArray(), sensors(), STEP, shown)
	else:
		action = agent.update(reward, PoolIntArray(), sensors(), STEP)
		if action < 0:
			get_tree().quit(1)  # the error is printed already
			return
	var before = int(abs(ball.x - pet.x) + abs(ball.y - pet.y))
	reward = 0.0
	trial_steps += 1
	if praising and trial <= PRAISE_TRIALS and action == SIT:
		clicks.append([clock + PRAISE_DELAY, 1.0 if before == 0 else -1.0])
	if action == SIT:
		if pet == ball:
			end_trial(true)
			return
	else:
		pet.x = clamp(pet.x + MOVES[action].x, 0, SIZE - 1)
		pet.y = clamp(pet.y + MOVES[action].y, 0, SIZE - 1)
	if trial_steps >= CAP:
		end_trial(false)


func deliver_clicks():
	while not clicks.empty() and clicks[0][0] <= clock + 1e-9:
		agent.teach(clicks.pop_front()[1])


func _process(delta):
	if testing:
		test_progress()
		return
	held = -1
	var keys = {KEY_UP: NORTH, KEY_RIGHT: EAST, KEY_DOWN: SOUTH, KEY_LEFT: WEST, KEY_S: SIT}
	for key in keys:
		if Input.is_key_pressed(key):
			held = keys[key]
	pending = min(pending + delta * (20 if fast else 1), 1.0)
	while pending >= STEP:
		step()
		pending -= STEP
	update()  # redraw


func _unhandled_input(event):
	if testing or not (event is InputEventKey and event.pressed and not event.echo):
		return
	match event.scancode:
		KEY_G:
			agent.teach(1.0)
		KEY_B:
			agent.teach(-1.0)
		KEY_SPACE:
			fast = not fast
		KEY_ESCAPE:
			get_tree().quit()


func _draw():
	if testing:
		return
	var origin = Vector2(20, 20)
	for x in SIZE:
		for y in SIZE:
			draw_rect(Rect2(origin + Vector2(x * CELL + 1, y * CELL + 1), Vector2(CELL - 2, CELL - 2)),
				Color(0.2, 0.32, 0.18))
	draw_circle(origin + (ball + Vector2(0.5, 0.5)) * CELL, CELL * 0.18, Color(0.95, 0.9, 0.3))
	draw_circle(origin + (pet + Vector2(0.5, 0.5)) * CELL, CELL * 0.32, Color(0.85, 0.6, 0.35))
	var lines = [
		"trial %d, step %d" % [trial, trial_steps],
		"treats: %d" % treats,
		"learned at trial %d" % learned_at if learned_at > 0 else "learning...",
		"",
		"you have the controls" if held >= 0 else "the pet acts",
		"",
		"arrows, S: take the controls", "G / B: good / bad", "Space: fast-forward", "Esc: quit"]
	hud.text = PoolStringArray(lines).join("\n")


# --verve-test: one run (a seed in one mode) a frame; the scripted teacher plays the player's part.
func test_progress():
	if finished:
		return
	var seed_value = 1 + test_run / TEST_MODES.size()
	if seed_value > TEST_SEEDS:
		report()
		return
	var mode = TEST_MODES[test_run % TEST_MODES.size()]
	if not start(seed_value, TEST_SHOWN if mode == "shown" else 0, mode == "praised", true):
		finished = true
		return
	while learned_at == 0 and trial <= MAX_TRIALS:
		step()
		deliver_clicks()
	var text = str(learned_at) if learned_at > 0 else "more than %d" % MAX_TRIALS
	print("pet seed %d, %s: learned the trick after %s trials, %d treats" % [seed_value, mode, text, treats])
	if learned_at == 0:
		failed = true  # counted as MAX_TRIALS + 1 below: the mean is then a lower bound
		unlearned.append("seed %d %s" % [seed_value, mode])
		if mode == "shown":
			shown_unlearned = true
		elif mode == "praised":
			praised_unlearned = true
	sums[mode] += (learned_at if learned_at > 0 else MAX_TRIALS + 1) / float(TEST_SEEDS)
	test_run += 1


func report():
	var alone = sums["alone"]
	var shown = sums["shown"]
	var praised = sums["praised"]
	print("mean of %d seeds: alone %.1f, shown for %d trials %.1f, praised %.1f" % [TEST_SEEDS, alone, TEST_SHOWN,
		shown, praised])
	if failed:
		print("not learned within %d trials (counted as %d): %s" % [MAX_TRIALS, MAX_TRIALS + 1,
			PoolStringArray(unlearned).join(", ")])
	print("alone / shown %.2f (needs 3), alone / praised %.2f (needs 1.3)" % [alone / shown, alone / praised])
	finished = true
	# A shown or praised run that never learns fails its bar (an alone one only raises the mean).
	var shown_ok = alone >= 3.0 * shown and not shown_unlearned
	var praise_ok = alone >= 1.3 * praised and not praised_unlearned
	var ok = shown_ok and praise_ok
	print("verve godot pet: ", "PASS" if ok else "FAIL")
	get_tree().quit(0 if ok else 1)
