"""Renders solidtex particle meshes headless with Blender's Cycles, in their own colours.

Usage: blender -b --python scripts/render_meshes.py -- MESHES.ply|MESHES.obj OUT.png [SAMPLES]
PLY colours come from its vertex colours, OBJ colours from its MTL materials. Both are imported
without turning axes, so the meshes sit where the .vdb's voxels do.
"""
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from blender_scene import cycles_scene, light_and_frame  # noqa: E402

args = sys.argv[sys.argv.index("--") + 1:]
mesh_path, out_path = args[0], args[1]
samples = int(args[2]) if len(args) > 2 else 32

scene = cycles_scene(out_path, samples)

if mesh_path.endswith(".obj"):
    bpy.ops.wm.obj_import(filepath=mesh_path, forward_axis="Y", up_axis="Z")
else:
    bpy.ops.import_mesh.ply(filepath=mesh_path)
    material = bpy.data.materials.new("vertex colours")
    material.use_nodes = True
    nodes = material.node_tree.nodes
    colours = nodes.new("ShaderNodeVertexColor")
    material.node_tree.links.new(colours.outputs["Color"], nodes["Principled BSDF"].inputs["Base Color"])
    for obj in bpy.context.selected_objects:
        obj.data.materials.append(material)

objects = [o for o in scene.objects if o.type == "MESH"]
lo = [min(min((o.matrix_world @ v.co)[a] for v in o.data.vertices) for o in objects) for a in range(3)]
hi = [max(max((o.matrix_world @ v.co)[a] for v in o.data.vertices) for o in objects) for a in range(3)]
centre = [(l + h) / 2 for l, h in zip(lo, hi)]
size = max(h - l for l, h in zip(lo, hi))
for o in objects:
    o.location = [o.location[a] - centre[a] for a in range(3)]

light_and_frame(scene, size)

bpy.ops.render.render(write_still=True)
print(f"rendered {len(objects)} objects of {mesh_path} to {out_path}")
