"""The path-traced reference of scripts/cycles_reference.sh, run by Blender:

  blender -b --factory-startup -P scripts/cycles_reference.py -- \\
      SCENE.gltf SNOW.glb OUT.npy WIDTH HEIGHT SAMPLES

Imports the scene's meshes and the snow snow_run exported, places the scene's
camera (extras.snow.camera: position, target, vertical field of view) and sun
(extras.snow.sun) and lights the world with the sky colour
(extras.snow.environment.sky), then renders with Cycles on the CPU, no
denoiser. OUT.npy holds the linear radiance, RGBA, top row first, in our
units (a sun of intensity I gives flat white snow facing it a radiance of I,
as common.glsl's shade() has it); the sky is left transparent for
scripts/cycles_compare.py to tone and put behind, as our renderer does."""
import numpy

numpy.bool = bool  # Debian's numpy 1.24 dropped it; Blender 3.4's glTF importer uses it
import json
import math
import os
import sys

import bpy
from mathutils import Vector

SNOW_ALBEDO = 0.9  # common.glsl, times RenderSettings::snow_color [WAR]
SNOW_COLOR = (0.94, 0.96, 1.0)
SNOW_ROUGHNESS = 0.6  # common.glsl: GGX alpha = 0.6^2, as Principled's roughness
SNOW_SPECULAR = 0.02 / 0.08  # F0 of ice (n = 1.31) in Principled's specular units


def z_up(v):
    """A glTF point or direction (y up) in Blender's frame (z up)."""
    return Vector((v[0], -v[2], v[1]))


def scene_node_names(gltf):
    """The names of the scene's nodes and their children: Blender's importer
    also brings in the nodes no scene holds (scripts/cycles_scene.py drops
    the lamps and the walker from the scene only)."""
    names, todo = set(), list(gltf["scenes"][gltf.get("scene", 0)]["nodes"])
    while todo:
        node = gltf["nodes"][todo.pop()]
        names.add(node.get("name"))
        todo += node.get("children", [])
    return names


def snow_material():
    m = bpy.data.materials.new("snow")
    m.use_nodes = True
    bsdf = m.node_tree.nodes["Principled BSDF"]
    bsdf.inputs["Base Color"].default_value = (*(SNOW_ALBEDO * c for c in SNOW_COLOR), 1.0)
    bsdf.inputs["Roughness"].default_value = SNOW_ROUGHNESS
    bsdf.inputs["Specular"].default_value = SNOW_SPECULAR
    return m


def add_camera(scene, c):
    cam = bpy.data.objects.new("camera", bpy.data.cameras.new("camera"))
    position, target = z_up(c["position"]), z_up(c["target"])
    cam.location = position
    cam.rotation_euler = (target - position).to_track_quat("-Z", "Y").to_euler()
    cam.data.sensor_fit = "VERTICAL"
    cam.data.angle_y = math.radians(c["fov_y_deg"])
    cam.data.clip_start, cam.data.clip_end = c["near_plane"], c["far_plane"]
    scene.collection.objects.link(cam)
    scene.camera = cam


def add_sun(scene, s):
    light = bpy.data.lights.new("sun", "SUN")
    light.color = s["color"]
    light.energy = math.pi * s["intensity"]  # Cycles: radiance = albedo * energy / pi
    light.angle = math.radians(0.53)  # the sun's disc
    sun = bpy.data.objects.new("sun", light)
    sun.rotation_euler = z_up(s["direction"]).normalized().to_track_quat("Z", "Y").to_euler()
    scene.collection.objects.link(sun)


def main(scene_path, snow_path, out_path, width, height, samples):
    with open(scene_path) as f:
        gltf = json.load(f)
    extras = gltf["scenes"][gltf.get("scene", 0)]["extras"]["snow"]
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.import_scene.gltf(filepath=scene_path)
    keep = scene_node_names(gltf)
    for o in list(bpy.data.objects):
        if o.name not in keep:
            bpy.data.objects.remove(o)
    bpy.ops.import_scene.gltf(filepath=snow_path)
    material = snow_material()
    for o in bpy.context.selected_objects:  # what the snow's import made
        if o.type == "MESH":
            o.data.materials.clear()
            o.data.materials.append(material)

    scene = bpy.context.scene
    add_camera(scene, extras["camera"])
    add_sun(scene, extras["sun"])
    scene.world = bpy.data.worlds.new("sky")
    scene.world.use_nodes = True
    scene.world.node_tree.nodes["Background"].inputs["Color"].default_value = (
        *extras["environment"]["sky"], 1.0)

    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = samples
    scene.cycles.use_denoising = False  # Debian's Blender has no OpenImageDenoise
    scene.render.film_transparent = True
    scene.render.resolution_x, scene.render.resolution_y = width, height
    scene.render.resolution_percentage = 100
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.image_settings.color_depth = "32"
    scene.render.filepath = out_path + ".exr"
    bpy.ops.render.render(write_still=True)

    image = bpy.data.images.load(scene.render.filepath)
    rgba = numpy.array(image.pixels[:], dtype=numpy.float32).reshape(height, width, 4)
    numpy.save(out_path, rgba[::-1])
    os.remove(scene.render.filepath)


if __name__ == "__main__":
    args = sys.argv[sys.argv.index("--") + 1:]
    main(args[0], args[1], args[2], int(args[3]), int(args[4]), int(args[5]))
