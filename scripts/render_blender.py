"""Renders a solidtex .vdb headless with Blender's Cycles, colour from the `color` grid.

Usage: blender -b --python scripts/render_blender.py -- VOLUME.vdb OUT.png [SAMPLES]
"""
import math
import sys

import bpy

args = sys.argv[sys.argv.index("--") + 1:]
volume_path, out_path = args[0], args[1]
samples = int(args[2]) if len(args) > 2 else 32

bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene
scene.render.engine = "CYCLES"
scene.cycles.device = "CPU"
scene.cycles.samples = samples
scene.cycles.use_denoising = False  # Debian's build has no OpenImageDenoise
scene.render.resolution_x = scene.render.resolution_y = 512
scene.render.filepath = out_path

bpy.ops.object.volume_import(filepath=volume_path)
volume = bpy.context.active_object
size = max(volume.dimensions)
volume.location = (-volume.dimensions.x / 2, -volume.dimensions.y / 2, -volume.dimensions.z / 2)

material = bpy.data.materials.new("solidtex")
material.use_nodes = True
nodes = material.node_tree.nodes
nodes.clear()
shader = nodes.new("ShaderNodeVolumePrincipled")
shader.inputs["Color Attribute"].default_value = "color"
shader.inputs["Density"].default_value = 20.0 / size
output = nodes.new("ShaderNodeOutputMaterial")
material.node_tree.links.new(shader.outputs["Volume"], output.inputs["Volume"])
volume.data.materials.append(material)

camera_data = bpy.data.cameras.new("camera")
camera = bpy.data.objects.new("camera", camera_data)
scene.collection.objects.link(camera)
distance = 2.2 * size
camera.location = (distance * 0.8, -distance * 0.9, distance * 0.7)
direction = -camera.location
camera.rotation_euler = direction.to_track_quat("-Z", "Y").to_euler()
scene.camera = camera

sun_data = bpy.data.lights.new("sun", type="SUN")
sun_data.energy = 4.0
sun = bpy.data.objects.new("sun", sun_data)
sun.rotation_euler = (math.radians(40), math.radians(20), math.radians(30))
scene.collection.objects.link(sun)
world = bpy.data.worlds.new("world")
world.use_nodes = True
world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.6
scene.world = world

bpy.ops.render.render(write_still=True)
print(f"rendered {volume_path} to {out_path}")
