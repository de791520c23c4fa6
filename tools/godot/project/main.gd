# Draws a sphere with the ShaderMaterial in res://shader.shader (written by try_godot3.sh),
# saves the frame to the path in the environment variable PBRLAB_GODOT_OUT, and quits.
extends Spatial

func _ready():
	var source = File.new()
	source.open("res://shader.shader", File.READ)
	var shader = Shader.new()
	shader.code = source.get_as_text()
	source.close()
	var material = ShaderMaterial.new()
	material.shader = shader
	var sphere = MeshInstance.new()
	sphere.mesh = SphereMesh.new()
	sphere.material_override = material
	add_child(sphere)
	var camera = Camera.new()
	camera.translation = Vector3(0, 0, 3)
	add_child(camera)
	camera.current = true
	yield(get_tree(), "idle_frame")
	yield(VisualServer, "frame_post_draw")
	var frame = get_viewport().get_texture().get_data()
	frame.flip_y()
	frame.save_png(OS.get_environment("PBRLAB_GODOT_OUT"))
	get_tree().quit()
