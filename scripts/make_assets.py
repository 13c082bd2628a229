#!/usr/bin/env python3
"""Writes the project's glTF scenes to assets/scenes/ (docs/scenes.md).

    python3 scripts/make_assets.py [--check]

Standard library only. Output is deterministic: running it again rewrites
the same bytes (--check exits 1 if a file would change). Scenes:

  village.gltf          the test scene of [WF §5]: ground, a house with a pitched
                        roof (two sloped mesh colliders with sloped surfaces),
                        a porch roof under its lee eave, a flat-roofed garage,
                        a fence, a three-sphere snowman, three coloured point
                        lights (white above the house, blue nearer the camera,
                        yellow on the right), steady wind along +x,
                        exponential fog, an occlusion camera, a snow cover
                        for the snowman and the fence, and a walker doing
                        laps round the snowman.
  village_effects.gltf  the village plus the spectral far-field layer, gusts,
                        layered fog with a puff, a wind field (with wind
                        transport of snow) that the buildings shape, and a
                        low winter sun under a clear sky (lamps at half).
  minimal.gltf          ground and an emitter only: no wind, fog, occlusion or
                        spectral layer, default bounds.
  park.gltf             no declared surfaces at all: hilly terrain (a mesh), a
                        statue of spheres and boxes on a plinth, three benches,
                        five cone trees, a snow cover over everything, and
                        an afternoon sun (the trees' shadows on the snow).
  valley.gltf           a 4 x 4 km terrain from the 16-bit height map
  + valley_height.png   valley_height.png (docs/world.md): hills round a
                        valley with a road along its floor, a village of the
                        village's houses and garages on a levelled terrace by
                        the road, a forest of cone trees on the slopes; snow
                        falls on a 120 x 120 m region round the village.
"""

import base64
import json
import math
import struct
import sys
import zlib
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
OUT_DIR = ROOT / "assets" / "scenes"

FLOAT = 5126
UNSIGNED_SHORT = 5123
UNSIGNED_INT = 5125
ARRAY_BUFFER = 34962
ELEMENT_ARRAY_BUFFER = 34963


def f32(x):
    """x rounded to float32, as the buffer stores it."""
    return struct.unpack("<f", struct.pack("<f", x))[0]


def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def normalized(v):
    n = math.sqrt(sum(c * c for c in v))
    return [c / n for c in v]


def hexahedron(c):
    """Flat-shaded six-sided solid from 8 corners indexed by bits (x, y, z):
    corner k has x-side k & 1, y-side (k >> 1) & 1, z-side (k >> 2) & 1.
    Faces are wound counter-clockwise seen from outside."""
    faces = [
        (0, 4, 6, 2),  # -x
        (1, 3, 7, 5),  # +x
        (0, 1, 5, 4),  # -y
        (2, 6, 7, 3),  # +y
        (0, 2, 3, 1),  # -z
        (4, 5, 7, 6),  # +z
    ]
    positions, normals, indices = [], [], []
    for quad in faces:
        p = [c[k] for k in quad]
        n = normalized(cross(sub(p[1], p[0]), sub(p[2], p[0])))
        base = len(positions)
        positions += p
        normals += [n] * 4
        indices += [base, base + 1, base + 2, base, base + 2, base + 3]
    return positions, normals, indices


def unit_box():
    """The cube [-0.5, 0.5]^3; nodes scale and place it."""
    return hexahedron([[(k & 1) - 0.5, ((k >> 1) & 1) - 0.5, ((k >> 2) & 1) - 0.5]
                       for k in range(8)])


def roof_slab(x_low, x_high, z0, z1, top_at, thickness):
    """A roof side: top plane y = top_at(x), vertical thickness, spanning
    x_low..x_high and z0..z1."""
    corners = []
    for k in range(8):
        x = x_high if k & 1 else x_low
        z = z1 if (k >> 2) & 1 else z0
        y = top_at(x) - (0.0 if (k >> 1) & 1 else thickness)
        corners.append([x, y, z])
    return hexahedron(corners)


def unit_sphere(rings=8, segments=12):
    """UV sphere of radius 1, smooth normals; its bounds are exactly [-1, 1]^3
    (segments divisible by 4), so a sphere collider recovers the radius."""
    positions, indices = [], []
    for r in range(rings + 1):
        theta = math.pi * r / rings
        for s in range(segments + 1):
            phi = 2.0 * math.pi * s / segments
            positions.append([round(math.sin(theta) * math.cos(phi), 9),
                              round(math.cos(theta), 9),
                              round(-math.sin(theta) * math.sin(phi), 9)])
    row = segments + 1
    for r in range(rings):
        for s in range(segments):
            a, b = r * row + s, (r + 1) * row + s
            if r != 0:
                indices += [a, b, a + 1]
            if r != rings - 1:
                indices += [a + 1, b, b + 1]
    return positions, [list(p) for p in positions], indices


