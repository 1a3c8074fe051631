# Renders a .glb with Blender headless, as a user would see it after File > Import > glTF 2.0:
# the importer's own nodes, materials and texture sampling, a sun, a camera three-quarters
# from the front (glTF +Z, Blender -Y) and above, Cycles on the CPU.
#
#   blender -b --factory-startup --python tools/blender_render_glb.py -- MODEL.glb OUT.png [SIZE] [--pair]
#
# --pair: two renders side by side in one picture, same camera and light: on the left without the
# normal maps (the links out of the importer's Normal Map nodes cut), on the right as imported.
#
# Debian's Blender 3.4 glTF importer calls numpy's removed np.bool: set it before importing.
import math
import os
import sys

import numpy

numpy.bool = bool
import bpy  # noqa: E402
from mathutils import Vector  # noqa: E402

args = sys.argv[sys.argv.index("--") + 1:]
pair = "--pair" in args
args = [a for a in args if a != "--pair"]
glb, out = args[0], args[1]
size = int(args[2]) if len(args) > 2 else 640

bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.import_scene.gltf(filepath=glb)
meshes = [o for o in bpy.context.scene.objects if o.type == "MESH"]
points = [o.matrix_world @ Vector(c) for o in meshes for c in o.bound_box]
lo = Vector([min(p[a] for p in points) for a in range(3)])
hi = Vector([max(p[a] for p in points) for a in range(3)])
centre, radius = (lo + hi) / 2, (hi - lo).length / 2

scene = bpy.context.scene
camera = bpy.data.objects.new("camera", bpy.data.cameras.new("camera"))
scene.collection.objects.link(camera)
direction = Vector((0.75, -1.0, 0.6)).normalized()  # front-right, above: the front is -Y
camera.location = centre + direction * radius * 2.5
camera.rotation_euler = (centre - camera.location).to_track_quat("-Z", "Y").to_euler()
camera.data.lens = 50
scene.camera = camera
sun = bpy.data.objects.new("sun", bpy.data.lights.new("sun", "SUN"))
sun.data.energy = 4.0
sun.rotation_euler = (math.radians(40), math.radians(10), math.radians(30))
scene.collection.objects.link(sun)
world = bpy.data.worlds.new("world")
world.use_nodes = True
world.node_tree.nodes["Background"].inputs[0].default_value = (0.8, 0.82, 0.86, 1.0)
world.node_tree.nodes["Background"].inputs[1].default_value = 0.6
scene.world = world

scene.render.engine = "CYCLES"
scene.cycles.device = "CPU"
scene.cycles.samples = 48
scene.cycles.use_denoising = False  # Debian builds Blender without OpenImageDenoise
scene.render.resolution_x = size
scene.render.resolution_y = int(size * 0.75)
scene.view_settings.view_transform = "Standard"
if not pair:
    scene.render.filepath = out
    bpy.ops.render.render(write_still=True)
else:
    normal_links = [(m.node_tree, link.from_socket, link.to_socket) for m in bpy.data.materials if m.node_tree
                    for link in m.node_tree.links if link.from_node.type == "NORMAL_MAP"]
    halves = []
    for with_map in (False, True):
        for tree, from_socket, to_socket in normal_links:
            if with_map:
                tree.links.new(from_socket, to_socket)
            else:
                tree.links.remove(next(l for l in tree.links if l.from_socket == from_socket and l.to_socket == to_socket))
        scene.render.filepath = out + (".with.png" if with_map else ".without.png")
        bpy.ops.render.render(write_still=True)
        image = bpy.data.images.load(scene.render.filepath)
        halves.append(numpy.array(image.pixels[:]).reshape(image.size[1], image.size[0], 4))
        os.remove(scene.render.filepath)
    both = numpy.concatenate(halves, axis=1)
    picture = bpy.data.images.new("pair", both.shape[1], both.shape[0], alpha=True)
    picture.pixels = both.ravel()
    picture.filepath_raw = out
    picture.file_format = "PNG"
    picture.save()
print(f"rendered {glb} -> {out}")
