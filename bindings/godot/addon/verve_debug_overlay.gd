# What a VerveAgentNode wants and expects, drawn over the game (its `debug_overlay` export): one
# bar per action, its probability at the latest decision (the chosen one brighter), and, for an
# agent with 1 or 2 continuous sensors, its value over them as a heat map (sample_values: the other
# sensors held at the latest observation; across: sensor 0 from -1 to 1, down: sensor 1), brighter
# where it expects more, with a white mark at the latest observation.
extends Control

const BAR = Vector2(120, 10)
const CELL = 4.0
const COLUMNS = 32
const HEAT_ROWS = 24      # with 2 sensors; 1 row per value with 1
const LOW = Color(0.1, 0.1, 0.35)
const HIGH = Color(1.0, 0.85, 0.2)

# Re-sampling the values costs one evaluation per cell: at most this often, in decision time.
export(float) var heat_map_interval = 0.5

var node                  # the VerveAgentNode
var probabilities = PoolRealArray()
var values = PoolRealArray()
var rows = 0              # heat map rows; 0: no heat map
var draws = 0             # _draw calls (the tests count them)
var _since = INF          # decision time since the latest sampling


func _ready():
	mouse_filter = MOUSE_FILTER_IGNORE
	rect_position = Vector2(8, 8)


# After each decision (dt: game time since the previous one).
func refresh(dt):
	probabilities = node.agent.get_action_probabilities()
	_since += dt
	var sensors = node.continuous.size()
	if sensors >= 1 and sensors <= 2 and _since >= heat_map_interval:
		_since = 0.0
		var axes = [{"kind": "continuous", "index": 0, "samples": COLUMNS}]
		if sensors == 2:
			axes.append({"kind": "continuous", "index": 1, "samples": HEAT_ROWS})
		var sampled = node.agent.sample_values(axes, node.discrete, node.continuous)
		if sampled != null:   # null: the agent printed why
			values = sampled
			rows = HEAT_ROWS if sensors == 2 else 1
	rect_size = Vector2(max(BAR.x, COLUMNS * CELL), probabilities.size() * (BAR.y + 2) + 4 + _heat_height())
	update()


func _heat_height():
	return 0.0 if rows == 0 else (rows * CELL if rows > 1 else 3 * CELL)


func _draw():
	draws += 1
	draw_rect(Rect2(Vector2.ZERO, rect_size), Color(0, 0, 0, 0.6))
	for i in probabilities.size():
		var y = 2 + i * (BAR.y + 2)
		var color = Color(0.4, 0.9, 0.4) if i == node.action else Color(0.25, 0.5, 0.25)
		draw_rect(Rect2(2, y, BAR.x * probabilities[i], BAR.y), color)
	if rows == 0:
		return
	var top = 4 + probabilities.size() * (BAR.y + 2)
	var low = values[0]
	var high = values[0]
	for v in values:
		low = min(low, v)
		high = max(high, v)
	var height = _heat_height() / rows
	for r in rows:
		for c in COLUMNS:
			var t = (values[r * COLUMNS + c] - low) / (high - low) if high > low else 0.5
			draw_rect(Rect2(c * CELL, top + r * height, CELL, height), LOW.linear_interpolate(HIGH, t))
	# The latest observation: sensor values in [-1, 1] to the map's corners.
	var seen = Vector2((node.continuous[0] + 1.0) / 2.0 * COLUMNS * CELL,
		top + ((node.continuous[1] + 1.0) / 2.0 * rows * height if rows > 1 else _heat_height() / 2))
	draw_rect(Rect2(seen - Vector2(1.5, 1.5), Vector2(3, 3)), Color.white)