class Gltf:
    """Accumulates one glTF document with a single embedded buffer."""

    def __init__(self):
        self.bin = bytearray()
        self.views, self.accessors, self.materials, self.meshes, self.nodes = [], [], [], [], []

    def _view(self, data, target):
        while len(self.bin) % 4:
            self.bin.append(0)
        self.views.append({"buffer": 0, "byteOffset": len(self.bin), "byteLength": len(data),
                           "target": target})
        self.bin += data
        return len(self.views) - 1

    def _vec3(self, values):
        flat = [c for v in values for c in v]
        view = self._view(struct.pack("<%df" % len(flat), *flat), ARRAY_BUFFER)
        rounded = [[f32(c) for c in v] for v in values]
        self.accessors.append({
            "bufferView": view, "componentType": FLOAT, "count": len(values), "type": "VEC3",
            "min": [min(v[i] for v in rounded) for i in range(3)],
            "max": [max(v[i] for v in rounded) for i in range(3)]})
        return len(self.accessors) - 1

    def _indices(self, values):
        wide = max(values) > 0xFFFF
        data = struct.pack("<%d%s" % (len(values), "I" if wide else "H"), *values)
        view = self._view(data, ELEMENT_ARRAY_BUFFER)
        self.accessors.append({"bufferView": view,
                               "componentType": UNSIGNED_INT if wide else UNSIGNED_SHORT,
                               "count": len(values), "type": "SCALAR"})
        return len(self.accessors) - 1

    def geometry(self, shape):
        """Accessors (POSITION, NORMAL, indices) of a (positions, normals, indices) shape."""
        positions, normals, indices = shape
        return self._vec3(positions), self._vec3(normals), self._indices(indices)

    def material(self, name, rgb):
        self.materials.append({"name": name, "pbrMetallicRoughness": {
            "baseColorFactor": list(rgb) + [1.0], "metallicFactor": 0.0, "roughnessFactor": 0.9}})
        return len(self.materials) - 1

    def mesh(self, name, geometry, material):
        pos, nrm, idx = geometry
        self.meshes.append({"name": name, "primitives": [{
            "attributes": {"POSITION": pos, "NORMAL": nrm}, "indices": idx,
            "material": material}]})
        return len(self.meshes) - 1

    def node(self, name, mesh=None, translation=None, rotation=None, scale=None,
             children=None, snow=None, light=None):
        n = {"name": name}
        for key, value in (("mesh", mesh), ("translation", translation),
                           ("rotation", rotation), ("scale", scale), ("children", children)):
            if value is not None:
                n[key] = value
        if snow is not None:
            n["extras"] = {"snow": snow}
        if light is not None:
            n["extensions"] = {"KHR_lights_punctual": {"light": light}}
        self.nodes.append(n)
        return len(self.nodes) - 1

    def document(self, scene_name, roots, scene_snow, lights=None):
        doc = {"asset": {"version": "2.0", "generator": "snow scripts/make_assets.py"}}
        if lights:
            doc["extensionsUsed"] = ["KHR_lights_punctual"]
            doc["extensions"] = {"KHR_lights_punctual": {"lights": lights}}
        doc.update({
            "scene": 0,
            "scenes": [{"name": scene_name, "nodes": roots, "extras": {"snow": scene_snow}}],
            "nodes": self.nodes,
            "meshes": self.meshes,
            "materials": self.materials,
            "accessors": self.accessors,
            "bufferViews": self.views,
            "buffers": [{"byteLength": len(self.bin),
                         "uri": "data:application/octet-stream;base64," +
                                base64.b64encode(bytes(self.bin)).decode("ascii")}],
        })
        return doc


def point_light(name, rgb, intensity):
    return {"name": name, "type": "point", "color": list(rgb), "intensity": intensity}


# --- the scenes ---------------------------------------------------------------

DT = 1.0 / 60.0
GROUND = {"surface": {"cell": 0.1, "edge_limit": 0.1, "spills": False}}
# A storm's heaviest hour, 15 kg/m²/h (about 15 cm/h of fresh snow), of
# unrimed dendrite aggregates 1-20 mm across (docs/references.md [GM58], [LH74]).
EMITTER = {"rate": 3000.0, "snowfall_kg_m2_h": 15.0, "crystal": "dendrite_aggregate",
           "size_mean": 0.004, "size_min": 0.001, "size_max": 0.02}
CAMERA = {"position": [1.0, 6.0, 17.0], "target": [0.0, 1.5, -1.0], "fov_y_deg": 50.0,
          "near_plane": 0.05, "far_plane": 200.0}
