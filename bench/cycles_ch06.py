# The chapter-6 scene (scenes/ch06/diffuse.rib) built in Blender for Cycles;
# run by bench/vs-cycles.sh inside Blender:
#
#   blender -b --factory-startup --python bench/cycles_ch06.py -- OUT_PREFIX SPP REF_SPP THREADS RUNS
#
# Writes OUT_PREFIX-ref.exr (REF_SPP samples, seed 1) and OUT_PREFIX.exr (SPP
# samples, seed 0, rendered RUNS times), and prints one "render seconds" line
# per render: the time of the render call (scene sync, BVH, sampling, writing
# the image), without Blender's start-up or the building of the scene below.
#
# How the RIB scene maps onto Blender:
# - RenderMan's space is left-handed (x right, y up, z into the screen);
#   Blender's is right-handed with z up. RIB (x, y, z) becomes (x, z, y), and
#   the camera at the origin looks along +y.
# - "fov" 15 spans the shorter image side (700 pixels): a vertical fit.
# - The sphere of radius 0.8 at RIB (0 0 8) is a smooth-shaded UV sphere
#   (Cycles has no analytic sphere), with a white Lambertian BSDF.
# - PxrDiskLight is a one-sided disk of diameter 1 whose radiance is its
#   intensity (150). In Blender 3.4 a disk area light of size 1 and power P
#   watts has the radiance P / pi, so P = 150 pi. The bench does not take
#   this on trust: it compares the means of the two references.
# - Direct lighting only (no bounces), no background, box pixel filter of one
#   pixel, no adaptive sampling, no denoising, linear float output.
import math
import sys
import time

import bpy
from mathutils import Vector

args = sys.argv[sys.argv.index("--") + 1:]
prefix, spp, ref_spp, threads, runs = args[0], int(args[1]), int(args[2]), int(args[3]), int(args[4])

bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene
scene.render.engine = 'CYCLES'
cycles = scene.cycles
cycles.device = 'CPU'
cycles.use_adaptive_sampling = False
cycles.use_denoising = False
cycles.max_bounces = 0
cycles.pixel_filter_type = 'BOX'
cycles.filter_width = 1.0
scene.render.threads_mode = 'FIXED'
scene.render.threads = threads
scene.render.resolution_x, scene.render.resolution_y = 800, 700
scene.render.resolution_percentage = 100
scene.view_settings.view_transform = 'Standard'
scene.render.image_settings.file_format = 'OPEN_EXR'
scene.render.image_settings.color_depth = '32'

world = bpy.data.worlds.new("black")
world.use_nodes = True
world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
scene.world = world

camera = bpy.data.cameras.new("camera")
camera.sensor_fit = 'VERTICAL'
camera.angle_y = math.radians(15.0)
camera_object = bpy.data.objects.new("camera", camera)
camera_object.rotation_euler = (math.pi / 2, 0.0, 0.0)  # from looking down -z to looking along +y
scene.collection.objects.link(camera_object)
scene.camera = camera_object

bpy.ops.mesh.primitive_uv_sphere_add(segments=512, ring_count=256, radius=0.8, location=(0.0, 8.0, 0.0))
bpy.ops.object.shade_smooth()
material = bpy.data.materials.new("white")
material.use_nodes = True
nodes = material.node_tree.nodes
nodes.remove(nodes["Principled BSDF"])
diffuse = nodes.new("ShaderNodeBsdfDiffuse")
diffuse.inputs["Color"].default_value = (1.0, 1.0, 1.0, 1.0)
material.node_tree.links.new(diffuse.outputs["BSDF"], nodes["Material Output"].inputs["Surface"])
bpy.context.object.data.materials.append(material)

light = bpy.data.lights.new("keyLight", 'AREA')
light.shape = 'DISK'
light.size = 1.0
light.energy = 150.0 * math.pi
light_object = bpy.data.objects.new("keyLight", light)
light_object.location = (-2.0, 0.0, 2.0)  # RIB (-2 2 0)
# Blender's area lights emit along their local -z: aim it at the sphere.
light_object.rotation_euler = (Vector((0.0, 8.0, 0.0)) - light_object.location).to_track_quat('-Z', 'Y').to_euler()
light_object.visible_camera = False
scene.collection.objects.link(light_object)


def render(samples, seed, path):
    cycles.samples = samples
    cycles.seed = seed
    scene.render.filepath = path
    start = time.perf_counter()
    bpy.ops.render.render(write_still=True)
    return time.perf_counter() - start


render(ref_spp, 1, prefix + "-ref.exr")
for _ in range(runs):
    print("render seconds %.4f" % render(spp, 0, prefix + ".exr"), flush=True)
