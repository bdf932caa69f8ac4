# Enabling the addon (Project Settings > Plugins) adds VerveAgentNode to the editor's "Add Node"
# dialog. Only the editor needs this: games and tests can preload verve_agent_node.gd directly.
tool
extends EditorPlugin


func _enter_tree():
	# No icon of our own: Godot shows the base type's.
	add_custom_type("VerveAgentNode", "Node", preload("res://addons/verve/verve_agent_node.gd"), null)


func _exit_tree():
	remove_custom_type("VerveAgentNode")