ENVIRONMENT = {"ambient": [0.18, 0.2, 0.24], "sky": [0.55, 0.62, 0.7]}

# House (node frame): walls x -2.5..2.5, z -2..2, 3 m high; the ridge runs
# along z at x = 0, 4.6 m high; eaves overhang 0.4 m; roof top slope 0.58.
RIDGE_Y, ROOF_SLOPE, EAVE, ROOF_T = 4.6, 0.58, 2.9, 0.15


def house_roofs(g):
    """The house's two roof slabs (west, east), as geometries of g."""
    west = g.geometry(roof_slab(-EAVE, 0.0, -2.4, 2.4, lambda x: RIDGE_Y + ROOF_SLOPE * x, ROOF_T))
    east = g.geometry(roof_slab(0.0, EAVE, -2.4, 2.4, lambda x: RIDGE_Y - ROOF_SLOPE * x, ROOF_T))
    return west, east


def building_materials(g):
    """Walls, roofs and garages: brick, slate, plaster."""
    return (g.material("brick", (0.55, 0.25, 0.2)), g.material("slate", (0.3, 0.3, 0.35)),
            g.material("plaster", (0.62, 0.6, 0.55)))


def village(effects):
    g = Gltf()
    box = g.geometry(unit_box())
    sphere = g.geometry(unit_sphere())
    left, right = house_roofs(g)
    m_ground = g.material("frozen ground", (0.42, 0.4, 0.36))
    m_wall, m_roof, m_garage = building_materials(g)
    m_wood = g.material("wood", (0.45, 0.32, 0.2))
    m_snowman = g.material("snowman", (0.95, 0.95, 0.97))

    # Smooth cold slate sheds: little friction and adhesion, so a line down a
    # roof side holding more than about 3 kg/m² (3 cm of fresh snow) slides off
    # its eave as one slab (the west side onto the ground, the east onto the porch).
    roof_cell = {"cell": 0.1, "edge_limit": 0.005, "slide_friction": 0.2, "slide_adhesion": 8.0}
    ground = g.node("ground", g.mesh("ground", box, m_ground), translation=[0.0, -0.1, 0.0],
                    scale=[20.0, 0.2, 20.0], snow=GROUND)
    walls = g.node("house walls", g.mesh("walls", box, m_wall), translation=[0.0, 1.5, 0.0],
                   scale=[5.0, 3.0, 4.0], snow={"collider": "box"})
    roof_l = g.node("roof west", g.mesh("roof west", left, m_roof),
                    snow={"collider": "mesh", "surface": dict(roof_cell, slope_x=ROOF_SLOPE)})
    roof_r = g.node("roof east", g.mesh("roof east", right, m_roof),
                    snow={"collider": "mesh", "surface": dict(roof_cell, slope_x=-ROOF_SLOPE)})
    house = g.node("house", translation=[-3.0, 0.0, -1.0], children=[walls, roof_l, roof_r])
    # Under the east (lee) eave, which ends at x = -0.1: receives the roof's spill.
    porch = g.node("porch roof", g.mesh("porch roof", box, m_wood),
                   translation=[0.575, 2.075, -1.0], scale=[2.05, 0.15, 2.4],
                   snow={"collider": "box", "surface": {"cell": 0.1, "edge_limit": 0.01}})
    posts = [g.node("porch post %d" % i, g.mesh("porch post", box, m_wood),
                    translation=[1.5, 1.0, z], scale=[0.1, 2.0, 0.1])
             for i, z in enumerate((-2.1, 0.1))]
    garage = g.node("garage", g.mesh("garage", box, m_garage), translation=[5.0, 1.25, -1.5],
                    scale=[4.0, 2.5, 3.0],
                    snow={"collider": "box", "surface": {"cell": 0.1, "edge_limit": 0.01}})
    # Rotated a quarter turn about y: 10 m long along z, upwind of everything.
    fence = g.node("fence", g.mesh("fence", box, m_wood), translation=[-8.0, 0.5, -1.0],
                   rotation=[0.0, math.sqrt(0.5), 0.0, math.sqrt(0.5)], scale=[10.0, 1.0, 0.1],
                   snow={"collider": "box"})
    balls = [g.node("snowman %s" % part, g.mesh("snowman " + part, sphere, m_snowman),
                    translation=[0.0, y, 0.0], scale=[r, r, r], snow={"collider": "sphere"})
             for part, y, r in (("base", 0.6, 0.6), ("body", 1.5, 0.42), ("head", 2.12, 0.28))]
    snowman = g.node("snowman", translation=[2.0, 0.0, 4.0], children=balls)
    # A walker (an upright capsule) doing laps round the snowman: its trail
    # is carved through the ground's snow and filled again by the snowfall.
    lap = [[-1.0, 0.9, 2.5], [5.0, 0.9, 2.5], [5.0, 0.9, 6.5], [-1.0, 0.9, 6.5]]
    walker = g.node("walker", g.mesh("walker", box, m_wood), translation=lap[0],
                    scale=[0.4, 1.8, 0.4],
                    snow={"collider": "capsule", "on_ground": True,
                          "motion": {"waypoints": lap, "speed": 1.2, "loop": True}})
    # By day, under the effects scene's sun, the lamps give half their light.
    dim = 0.5 if effects else 1.0
    lights = [point_light("white", (1.0, 1.0, 1.0), 1.0 * dim),
              point_light("blue", (0.35, 0.5, 1.0), 0.6 * dim),
              point_light("yellow", (1.0, 0.85, 0.35), 0.7 * dim)]
    lamps = [g.node("white light", translation=[-3.0, 9.0, -1.0], light=0),
             g.node("blue light", translation=[-1.0, 5.0, 7.0], light=1),
             g.node("yellow light", translation=[9.0, 5.0, 1.0], light=2)]

    wind = {"base": [2.0, 0.0, 0.0], "walk": 0.2, "max_deviation": 0.8}
    fog = {"mode": "exponential", "color": [0.75, 0.78, 0.82], "density": 0.02}
    if effects:
        wind.update({"gust_strength": 3.0, "gust_rate": 0.1, "gust_duration": 1.5})
        # The air flows round the buildings (docs/wind_field.md): 31 cm cells
        # across, 78 cm up, a solver step every 4 ticks; gusts (5 m/s) lift
        # the snow where the air speeds up, over roof edges and round corners.
        wind["field"] = {"cells": [64, 16, 64], "update_every": 4,
                         "transport": {"roughness": 0.001}}
        fog = {"mode": "layered", "color": [0.78, 0.8, 0.84], "layer_bottom": 0.0,
               "layer_top": 3.0, "layer_density": 0.12,
               "puffs": [{"center": [4.0, 1.0, 3.0], "sigma": 1.5, "density": 0.3}]}
    snow = {
        "simulation": {"dt": DT, "seed": 2, "max_flakes": 50000, "integrator": "euler",
                       "threads": 1, "bounds": {"min": [-10.0, -0.5, -10.0],
                                                "max": [10.0, 12.0, 10.0]}},
        "emitter": EMITTER,
        "wind": wind,
        "fog": fog,
        "occlusion": {"resolution": 256, "tilt": 0.25},
        # Snow on everything no rectangle was declared for: the snowman, the
        # fence, the porch posts' tops.
        "cover": {"min": [-10.0, -10.0], "max": [10.0, 10.0], "cell": 0.1},
    }
    if effects:
        snow["spectral"] = {"size_xy": 64, "size_t": 32, "speed": 1.0, "band_low": 4.0,
                            "band_high": 16.0, "opacity": 0.5, "start_distance": 25.0}
        # A low winter sun from the west, a little behind the buildings: their
        # shadows reach across the snow towards the camera. On flat ground it
        # gives 5 times the sky's light, as a clear day's sun at 30° does, and
        # the clear sky is bluer than the overcast village's.
        snow["sun"] = {"direction": [-0.7, 0.45, -0.3], "color": [1.0, 0.95, 0.86],
                       "intensity": 4.0}
    snow["camera"] = CAMERA
    snow["environment"] = dict(ENVIRONMENT, sky=[0.45, 0.58, 0.8]) if effects else ENVIRONMENT
    roots = [ground, house, porch] + posts + [garage, fence, snowman, walker] + lamps
    return g.document("village effects" if effects else "village", roots, snow, lights)


