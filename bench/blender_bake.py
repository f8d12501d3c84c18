# Cycles bake of direct diffuse light to a colour attribute, for comparison with vlit
# (docs/accuracy.md, "End to end: Blender Cycles"). Optional: nothing in the build or the tests
# needs Blender. Run by scripts/blender-compare.sh; by hand:
#
#   blender -b --factory-startup --python bench/blender_bake.py -- \
#       --asset ASSET.glb --lights LIGHTS.json --samples 1,4,16 --threads 1 --out DIR
#   blender -b --factory-startup --python bench/blender_bake.py -- --calibrate --out DIR
#
# --shadows: the lights cast shadows and every mesh casts them (scripts/cycles-shadows-compare.sh
# compares that bake with vlit's exact shadows, docs/shadows.md).
#
# Asset mode writes DIR/cycles-S.txt per sample count S: one line "x y z nx ny nz r" per face
# corner, position and corner normal in glTF coordinates (+Y up), r the baked value; and
# DIR/cycles-times.txt: "samples seconds" per bake (the bpy.ops.object.bake call only) plus
# "import seconds". The lights come from a vlit LIGHTS.json (docs/lights-json.md) and are mapped
# to Cycles as below.
#
# Radiometric mapping (vlit conventions: docs/conventions.md "Radiometric definitions"). Every
# material is replaced by a white Diffuse BSDF and Cycles bakes the DIFFUSE pass, direct light
# only, colour included: the baked value is the radiance leaving a white Lambertian surface,
# E / pi, with E the irradiance. vlit's COLOR_0 is Id = sum Ip * (geometric factor), which is E
# for a light of radiant intensity Ip (point) or radiance Ip (area). The powers below make Cycles'
# value equal vlit's Id; `--calibrate` checks each on a plane where the answer is known by hand.
# - point (falloff 2): a Cycles point light of power P (radius 0) has radiant intensity
#   P / (4 pi); its bake value is P / (4 pi) * cos / r^2 / pi. So P = 4 pi^2 Ip.
# - spot (falloff 2, inner = outer cone: Blender's blend 0 is a hard cone): same power as a point
#   light (Cycles does not concentrate a spot's power in its cone); spot_size = 2 * outer angle.
#   Not exact: Cycles 3.4 multiplies its spot by cos psi (psi: angle to the spot's axis), vlit
#   and glTF do not; --calibrate measures the spot with that factor divided out, and the asset
#   comparison uses no spot.
# - area: a quadrilateral that is a rectangle (glTF/LIGHTS.json polygon of 4 vertices with right
#   angles) becomes a RECTANGLE area light. Cycles gives a one-sided Lambertian emitter of power P
#   and area A the radiance P / (4 A) (its "power" is not the emitted flux pi L A); the bake value
#   is then L E_geom / pi with E_geom = integral cos cos_l / r^2 dA. vlit's Id = Ip E_geom, so
#   P = 4 pi A Ip. (Measured by --calibrate: see docs/accuracy.md.)
# - linear (falloff 2 only): vlit's linear light is a continuum of isotropic point emitters,
#   Ip dt each (docs/conventions.md, eq. 3-4). Neither of Blender's usual stand-ins has that emission
#   pattern: a thin rectangular area light is Lambertian (a cos theta_l factor, nothing along its
#   plane), and an emissive tube's projected width gives a sin psi factor (psi: angle to the axis).
#   So it becomes K point lights at the midpoints of K equal pieces, each of power 4 pi^2 Ip / K:
#   the midpoint rule of vlit's own integral, whose error (vlit bakes the same point chain for
#   the report) is the floor Cycles cannot go below in this comparison.
# Shadows are off (lights' cast_shadow, objects' shadow visibility) unless --shadows is given:
# vlit's bake does not shadow by default.
import json
import math
import os
import sys
import time

import bpy

LINEAR_POINTS = 32
SHADOWS = False  # set by --shadows


