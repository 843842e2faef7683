# Builds bench/cycles/cornell_cycles.pov's Cornell box in Blender and renders
# it with Cycles, once per sample count given, to float EXR.
#
#   blender -b --factory-startup --python bench/cycles/cornell_cycles.py -- \
#       --out /tmp/cycles/cornell --size 256 --samples 1,4,16 \
#       [--threads 2] [--seed 0] [--bounces 15] [--half 0] [--specular 0]
#
# writes /tmp/cycles/cornell_<samples>.exr and appends one line per render to
# /tmp/cycles/cornell_times.txt: "samples <n> seconds <wall seconds of the
# render call, scene sync and BVH build included> cpu <its CPU seconds, all
# threads>". Blender's own start-up is
# not in those seconds: time the whole process to get it. --half 1 writes
# half floats (the checked-in reference: 3 significant digits are plenty for
# a 2 % test and halve the file). --specular 1 builds
# cornell_cycles_specular.pov instead (a mirror and a glass box).
#
# Coordinates: lancer/POV is left-handed with y up, Blender right-handed with
# z up. (x, y, z)_pov -> (x, z, y)_blender swaps two axes, which both turns y
# up into z up and flips the handedness, so the image is not mirrored.
#
# Settings are those that make Cycles compute what lancer's path does:
# - Standard view transform, no look, exposure 0, gamma 1: the EXR holds the
#   scene's linear radiance, as lancer's;
# - a 1-pixel box filter: lancer spreads a pixel's samples uniformly over the
#   pixel and averages them with equal weight;
# - max_bounces 15: lancer's max_depth counts the camera hit's direct light
#   as bounce 1, Cycles as bounce 0, so lancer's 16 is Cycles' 15;
# - no clamping, no light threshold, no denoising, no adaptive sampling, no
#   glossy filter, caustics on: each would bias or change the estimate, and
#   lancer's path does none of them;
# - a black world: lancer's background defaults to black.
import math
import os
import sys
import time

import bpy

# Keep in sync with cornell_cycles.pov.
WHITE = (0.73, 0.73, 0.73)
RED = (0.63, 0.065, 0.05)
GREEN = (0.14, 0.45, 0.091)
LAMP_COLOR = (1.0, 0.85, 0.6)
LAMP_STRENGTH = 40.0
# Quads as four corners in POV coordinates, in order around the edge.
QUADS = [
    ("floor", WHITE, [(-1, 0, -1), (1, 0, -1), (1, 0, 1), (-1, 0, 1)]),
    # The ceiling, around the lamp's hole.
    ("ceiling_front", WHITE, [(-1, 2, -1), (1, 2, -1), (1, 2, -0.25), (-1, 2, -0.25)]),
    ("ceiling_back", WHITE, [(-1, 2, 0.25), (1, 2, 0.25), (1, 2, 1), (-1, 2, 1)]),
    ("ceiling_left", WHITE, [(-1, 2, -0.25), (-0.25, 2, -0.25), (-0.25, 2, 0.25), (-1, 2, 0.25)]),
    ("ceiling_right", WHITE, [(0.25, 2, -0.25), (1, 2, -0.25), (1, 2, 0.25), (0.25, 2, 0.25)]),
    ("back", WHITE, [(-1, 0, 1), (1, 0, 1), (1, 2, 1), (-1, 2, 1)]),
    ("left", RED, [(-1, 0, -1), (-1, 0, 1), (-1, 2, 1), (-1, 2, -1)]),
    ("right", GREEN, [(1, 0, -1), (1, 0, 1), (1, 2, 1), (1, 2, -1)]),
]
LAMP = [(-0.25, 2, -0.25), (0.25, 2, -0.25), (0.25, 2, 0.25), (-0.25, 2, 0.25)]
# Boxes: lower corner, upper corner, rotation about y in degrees, translation.
BOXES = [
    ("tall", (-0.3, 0, -0.3), (0.3, 1.2, 0.3), 20.0, (-0.35, 0, 0.35)),
    ("short", (-0.3, 0, -0.3), (0.3, 0.6, 0.3), -18.0, (0.35, 0, -0.3)),
]
# cornell_cycles_specular.pov lifts the glass box 1 mm off the floor.
SPECULAR_LIFT = 0.001
CAMERA_LOCATION = (0, 1, -3.4)  # looking along +z, horizontal field of view:
CAMERA_ANGLE = 40.0
MAX_BOUNCES = 15  # lancer's max_depth 16