def terrain(half, n, height):
    """A hilly (n x n quads) terrain over [-half, half]^2, smooth normals."""
    def y(x, z):
        return height(x, z)
    positions, normals, indices = [], [], []
    step = 2.0 * half / n
    for j in range(n + 1):
        for i in range(n + 1):
            x, z = -half + i * step, -half + j * step
            positions.append([round(x, 6), round(y(x, z), 6), round(z, 6)])
            e = 1e-3
            dx = (y(x + e, z) - y(x - e, z)) / (2 * e)
            dz = (y(x, z + e) - y(x, z - e)) / (2 * e)
            normals.append([round(c, 6) for c in normalized([-dx, 1.0, -dz])])
    row = n + 1
    for j in range(n):
        for i in range(n):
            a, b = j * row + i, (j + 1) * row + i
            indices += [a, b, a + 1, a + 1, b, b + 1]
    return positions, normals, indices


def cone(segments=12):
    """A cone of radius 1 at y = 0 rising to its tip at y = 1, flat-shaded sides."""
    positions, normals, indices = [], [], []
    for s in range(segments):
        p0, p1 = 2.0 * math.pi * s / segments, 2.0 * math.pi * (s + 1) / segments
        a = [math.cos(p0), 0.0, -math.sin(p0)]
        b = [math.cos(p1), 0.0, -math.sin(p1)]
        tip = [0.0, 1.0, 0.0]
        n = normalized(cross(sub(b, a), sub(tip, a)))
        base = len(positions)
        positions += [[round(c, 9) for c in v] for v in (a, b, tip)]
        normals += [[round(c, 9) for c in n]] * 3
        indices += [base, base + 1, base + 2]
    return positions, normals, indices