def fix_numpy_bool_alias():
    # Debian 12's Blender 3.4.1 glTF importer uses np.bool, which numpy 1.24 (python3-numpy, which
    # the importer needs) removed; restore the alias for this process only.
    try:
        import numpy
    except ImportError:
        sys.exit("blender_bake.py: Blender's glTF importer needs numpy (Debian: apt-get install python3-numpy)")
    if "bool" not in numpy.__dict__:
        numpy.bool = bool


def parse_args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    args = {"samples": "1,4,16,64", "threads": "1", "out": None, "asset": None, "lights": None, "calibrate": False,
            "shadows": False}
    i = 0
    while i < len(argv):
        a = argv[i]
        if a == "--calibrate":
            args["calibrate"] = True
        elif a == "--shadows":
            args["shadows"] = True
        elif a in ("--asset", "--lights", "--samples", "--threads", "--out") and i + 1 < len(argv):
            args[a[2:]] = argv[i + 1]
            i += 1
        else:
            sys.exit("blender_bake.py: unknown argument " + a)
        i += 1
    if not args["out"]:
        sys.exit("blender_bake.py: --out DIR is required")
    if not args["calibrate"] and (not args["asset"] or not args["lights"]):
        sys.exit("blender_bake.py: --asset and --lights are required (or --calibrate)")
    return args


# glTF (+Y up) <-> Blender (+Z up), as Blender's glTF importer converts.
def to_blender(p):
    return (p[0], -p[2], p[1])


def to_gltf(p):
    return (p[0], p[2], -p[1])


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def length(a):
    return math.sqrt(dot(a, a))


def normalize(a):
    n = length(a)
    return (a[0] / n, a[1] / n, a[2] / n)


def orient(obj, direction):
    # Blender lights shine along their local -Z.
    import mathutils
    obj.rotation_euler = mathutils.Vector(direction).to_track_quat("-Z", "Y").to_euler()


def add_light(name, kind, location, power, **extra):
    data = bpy.data.lights.new(name, kind)
    data.energy = power
    data.color = (1.0, 1.0, 1.0)
    data.cycles.cast_shadow = SHADOWS
    data.use_shadow = SHADOWS
    if kind in ("POINT", "SPOT"):
        data.shadow_soft_size = 0.0
    for k, v in extra.items():
        setattr(data, k, v)
    obj = bpy.data.objects.new(name, data)
    bpy.context.scene.collection.objects.link(obj)
    obj.location = location
    return obj


def check_falloff(light, name):
    if abs(light.get("falloff", 2) - 2) > 0:
        sys.exit("blender_bake.py: %s: falloff %g has no Cycles light (only 2, the physical one)" % (name, light["falloff"]))


