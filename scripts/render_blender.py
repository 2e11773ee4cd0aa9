"""Renders a solidtex .vdb headless with Blender's Cycles, colour from the `color` grid.

Usage: blender -b --python scripts/render_blender.py -- VOLUME.vdb OUT.png [SAMPLES]
"""
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from blender_scene import cycles_scene, light_and_frame  # noqa: E402

args = sys.argv[sys.argv.index("--") + 1:]
volume_path, out_path = args[0], args[1]
samples = int(args[2]) if len(args) > 2 else 32

scene = cycles_scene(out_path, samples)

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

light_and_frame(scene, size)

bpy.ops.render.render(write_still=True)
print(f"rendered {volume_path} to {out_path}")