def park_height(x, z):
    """Rolling hills, 0 at the plaza in the middle."""
    r2 = x * x + z * z
    plaza = 1.0 - math.exp(-r2 / 18.0)
    return round(plaza * (0.9 * math.sin(0.35 * x) * math.cos(0.3 * z) + 0.6 +
                          0.4 * math.sin(0.5 * z + 0.7)), 6)


def park():
    """Snow on geometry nobody declared a surface for: terrain, a statue, benches, trees."""
    g = Gltf()
    box = g.geometry(unit_box())
    sphere = g.geometry(unit_sphere(12, 16))
    tree = g.geometry(cone())
    hills = g.geometry(terrain(12.0, 48, park_height))
    m_grass = g.material("frozen grass", (0.33, 0.38, 0.28))
    m_stone = g.material("stone", (0.55, 0.55, 0.58))
    m_bronze = g.material("bronze", (0.45, 0.33, 0.2))
    m_wood = g.material("wood", (0.45, 0.32, 0.2))
    m_pine = g.material("pine", (0.12, 0.3, 0.16))
    ground = g.node("terrain", g.mesh("terrain", hills, m_grass), snow={"collider": "mesh"})
    plinth = g.node("plinth", g.mesh("plinth", box, m_stone), translation=[0.0, 0.5, 0.0],
                    scale=[1.6, 1.0, 1.6], snow={"collider": "box"})
    figure = [g.node("statue %s" % part, g.mesh("statue " + part, sphere, m_bronze),
                     translation=[0.0, y, 0.0], scale=[r, r, r], snow={"collider": "sphere"})
              for part, y, r in (("hips", 1.45, 0.45), ("chest", 2.1, 0.38), ("head", 2.65, 0.22))]
    arm = g.node("statue arm", g.mesh("statue arm", box, m_bronze), translation=[0.45, 2.2, 0.0],
                 scale=[0.9, 0.14, 0.14], snow={"collider": "box"})
    statue = g.node("statue", children=[plinth] + figure + [arm])
    benches = []
    for k, (x, z, turn) in enumerate(((-3.0, 2.5, False), (3.0, 2.5, False), (0.0, -3.2, True))):
        sx, sz = (0.5, 1.8) if turn else (1.8, 0.5)
        seat = g.node("bench %d seat" % k, g.mesh("bench seat", box, m_wood),
                      translation=[0.0, 0.45, 0.0], scale=[sx, 0.08, sz], snow={"collider": "box"})
        legs = [g.node("bench %d leg %d" % (k, i), g.mesh("bench leg", box, m_wood),
                       translation=[dx, 0.2, dz], scale=[0.08, 0.4, 0.08], snow={"collider": "box"})
                for i, (dx, dz) in enumerate(((-0.8, -0.2), (0.8, 0.2)) if not turn
                                             else ((-0.2, -0.8), (0.2, 0.8)))]
        benches.append(g.node("bench %d" % k, translation=[x, 0.0, z], children=[seat] + legs))
    trees = []
    for k, (x, z, h) in enumerate(((-7.0, -6.0, 4.0), (-5.0, 6.5, 3.2), (6.5, -5.5, 3.6),
                                   (7.5, 5.0, 4.4), (-8.5, 1.0, 3.0))):
        y0 = park_height(x, z) - 0.1
        trees.append(g.node("tree %d" % k, g.mesh("tree", tree, m_pine), translation=[x, y0, z],
                            scale=[0.35 * h, h, 0.35 * h], snow={"collider": "mesh"}))
    snow = {
        "simulation": {"dt": DT, "seed": 5, "max_flakes": 60000, "integrator": "euler",
                       "threads": 1, "bounds": {"min": [-12.0, -0.5, -12.0],
                                                "max": [12.0, 10.0, 12.0]}},
        "emitter": dict(EMITTER, rate=4000.0),
        "wind": {"base": [1.5, 0.0, 0.5], "walk": 0.2, "max_deviation": 0.6},
        "fog": {"mode": "exponential", "color": [0.75, 0.78, 0.82], "density": 0.015},
        "occlusion": {"resolution": 256, "tilt": 0.0},
        "cover": {"min": [-12.0, -12.0], "max": [12.0, 12.0], "cell": 0.05},
        "camera": {"position": [0.0, 6.0, 14.0], "target": [0.0, 1.0, 0.0], "fov_y_deg": 50.0,
                   "near_plane": 0.05, "far_plane": 200.0},
        "environment": ENVIRONMENT,
        # A winter afternoon sun from the south-west: the pines' and the
        # statue's shadows fall across the snow towards the camera's right.
        "sun": {"direction": [-0.5, 0.55, -0.6], "color": [1.0, 0.95, 0.86], "intensity": 4.0},
    }
    return g.document("park", [ground, statue] + benches + trees, snow)