def add_vlit_light(light, index):
    """Adds the Cycles light(s) equivalent to one LIGHTS.json light (positions in glTF space)."""
    kind = light["type"]
    name = light.get("name", "%s%d" % (kind, index))
    ip = float(light.get("intensity", 1.0))
    if kind == "point":
        check_falloff(light, name)
        add_light(name, "POINT", to_blender(light["position"]), 4 * math.pi ** 2 * ip)
    elif kind == "spot":
        check_falloff(light, name)
        inner, outer = light.get("inner_cone_angle", 0.0), light.get("outer_cone_angle", math.pi / 4)
        if inner != outer:
            sys.exit("blender_bake.py: %s: only a hard cone (inner = outer) maps to Cycles' spot" % name)
        obj = add_light(name, "SPOT", to_blender(light["position"]), 4 * math.pi ** 2 * ip,
                        spot_size=2 * outer, spot_blend=0.0)
        orient(obj, to_blender(light["direction"]))
    elif kind == "linear":
        check_falloff(light, name)
        a, b = light["from"], light["to"]
        for k in range(LINEAR_POINTS):
            t = (k + 0.5) / LINEAR_POINTS
            p = tuple(a[i] + t * (b[i] - a[i]) for i in range(3))
            add_light("%s.%d" % (name, k), "POINT", to_blender(p), 4 * math.pi ** 2 * ip / LINEAR_POINTS)
    elif kind == "area":
        poly = [tuple(q) for q in light["polygon"]]
        if len(poly) != 4:
            sys.exit("blender_bake.py: %s: only rectangles map to Cycles' area light" % name)
        e1, e2 = sub(poly[1], poly[0]), sub(poly[3], poly[0])
        if abs(dot(e1, e2)) > 1e-6 * length(e1) * length(e2) or length(sub(sub(poly[2], poly[1]), e2)) > 1e-6 * length(e2):
            sys.exit("blender_bake.py: %s: the polygon is not a rectangle" % name)
        if light.get("two_sided", False):
            sys.exit("blender_bake.py: %s: two-sided area lights are not mapped" % name)
        centre = tuple(sum(q[i] for q in poly) / 4 for i in range(3))
        normal = normalize(cross(e1, e2))  # counter-clockwise seen from the emitting side
        w, h = length(e1), length(e2)
        data = add_light(name, "AREA", to_blender(centre), 4 * math.pi * w * h * ip, shape="RECTANGLE", size=h, size_y=w)
        # Light sampling only: with multiple importance sampling Cycles weights the light sample
        # expecting the BSDF-sampled hit of the light to add the rest, and with max_bounces = 0
        # that hit is never counted (measured: the panel's light came out 5x too dark next to
        # the point chains).
        data.data.cycles.use_multiple_importance_sampling = False
        import mathutils
        # Local X along e2, local Y along e1 (right-handed with Z = -normal, since e1 x e2 is the
        # normal); local -Z is the emission direction.
        x, y = mathutils.Vector(to_blender(normalize(e2))), mathutils.Vector(to_blender(normalize(e1)))
        z = -mathutils.Vector(to_blender(normal))
        m = mathutils.Matrix((x, y, z)).transposed()
        data.rotation_euler = m.to_euler()
    else:
        sys.exit("blender_bake.py: %s: light type %s is not mapped to Cycles" % (name, kind))


def setup_cycles(threads):
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.use_adaptive_sampling = False
    scene.cycles.use_denoising = False
    scene.cycles.max_bounces = 0
    scene.cycles.diffuse_bounces = 0
    scene.cycles.seed = 1
    scene.cycles.light_sampling_threshold = 0.0
    scene.render.threads_mode = "FIXED"
    scene.render.threads = threads
    scene.world = bpy.data.worlds.new("black")
    scene.world.color = (0.0, 0.0, 0.0)
    scene.world.use_nodes = False
    bake = scene.render.bake
    bake.target = "VERTEX_COLORS"
    bake.use_pass_direct = True
    bake.use_pass_indirect = False
    bake.use_pass_color = True
    scene.cycles.bake_type = "DIFFUSE"


def white_diffuse():
    mat = bpy.data.materials.new("vlit_white")
    mat.use_nodes = True
    nodes = mat.node_tree.nodes
    nodes.clear()
    bsdf = nodes.new("ShaderNodeBsdfDiffuse")
    bsdf.inputs["Color"].default_value = (1.0, 1.0, 1.0, 1.0)
    bsdf.inputs["Roughness"].default_value = 0.0
    out = nodes.new("ShaderNodeOutputMaterial")
    mat.node_tree.links.new(bsdf.outputs["BSDF"], out.inputs["Surface"])
    return mat


def prepare_meshes():
    mat = white_diffuse()
    meshes = [o for o in bpy.context.scene.objects if o.type == "MESH"]
    bpy.ops.object.select_all(action="DESELECT")
    for o in meshes:
        o.data.materials.clear()
        o.data.materials.append(mat)
        for poly in o.data.polygons:
            poly.material_index = 0
        o.visible_shadow = SHADOWS
        for a in list(o.data.color_attributes):
            o.data.color_attributes.remove(a)
        attr = o.data.color_attributes.new("cycles_bake", "FLOAT_COLOR", "CORNER")
        o.data.color_attributes.active_color = attr
        o.select_set(True)
    bpy.context.view_layer.objects.active = meshes[0]
    return meshes