def to_blender(p):
    return (p[0], p[2], p[1])


def pov_rotate_y(p, degrees):
    # POV's `rotate y*a` as lancer's parser applies it (glm::rotate about +y
    # on POV's own coordinates).
    a = math.radians(degrees)
    c, s = math.cos(a), math.sin(a)
    return (c * p[0] + s * p[2], p[1], -s * p[0] + c * p[2])


def node_material(name, node_type, output, inputs):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    nodes = m.node_tree.nodes
    nodes.clear()
    shader = nodes.new(node_type)
    for key, value in inputs.items():
        shader.inputs[key].default_value = value
    out = nodes.new("ShaderNodeOutputMaterial")
    m.node_tree.links.new(shader.outputs[output], out.inputs["Surface"])
    return m


def diffuse_material(name, color):
    # Roughness 0: Lambertian, not Oren-Nayar.
    return node_material(name, "ShaderNodeBsdfDiffuse", "BSDF", {"Color": (*color, 1.0), "Roughness": 0.0})


def emission_material(name, color, strength):
    m = node_material(name, "ShaderNodeEmission", "Emission", {"Color": (*color, 1.0), "Strength": strength})
    # Light sampling of the emitter (next-event estimation), as lancer's
    # path does for every emissive object; the property was renamed in 3.5.
    if hasattr(m.cycles, "emission_sampling"):
        m.cycles.emission_sampling = "BOTH"
    else:
        m.cycles.sample_as_light = True
    return m


def add_mesh(scene, name, vertices_pov, faces, material):
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata([to_blender(v) for v in vertices_pov], [], faces)
    mesh.update()
    mesh.materials.append(material)
    obj = bpy.data.objects.new(name, mesh)
    scene.collection.objects.link(obj)
    return obj


def build(scene, specular):
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj, do_unlink=True)
    materials = {}
    for name, color, corners in QUADS:
        m = materials.setdefault(color, diffuse_material("mat_%d" % len(materials), color))
        add_mesh(scene, name, corners, [(0, 1, 2, 3)], m)
    add_mesh(scene, "lamp", LAMP, [(0, 1, 2, 3)], emission_material("lamp", LAMP_COLOR, LAMP_STRENGTH))
    box_materials = {"tall": materials[WHITE], "short": materials[WHITE]}
    if specular:
        box_materials["tall"] = node_material(
            "mirror", "ShaderNodeBsdfGlossy", "BSDF", {"Color": (1, 1, 1, 1), "Roughness": 0.0})
        box_materials["short"] = node_material(
            "glass", "ShaderNodeBsdfGlass", "BSDF", {"Color": (1, 1, 1, 1), "Roughness": 0.0, "IOR": 1.5})
        for m in box_materials.values():
            m.node_tree.nodes[0].distribution = "SHARP"
    for name, lo, hi, degrees, offset in BOXES:
        if specular and name == "short":
            offset = (offset[0], offset[1] + SPECULAR_LIFT, offset[2])
        corners = []
        for i in range(8):
            p = (hi[0] if i & 1 else lo[0], hi[1] if i & 2 else lo[1], hi[2] if i & 4 else lo[2])
            r = pov_rotate_y(p, degrees)
            corners.append((r[0] + offset[0], r[1] + offset[1], r[2] + offset[2]))
        # Faces by corner index bits (x = 1, y = 2, z = 4); winding does not
        # matter: the walls are two-sided in both renderers.
        faces = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
        add_mesh(scene, name, corners, faces, box_materials[name])

    camera_data = bpy.data.cameras.new("camera")
    camera_data.sensor_fit = "HORIZONTAL"
    camera_data.angle_x = math.radians(CAMERA_ANGLE)
    camera_data.clip_start = 1e-3
    camera_data.clip_end = 1e3
    camera = bpy.data.objects.new("camera", camera_data)
    camera.location = to_blender(CAMERA_LOCATION)
    # A Blender camera looks along its -z with +y up; turning it 90 degrees
    # about x makes that +y (POV's +z) with +z (POV's +y) up.
    camera.rotation_euler = (math.radians(90.0), 0.0, 0.0)
    scene.collection.objects.link(camera)
    scene.camera = camera

    world = bpy.data.worlds.new("black")
    world.use_nodes = True
    background = world.node_tree.nodes["Background"]
    background.inputs["Color"].default_value = (0.0, 0.0, 0.0, 1.0)
    background.inputs["Strength"].default_value = 0.0
    scene.world = world