def minimal():
    g = Gltf()
    ground = g.node("ground", g.mesh("ground", g.geometry(unit_box()),
                                     g.material("ground", (0.42, 0.4, 0.36))),
                    translation=[0.0, -0.1, 0.0], scale=[10.0, 0.2, 10.0], snow=GROUND)
    snow = {"simulation": {"dt": DT, "seed": 1, "max_flakes": 5000},
            "emitter": dict(EMITTER, rate=1000.0, snowfall_kg_m2_h=5.0)}
    return g.document("minimal", [ground], snow)


# --- the valley: a terrain of kilometres (docs/world.md) ----------------------

VALLEY_EXTENT = 4000.0           # m, each way, centred on the origin
VALLEY_SAMPLES = 257             # per side: 15.625 m apart, 131 072 triangles
VALLEY_HEIGHT = (0.0, 400.0)     # grey 0 and 65535 (m)
ROAD_FLAT, ROAD_BLEND = 20.0, 40.0      # half-width of the levelled band, its blend (m)
VILLAGE_AT = (0.0, 60.0)                # the terrace's centre (x, z)
VILLAGE_FLAT, VILLAGE_BLEND = 60.0, 90.0
SNOW_HALF = 60.0                        # snow falls on 120 x 120 m round the village


def smoothstep(e0, e1, x):
    t = min(max((x - e0) / (e1 - e0), 0.0), 1.0)
    return t * t * (3.0 - 2.0 * t)


def road_z(x):
    """The valley floor's line, along x."""
    return 160.0 * math.sin(x / 700.0) - 40.0 * math.sin(x / 260.0 + 0.5)


def road_y(x):
    """The road's height: a gentle climb along the valley."""
    return 60.0 + 25.0 * math.sin(x / 900.0 + 0.4) + 0.004 * x


def valley_y(x, z):
    """Hills round a valley (sums of sines), the road's band and the village's
    terrace levelled into them."""
    d = z - road_z(x)
    sides = 230.0 * (1.0 - math.exp(-d * d / (2.0 * 520.0 ** 2)))
    hills = (38.0 * math.sin(x / 310.0 + 0.3) * math.cos(z / 270.0)
             + 22.0 * math.sin((x + z) / 190.0)
             + 9.0 * math.sin(x / 97.0) * math.sin(z / 83.0 + 1.0)
             + 4.0 * math.sin(x / 41.0 + 2.0) * math.cos(z / 37.0))
    # Hills grow away from the floor, so the valley keeps a floor.
    y = road_y(x) + sides + hills * smoothstep(0.0, 400.0, abs(d))
    y = y + (road_y(x) - y) * (1.0 - smoothstep(ROAD_FLAT, ROAD_FLAT + ROAD_BLEND, abs(d)))
    r = math.hypot(x - VILLAGE_AT[0], z - VILLAGE_AT[1])
    return y + (village_y() - y) * (1.0 - smoothstep(VILLAGE_FLAT, VILLAGE_FLAT + VILLAGE_BLEND, r))


def village_y():
    return road_y(VILLAGE_AT[0])


def grey(y):
    lo, hi = VALLEY_HEIGHT
    return min(max(int(round((y - lo) / (hi - lo) * 65535.0)), 0), 65535)


def valley_samples():
    """Row j at z = -extent/2 + j·step (row 0 at minimum z), column i likewise in x."""
    n, step = VALLEY_SAMPLES, VALLEY_EXTENT / (VALLEY_SAMPLES - 1)
    half = 0.5 * VALLEY_EXTENT
    return [[grey(valley_y(-half + i * step, -half + j * step)) for i in range(n)]
            for j in range(n)]