def bake(samples):
    bpy.context.scene.cycles.samples = samples
    t0 = time.perf_counter()
    bpy.ops.object.bake(type="DIFFUSE", pass_filter={"DIRECT", "COLOR"}, target="VERTEX_COLORS")
    return time.perf_counter() - t0


def corner_records(meshes):
    """(position, corner normal, value) per face corner, world space, glTF axes."""
    out = []
    for o in meshes:
        me = o.data
        me.calc_normals_split()
        mw = o.matrix_world
        nw = mw.to_3x3().inverted().transposed()
        colors = me.color_attributes["cycles_bake"].data
        for loop in me.loops:
            p = mw @ me.vertices[loop.vertex_index].co
            n = (nw @ loop.normal).normalized()
            out.append((to_gltf(p), to_gltf(n), colors[loop.index].color[0]))
    return out


def run_asset(args):
    global SHADOWS
    SHADOWS = args["shadows"]
    for path in (args["asset"], args["lights"]):
        if not os.path.isfile(path):
            sys.exit("blender_bake.py: %s: no such file" % path)
    try:
        with open(args["lights"]) as f:
            lights = json.load(f)["lights"]
    except (ValueError, KeyError, TypeError) as e:
        sys.exit("blender_bake.py: %s: not a LIGHTS.json with a \"lights\" array (%s)" % (args["lights"], e))
    bpy.ops.wm.read_factory_settings(use_empty=True)
    fix_numpy_bool_alias()
    t0 = time.perf_counter()
    bpy.ops.import_scene.gltf(filepath=os.path.abspath(args["asset"]))
    import_s = time.perf_counter() - t0
    for o in [o for o in bpy.context.scene.objects if o.type == "LIGHT"]:
        bpy.data.objects.remove(o)
    for i, light in enumerate(lights):
        try:
            add_vlit_light(light, i)
        except (KeyError, TypeError, ValueError) as e:
            sys.exit("blender_bake.py: %s: /lights/%d: bad or missing property %s" % (args["lights"], i, e))
    setup_cycles(int(args["threads"]))
    meshes = prepare_meshes()
    os.makedirs(args["out"], exist_ok=True)
    times = ["import %.6f" % import_s]
    for s in [int(x) for x in args["samples"].split(",")]:
        seconds = bake(s)
        times.append("%d %.6f" % (s, seconds))
        print("blender_bake: %d samples: %.3f s" % (s, seconds), flush=True)
        with open(os.path.join(args["out"], "cycles-%d.txt" % s), "w") as f:
            for p, n, r in corner_records(meshes):
                f.write("%.9g %.9g %.9g %.7g %.7g %.7g %.9g\n" % (p + n + (r,)))
    with open(os.path.join(args["out"], "cycles-times.txt"), "w") as f:
        f.write("\n".join(times) + "\n")
    with open(os.path.join(args["out"], "blender-version.txt"), "w") as f:
        f.write(bpy.app.version_string + "\n")


# --- Calibration: one light at a time over a plane, against the answer computed by hand. -----

def hand_point(p, n, q, ip):
    l = sub(q, p)
    c = dot(l, n)
    return ip * c / length(l) ** 3 if c > 0 else 0.0


