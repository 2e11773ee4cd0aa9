"""The scene, camera, sun and world that scripts/render_*.py share: a view from above one corner."""
import math

import bpy


def cycles_scene(out_path, samples):
    """An empty scene that Cycles renders on the CPU to a 512x512 out_path."""
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = samples
    scene.cycles.use_denoising = False  # Debian's build has no OpenImageDenoise
    scene.render.resolution_x = scene.render.resolution_y = 512
    scene.render.filepath = out_path
    return scene


def light_and_frame(scene, size):
    """A camera 2.2 sizes away looking at the origin, a sun and a grey world."""
    camera = bpy.data.objects.new("camera", bpy.data.cameras.new("camera"))
    scene.collection.objects.link(camera)
    distance = 2.2 * size
    camera.location = (distance * 0.8, -distance * 0.9, distance * 0.7)
    camera.rotation_euler = (-camera.location).to_track_quat("-Z", "Y").to_euler()
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