def sample_height(samples, x, z):
    """The terrain mesh's height at (x, z): the loader's triangles, (i, j) →
    (i, j + 1) → (i + 1, j) and (i + 1, j) → (i, j + 1) → (i + 1, j + 1)."""
    lo, hi = VALLEY_HEIGHT
    step, half = VALLEY_EXTENT / (VALLEY_SAMPLES - 1), 0.5 * VALLEY_EXTENT
    u, v = (x + half) / step, (z + half) / step
    i, j = min(int(u), VALLEY_SAMPLES - 2), min(int(v), VALLEY_SAMPLES - 2)
    fu, fv = u - i, v - j
    h = [[lo + (hi - lo) * samples[j + b][i + a] / 65535.0 for a in (0, 1)] for b in (0, 1)]
    if fu + fv <= 1.0:
        return h[0][0] + fu * (h[0][1] - h[0][0]) + fv * (h[1][0] - h[0][0])
    return h[1][1] + (1.0 - fu) * (h[1][0] - h[1][1]) + (1.0 - fv) * (h[0][1] - h[1][1])


def png16(rows):
    """A 16-bit grey PNG of the rows (standard library only; deterministic:
    filter Up on every row, zlib level 9)."""
    width, height = len(rows[0]), len(rows)
    raw = bytearray()
    prev = bytes(2 * width)
    for row in rows:
        line = struct.pack(">%dH" % width, *row)
        raw.append(2)  # Up: smooth hills leave small differences that deflate well
        raw += bytes((line[k] - prev[k]) & 0xFF for k in range(len(line)))
        prev = line

    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data +
                struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF))
    header = struct.pack(">IIBBBBB", width, height, 16, 0, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) +
            chunk(b"IDAT", zlib.compress(bytes(raw), 9)) + chunk(b"IEND", b""))


def lcg(seed):
    """Deterministic uniform numbers in [0, 1) (no dependence on Python's random)."""
    state = seed
    while True:
        state = (state * 6364136223846793005 + 1442695040888963407) % (1 << 64)
        yield (state >> 11) / float(1 << 53)