def hand_rectangle(p, n, poly, ip):
    # Lambert's polygon formula (irradiance from a uniform Lambertian polygon of radiance ip):
    # E = ip / 2 * sum_i angle(v_i, v_i+1) * (unit(v_i x v_i+1) . n), v_i = corner_i - p, for a
    # polygon entirely above the tangent plane, wound so that the sum is positive.
    emit = cross(sub(poly[1], poly[0]), sub(poly[2], poly[0]))  # counter-clockwise from the lit side
    if dot(sub(p, poly[0]), emit) <= 0:
        return 0.0
    v = [normalize(sub(q, p)) for q in poly]
    s = 0.0
    for i in range(len(v)):
        a, b = v[i], v[(i + 1) % len(v)]
        s += math.acos(max(-1.0, min(1.0, dot(a, b)))) * dot(normalize(cross(a, b)), n)
    return ip / 2 * abs(s)


def run_calibration(args):
    """A 2 x 2 plane at y = 0 (glTF axes) facing +Y, 17 x 17 vertices, one light at a time."""
    results = []
    cases = [
        ("point", {"type": "point", "position": [0.3, 1.5, -0.2], "intensity": 2.0}),
        ("spot", {"type": "spot", "position": [0.0, 2.0, 0.0], "direction": [0.0, -1.0, 0.0],
                  "inner_cone_angle": 0.6, "outer_cone_angle": 0.6, "intensity": 1.5}),
        ("area", {"type": "area", "intensity": 0.7,
                  "polygon": [[0.5, 1.0, -0.25], [0.5, 1.0, 0.25], [-0.5, 1.0, 0.25], [-0.5, 1.0, -0.25]]}),
        ("linear", {"type": "linear", "from": [-0.6, 0.8, 0.1], "to": [0.7, 0.8, 0.1], "intensity": 1.2}),
    ]
    samples = 1024
    for label, light in cases:
        bpy.ops.wm.read_factory_settings(use_empty=True)
        bpy.ops.mesh.primitive_grid_add(x_subdivisions=17, y_subdivisions=17, size=2.0)
        bpy.ops.object.shade_smooth()
        add_vlit_light(light, 0)
        setup_cycles(int(args["threads"]))
        meshes = prepare_meshes()
        bake(samples)
        ratios = []
        for p, n, r in corner_records(meshes):
            if label == "point":
                h = hand_point(p, n, tuple(light["position"]), light["intensity"])
            elif label == "spot":
                q = tuple(light["position"])
                d = normalize(sub(p, q))
                inside = dot(d, (0.0, -1.0, 0.0)) > math.cos(light["outer_cone_angle"])
                # Cycles 3.4's spot multiplies the point light by cos psi, psi the angle to the
                # spot's axis (its spot attenuation starts from dot(axis, direction)); vlit's
                # (glTF's) hard cone does not. The check divides that factor out.
                cos_psi = dot(d, (0.0, -1.0, 0.0))
                h = hand_point(p, n, q, light["intensity"]) * cos_psi if inside else 0.0
                # Skip the vertices within 0.02 rad of the cone's edge (a step there).
                if abs(math.acos(dot(d, (0.0, -1.0, 0.0))) - light["outer_cone_angle"]) < 0.02:
                    continue
            elif label == "area":
                h = hand_rectangle(p, n, [tuple(q) for q in light["polygon"]], light["intensity"])
            else:
                a, b, k = light["from"], light["to"], 4096
                h = sum(hand_point(p, n, tuple(a[i] + (j + 0.5) / k * (b[i] - a[i]) for i in range(3)),
                                   light["intensity"] / k) for j in range(k))
            if h > 0:
                ratios.append(r / h)
            elif r != 0:
                ratios.append(float("inf"))
        ratios.sort()
        line = "%-6s Cycles/hand over %d lit corners (%d samples): min %.4f median %.4f max %.4f" % (
            label, len(ratios), samples, ratios[0], ratios[len(ratios) // 2], ratios[-1])
        print("blender_bake: " + line, flush=True)
        results.append(line)
    os.makedirs(args["out"], exist_ok=True)
    with open(os.path.join(args["out"], "calibration.txt"), "w") as f:
        f.write("\n".join(results) + "\n")


def main():
    args = parse_args()
    if args["calibrate"]:
        run_calibration(args)
    else:
        run_asset(args)


main()