def configure(scene, size, threads, seed, bounces, half):
    scene.render.engine = "CYCLES"
    c = scene.cycles
    c.device = "CPU"
    c.use_adaptive_sampling = False
    c.use_denoising = False
    c.use_preview_denoising = False
    c.max_bounces = bounces
    c.diffuse_bounces = bounces
    c.glossy_bounces = bounces
    c.transmission_bounces = bounces
    c.transparent_max_bounces = bounces
    c.volume_bounces = 0
    c.sample_clamp_direct = 0.0
    c.sample_clamp_indirect = 0.0
    c.light_sampling_threshold = 0.0
    c.blur_glossy = 0.0
    c.caustics_reflective = True
    c.caustics_refractive = True
    c.seed = seed
    c.use_animated_seed = False
    c.pixel_filter_type = "BOX"
    c.filter_width = 1.0
    c.time_limit = 0.0
    if hasattr(c, "use_light_tree"):  # 3.5 and later
        c.use_light_tree = False
    scene.view_layers[0].cycles.denoising_store_passes = False
    r = scene.render
    r.resolution_x = size
    r.resolution_y = size
    r.resolution_percentage = 100
    r.film_transparent = False
    r.threads_mode = "FIXED"
    r.threads = threads
    r.use_persistent_data = False
    image = r.image_settings
    image.file_format = "OPEN_EXR"
    image.color_mode = "RGB"
    image.color_depth = "16" if half else "32"
    image.exr_codec = "ZIP"
    v = scene.view_settings
    v.view_transform = "Standard"
    v.look = "None"
    v.exposure = 0.0
    v.gamma = 1.0
    scene.display_settings.display_device = "sRGB"
    scene.sequencer_colorspace_settings.name = "sRGB"


def parse(argv):
    args = argv[argv.index("--") + 1:] if "--" in argv else []
    options = {"--out": None, "--size": "256", "--samples": "16", "--threads": "2", "--seed": "0",
               "--bounces": str(MAX_BOUNCES), "--half": "0", "--specular": "0"}
    for key, value in zip(args[::2], args[1::2]):
        if key not in options:
            raise SystemExit("cornell_cycles.py: unknown option " + key)
        options[key] = value
    if not options["--out"]:
        raise SystemExit("cornell_cycles.py: --out PREFIX is required")
    return options


def main():
    options = parse(sys.argv)
    prefix = options["--out"]
    os.makedirs(os.path.dirname(os.path.abspath(prefix)), exist_ok=True)
    scene = bpy.context.scene
    build(scene, options["--specular"] == "1")
    configure(scene, int(options["--size"]), int(options["--threads"]), int(options["--seed"]),
              int(options["--bounces"]), options["--half"] == "1")
    with open(prefix + "_times.txt", "a") as times:
        for samples in [int(s) for s in options["--samples"].split(",")]:
            scene.cycles.samples = samples
            scene.render.filepath = "%s_%d.exr" % (prefix, samples)
            start, start_cpu = time.perf_counter(), time.process_time()
            bpy.ops.render.render(write_still=True)
            seconds = time.perf_counter() - start
            # CPU time of every thread: on a shared machine, wall time
            # measures the other processes too.
            cpu = time.process_time() - start_cpu
            times.write("samples %d seconds %.6f cpu %.6f\n" % (samples, seconds, cpu))
            times.flush()
            print("cornell_cycles: %d samples in %.3f s" % (samples, seconds), flush=True)


main()