def valley():
    samples = valley_samples()
    g = Gltf()
    box = g.geometry(unit_box())
    tree = g.geometry(cone())
    left, right = house_roofs(g)
    m_wall, m_roof, m_garage = building_materials(g)
    m_pine = g.material("pine", (0.12, 0.3, 0.16))
    m_road = g.material("road", (0.2, 0.2, 0.22))
    walls_mesh = g.mesh("walls", box, m_wall)
    roof_w_mesh = g.mesh("roof west", left, m_roof)
    roof_e_mesh = g.mesh("roof east", right, m_roof)
    garage_mesh = g.mesh("garage", box, m_garage)
    tree_mesh = g.mesh("tree", tree, m_pine)
    ground_y = village_y()
    lo_q = VALLEY_HEIGHT[0] + (VALLEY_HEIGHT[1] - VALLEY_HEIGHT[0]) * grey(ground_y) / 65535.0
    base = round(lo_q, 6)  # the terrace's height as the mesh has it

    # The village: the village scene's house (walls, two roof sides) and
    # garage, in two rows either side of a lane parallel to the road.
    roots = []
    vx, vz = VILLAGE_AT
    for k, (dx, dz) in enumerate(((-40, -22), (-20, -22), (0, -22), (20, -22), (40, -22),
                                  (-30, 22), (-10, 22), (10, 22), (30, 22))):
        walls = g.node("house %d walls" % k, walls_mesh, translation=[0.0, 1.5, 0.0],
                       scale=[5.0, 3.0, 4.0], snow={"collider": "box"})
        roof_w = g.node("house %d roof west" % k, roof_w_mesh, snow={"collider": "mesh"})
        roof_e = g.node("house %d roof east" % k, roof_e_mesh, snow={"collider": "mesh"})
        roots.append(g.node("house %d" % k, translation=[vx + dx, base, vz + dz],
                            children=[walls, roof_w, roof_e]))
    for k, (dx, dz) in enumerate(((-50, 8), (50, 8), (0, 36))):
        roots.append(g.node("garage %d" % k, garage_mesh,
                            translation=[vx + dx, base + 1.25, vz + dz], scale=[4.0, 2.5, 3.0],
                            snow={"collider": "box"}))

    # The road: a dark strip 8 m wide, drawn 0.2 m over the levelled band.
    half = 0.5 * VALLEY_EXTENT
    xs = [-half + 10.0 * k for k in range(int(VALLEY_EXTENT / 10.0) + 1)]
    positions, normals, indices = [], [], []
    for k, x in enumerate(xs):
        z = road_z(x)
        y = sample_height(samples, x, z) + 0.2
        positions += [[round(x, 4), round(y, 4), round(z - 4.0, 4)],
                      [round(x, 4), round(y, 4), round(z + 4.0, 4)]]
        normals += [[0.0, 1.0, 0.0], [0.0, 1.0, 0.0]]
        if k:
            a = 2 * k - 2
            indices += [a, a + 1, a + 2, a + 2, a + 1, a + 3]
    roots.append(g.node("road", g.mesh("road", g.geometry((positions, normals, indices)),
                                       m_road)))

    # The forest: pines on the slopes, off the road and the terrace; those in
    # the snowing region are colliders, the rest only drawn.
    rnd = lcg(31)
    trees = 0
    while trees < 300:
        x = (next(rnd) - 0.5) * 2400.0
        z = (next(rnd) - 0.5) * 2400.0
        h = 8.0 + 8.0 * next(rnd)
        if abs(z - road_z(x)) < ROAD_FLAT + ROAD_BLEND + 10.0:
            continue
        if math.hypot(x - vx, z - vz) < VILLAGE_FLAT + 5.0:
            continue
        y = round(sample_height(samples, x, z) - 0.5, 4)  # rooted below the slope
        snow = {"collider": "mesh"} if max(abs(x - vx), abs(z - vz)) < SNOW_HALF + 20.0 else None
        roots.append(g.node("tree %d" % trees, tree_mesh, translation=[round(x, 3), y, round(z, 3)],
                            scale=[round(0.3 * h, 4), round(h, 4), round(0.3 * h, 4)], snow=snow))
        trees += 1

    top = base + 25.0
    snow = {
        "simulation": {"dt": DT, "seed": 7, "max_flakes": 100000, "integrator": "euler",
                       "threads": 1,
                       "bounds": {"min": [vx - SNOW_HALF, base - 40.0, vz - SNOW_HALF],
                                  "max": [vx + SNOW_HALF, top, vz + SNOW_HALF]}},
        # Light snow (1 kg/m²/h) of flakes up to 1 cm: over 120 × 120 m that
        # takes about 3000 parcels a second to keep each under 5 g.
        "emitter": dict(EMITTER, rate=3000.0, snowfall_kg_m2_h=1.0, size_max=0.01),
        "wind": {"base": [1.5, 0.0, 0.4], "walk": 0.2, "max_deviation": 0.6},
        "fog": {"mode": "exponential", "color": [0.75, 0.78, 0.82], "density": 0.0006},
        "occlusion": {"resolution": 512, "tilt": 0.0},
        "cover": {"min": [vx - SNOW_HALF, vz - SNOW_HALF], "max": [vx + SNOW_HALF, vz + SNOW_HALF],
                  "cell": 0.25},
        "camera": {"position": [vx - 260.0, base + 110.0, vz + 330.0],
                   "target": [vx, base + 5.0, vz], "fov_y_deg": 50.0,
                   "near_plane": 0.5, "far_plane": 6000.0},
        "environment": ENVIRONMENT,
        "world": {"heightmap": "valley_height.png", "extent": [VALLEY_EXTENT, VALLEY_EXTENT],
                  "height": list(VALLEY_HEIGHT)},
    }
    return g.document("valley", roots, snow), png16(samples)


def render(value, depth=0):
    """JSON with objects one key per line and arrays of plain values on one line."""
    pad, inner = " " * depth, " " * (depth + 1)
    if isinstance(value, dict):
        items = [inner + json.dumps(k) + ": " + render(v, depth + 1) for k, v in value.items()]
        return "{\n" + ",\n".join(items) + "\n" + pad + "}"
    if isinstance(value, list) and any(isinstance(v, (dict, list)) for v in value):
        return "[\n" + ",\n".join(inner + render(v, depth + 1) for v in value) + "\n" + pad + "]"
    if isinstance(value, list):
        return "[" + ", ".join(json.dumps(v) for v in value) + "]"
    return json.dumps(value)


def main(argv):
    check = "--check" in argv[1:]
    valley_doc, valley_png = valley()
    scenes = {"village.gltf": village(False), "village_effects.gltf": village(True),
              "minimal.gltf": minimal(), "park.gltf": park(), "valley.gltf": valley_doc}
    files = {name: (render(doc) + "\n").encode("ascii") for name, doc in scenes.items()}
    files["valley_height.png"] = valley_png
    OUT_DIR.mkdir(parents=True, exist_ok=True)
    stale = []
    for name, data in files.items():
        path = OUT_DIR / name
        if path.exists() and path.read_bytes() == data:
            continue
        stale.append(name)
        if not check:
            path.write_bytes(data)
    if check and stale:
        print("make_assets: out of date: " + ", ".join(stale), file=sys.stderr)
        return 1
    for name in stale:
        print("make_assets: wrote assets/scenes/" + name)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
