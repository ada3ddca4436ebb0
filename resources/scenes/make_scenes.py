"""Generate RigidLab's sample scenes with Blender and export them as OBJ.

Run headless (Blender 3.4):

    blender -b --factory-startup --python resources/scenes/make_scenes.py [-- OUTDIR]

OUTDIR defaults to the folder holding this script. Every scene is built from
an empty file in code, exported with Blender's own OBJ exporter
(bpy.ops.export_scene.obj with its defaults: forward -Z, up Y, materials on,
modifiers applied, whole scene), then read back with plain Python and checked.

All placements below are written in OBJ coordinates (Y up, metres). The helper
`place` converts them to Blender's Z-up frame so that the exporter's axis
conversion brings them back exactly.
"""

import math
import os
import sys

import bmesh  # noqa: F401  (kept for interactive use of this script)
import bpy
from mathutils import Matrix, Vector

PRESETS = ("Default", "Steel", "Wood", "Rubber", "Ice", "Concrete", "Plastic")

# Display colours only (written as Kd in the .mtl); physics comes from the name.
COLOURS = {
    "Default": (0.8, 0.8, 0.8), "Steel": (0.55, 0.6, 0.68), "Wood": (0.6, 0.4, 0.2),
    "Rubber": (0.55, 0.1, 0.1), "Ice": (0.7, 0.9, 1.0), "Concrete": (0.5, 0.5, 0.48),
    "Plastic": (0.95, 0.8, 0.1), "MyPaint": (0.5, 0.2, 0.7),
}

# OBJ (x, y, z) -> Blender (x, -z, y); a proper rotation (det +1).
C = Matrix(((1.0, 0.0, 0.0, 0.0),
            (0.0, 0.0, -1.0, 0.0),
            (0.0, 1.0, 0.0, 0.0),
            (0.0, 0.0, 0.0, 1.0)))
C_INV = C.inverted()


def out_dir():
    if "--" in sys.argv:
        rest = sys.argv[sys.argv.index("--") + 1:]
        if rest:
            return os.path.abspath(rest[0])
    return os.path.dirname(os.path.abspath(__file__))


# ----------------------------------------------------------------------------
# Scene building helpers
# ----------------------------------------------------------------------------

class SceneBuilder:
    def __init__(self):
        bpy.ops.wm.read_factory_settings(use_empty=True)
        self.collection = bpy.context.scene.collection
        self.materials = {}
        self.objects = []  # in file order

    def material(self, name):
        if name not in self.materials:
            mat = bpy.data.materials.new(name)
            assert mat.name == name, (mat.name, name)
            mat.diffuse_color = COLOURS.get(name, (0.8, 0.8, 0.8)) + (1.0,)
            self.materials[name] = mat
        return self.materials[name]

    @staticmethod
    def primitive(kind, **kwargs):
        """Make a mesh with one of Blender's own primitive operators.

        The temporary object is removed again; only its mesh is kept.
        """
        getattr(bpy.ops.mesh, "primitive_%s_add" % kind)(**kwargs)
        tmp = bpy.context.active_object
        mesh = tmp.data
        mesh.name = "tmp_mesh"
        bpy.data.objects.remove(tmp, do_unlink=True)
        return mesh

    def add(self, name, mesh, material=None, location=(0.0, 0.0, 0.0),
            rotation=None, scale=(1.0, 1.0, 1.0)):
        """Link a new object in file order; transform given in OBJ coordinates.

        rotation is None or (axis_xyz, angle_degrees) about an OBJ-space axis.
        """
        obj = bpy.data.objects.new(name, mesh)
        # Blender numbers repeated names itself: Cube, Cube.001, Cube.002, ...
        assert obj.name == name or obj.name.startswith(name + "."), obj.name
        self.collection.objects.link(obj)
        if material is not None:
            mesh.materials.clear()
            mesh.materials.append(self.material(material))
        place(obj, location, rotation, scale)
        self.objects.append(obj)
        return obj

    def export(self, path):
        # The legacy exporter writes "o <object>_<mesh>" when the names differ.
        for i, obj in enumerate(self.objects):
            obj.data.name = "tmp_%d" % i
        for obj in self.objects:
            obj.data.name = obj.name
            assert obj.data.name == obj.name
        assert [o.name for o in bpy.context.scene.objects] == \
            [o.name for o in self.objects], "scene order differs from build order"
        bpy.ops.export_scene.obj(
            filepath=path,
            use_selection=False,
            use_mesh_modifiers=True,
            use_materials=True,
            axis_forward='-Z',
            axis_up='Y',
        )
        print("exported", path)


def place(obj, location, rotation=None, scale=(1.0, 1.0, 1.0)):
    """Set obj.matrix_world from an OBJ-space translation, rotation and scale.

    The primitive's local shape is read in OBJ axes too (a Blender plane lies in
    OBJ's xz plane, a cylinder's axis is OBJ's y axis).
    """
    t = Matrix.Translation(Vector(location))
    r = Matrix.Identity(4)
    if rotation is not None:
        axis, deg = rotation
        r = Matrix.Rotation(math.radians(deg), 4, Vector(axis).normalized())
    s = Matrix.Diagonal(Vector((scale[0], scale[1], scale[2], 1.0)))
    obj.matrix_world = C @ t @ r @ s @ C_INV


def world_min_y(obj):
    """Lowest OBJ y of the object's vertices after its transform."""
    bpy.context.view_layer.update()
    m = obj.matrix_world
    return min((m @ v.co).z for v in obj.data.vertices)  # Blender z == OBJ y


def world_box(obj):
    bpy.context.view_layer.update()
    m = obj.matrix_world
    pts = [C_INV @ (m @ v.co) for v in obj.data.vertices]
    lo = [min(p[i] for p in pts) for i in range(3)]
    hi = [max(p[i] for p in pts) for i in range(3)]
    return lo, hi


def rest_on(obj, floor_y, gap):
    """Translate obj (in OBJ y) so that its lowest vertex is floor_y + gap."""
    dy = floor_y + gap - world_min_y(obj)
    loc = obj.location.copy()
    loc.z += dy  # Blender z == OBJ y
    obj.location = loc
    bpy.context.view_layer.update()


# ----------------------------------------------------------------------------
# Scenes
# ----------------------------------------------------------------------------

def build_stack():
    """Floor plane and a tower of 10 unit cubes, exactly touching."""
    b = SceneBuilder()
    b.add("Anchor", b.primitive("plane", size=20.0), "Concrete")
    for i in range(10):
        b.add("Cube", b.primitive("cube", size=1.0), "Wood",
              location=(0.0, 0.5 + i, 0.0))
    return b


def build_pyramid():
    """A 10-wide pyramid of 55 unit cubes, each row shifted by half a cube."""
    b = SceneBuilder()
    b.add("Anchor", b.primitive("plane", size=20.0), "Concrete")
    for row in range(10):
        n = 10 - row
        for j in range(n):
            x = -0.5 * (n - 1) + j
            b.add("Cube", b.primitive("cube", size=1.0), "Wood",
                  location=(x, 0.5 + row, 0.0))
    return b


RAMP_COUNT = 3
RAMP_CUBES = 642


def build_ramps():
    """Three tilted anchor ramps side by side and 642 small cubes above them."""
    b = SceneBuilder()
    b.add("Anchor", b.primitive("plane", size=30.0), "Concrete")
    # (tilt in degrees about OBJ z, centre z). Ramps: 6 m long (x), 0.3 m
    # thick (y), 3 m wide (z), centred at x = 0, y = 2.5.
    ramp_specs = [(20.0, -4.0), (27.5, 0.0), (35.0, 4.0)]
    ramps = []
    for tilt, z in ramp_specs:
        ramps.append(b.add("Anchor", b.primitive("cube", size=1.0), "Concrete",
                           location=(0.0, 2.5, z),
                           rotation=((0.0, 0.0, 1.0), -tilt),  # lower at +x
                           scale=(6.0, 0.3, 3.0)))
    # 642 cubes of 0.2 m: per ramp a grid of 11 (x) by 7 (z) at 0.4 m pitch,
    # layers 0.4 m apart, starting 0.5 m above the ramp's highest point.
    # 642 = 3 * 214 = 3 * (2 * 77 + 60): two full layers and a partial one.
    per_ramp = RAMP_CUBES // RAMP_COUNT
    pitch = 0.4
    cube_mesh_count = 0
    for ramp, (tilt, zc) in zip(ramps, ramp_specs):
        lo, hi = world_box(ramp)
        base_y = hi[1] + 0.5 + 0.1  # cube centre of the lowest layer
        k = 0
        layer = 0
        while k < per_ramp:
            for iz in range(7):
                for ix in range(11):
                    if k == per_ramp:
                        break
                    x = (ix - 5) * pitch
                    z = zc + (iz - 3) * pitch
                    y = base_y + layer * pitch
                    b.add("Cube", b.primitive("cube", size=0.2), "Default",
                          location=(x, y, z))
                    k += 1
                    cube_mesh_count += 1
            layer += 1
    assert cube_mesh_count == RAMP_CUBES
    return b


def build_mixed():
    """Mixed shapes and materials; anchors at the end of the file."""
    b = SceneBuilder()
    gap = 0.05
    dyn = []
    dyn.append(b.add("Sphere", b.primitive("uv_sphere", segments=32, ring_count=16, radius=0.5),
                     "Rubber", location=(-4.5, 0.0, 0.0)))
    dyn.append(b.add("Cylinder", b.primitive("cylinder", vertices=32, radius=0.4, depth=1.2,
                                              end_fill_type='NGON'),
                     "Steel", location=(-3.0, 0.0, 0.0)))
    # The cone has no material: the exporter writes "usemtl None" -> Default.
    dyn.append(b.add("Cone", b.primitive("cone", vertices=32, radius1=0.5, radius2=0.0, depth=1.0,
                                          end_fill_type='NGON'),
                     None, location=(-1.5, 0.0, 0.0)))
    dyn.append(b.add("Icosphere", b.primitive("ico_sphere", subdivisions=2, radius=0.5),
                     "Ice", location=(0.0, 0.0, 0.0)))
    dyn.append(b.add("Cube", b.primitive("cube", size=1.0), "Plastic",
                     location=(1.6, 0.0, 0.0),
                     rotation=((1.0, 1.0, 0.3), 40.0),
                     scale=(1.2, 0.5, 0.8)))
    dyn.append(b.add("Torus", b.primitive("torus", major_radius=0.6, minor_radius=0.2,
                                           major_segments=48, minor_segments=12),
                     "Wood", location=(3.4, 0.0, 0.0),
                     rotation=((1.0, 0.0, 0.0), 15.0)))
    for obj in dyn:
        rest_on(obj, 0.0, gap)
    # A slab anchor with a crate resting slightly above it.
    slab = b.add("Crate", b.primitive("cube", size=0.8), "MyPaint",
                 location=(0.0, 0.0, -3.0))
    b.add("Anchor.002", b.primitive("cube", size=1.0), "Concrete",
          location=(0.0, 0.25, -3.0), scale=(4.0, 0.5, 2.0))
    rest_on(slab, 0.5, gap)
    b.add("Anchor", b.primitive("plane", size=20.0), "Concrete")
    return b


# ----------------------------------------------------------------------------
# Reading the exported file back (plain Python, OBJ coordinates)
# ----------------------------------------------------------------------------

def read_obj(path):
    """Return [(name, [usemtl...], [(x, y, z)...], [faces as index lists])]."""
    objs = []
    verts = []
    cur = None
    with open(path) as f:
        for line in f:
            parts = line.split()
            if not parts:
                continue
            if parts[0] == "o":
                cur = {"name": line[2:].strip(), "mtl": [], "v": [], "f": []}
                objs.append(cur)
            elif parts[0] == "v":
                p = tuple(float(t) for t in parts[1:4])
                verts.append(p)
                cur["v"].append(len(verts) - 1)
            elif parts[0] == "usemtl":
                cur["mtl"].append(line[7:].strip())
            elif parts[0] == "f":
                cur["f"].append([int(t.split("/")[0]) - 1 for t in parts[1:]])
    out = []
    for o in objs:
        used = {i for face in o["f"] for i in face}
        assert used == set(o["v"]), "faces of %s use foreign vertices" % o["name"]
        out.append((o["name"], o["mtl"], [verts[i] for i in o["v"]], o["f"]))
    return out


def box_of(pts):
    return ([min(p[i] for p in pts) for i in range(3)],
            [max(p[i] for p in pts) for i in range(3)])


def boxes_overlap(a, b):
    return all(a[0][i] < b[1][i] and b[0][i] < a[1][i] for i in range(3))


def check(path, builder):
    objs = read_obj(path)
    names = [o[0] for o in objs]
    assert names == [o.name for o in builder.objects], "object names/order differ"
    n_usemtl = sum(len(o[1]) for o in objs)
    mats = {}
    for name, mtl, _, _ in objs:
        assert len(mtl) == 1, "%s has %d usemtl lines" % (name, len(mtl))
        mats[mtl[0]] = mats.get(mtl[0], 0) + 1
    anchors = [n for n in names if strip_digits(n) == "Anchor"]
    print("%s: %d objects, %d anchors %s, %d usemtl lines, materials %s"
          % (os.path.basename(path), len(objs), len(anchors), anchors, n_usemtl,
             dict(sorted(mats.items()))))
    return objs


def strip_digits(name):
    """The anchor rule: remove every '.' followed by digits."""
    out = []
    i = 0
    while i < len(name):
        if name[i] == "." and i + 1 < len(name) and name[i + 1].isdigit():
            i += 1
            while i < len(name) and name[i].isdigit():
                i += 1
        else:
            out.append(name[i])
            i += 1
    return "".join(out)


def check_stack(objs):
    assert len(objs) == 11
    lo, hi = box_of(objs[0][2])
    assert lo[1] == hi[1] == 0.0 and hi[0] - lo[0] == 20.0 and hi[2] - lo[2] == 20.0
    for i, (name, mtl, pts, _) in enumerate(objs[1:]):
        lo, hi = box_of(pts)
        assert mtl == ["Wood"] and len(pts) == 8
        assert lo[1] == float(i) and hi[1] == float(i + 1), (name, lo, hi)
        assert hi[0] - lo[0] == 1.0 and hi[2] - lo[2] == 1.0


def check_pyramid(objs):
    assert len(objs) == 56
    cubes = [box_of(o[2]) for o in objs[1:]]
    for b in cubes:
        assert all(b[1][i] - b[0][i] == 1.0 for i in range(3))
        assert b[0][1] == int(b[0][1]) >= 0
    for i in range(len(cubes)):
        for j in range(i + 1, len(cubes)):
            assert not boxes_overlap(cubes[i], cubes[j])
    rows = {}
    for b in cubes:
        rows.setdefault(b[0][1], []).append(b[0][0])
    for y, xs in rows.items():
        xs.sort()
        assert all(xs[k + 1] - xs[k] == 1.0 for k in range(len(xs) - 1))  # gap-free
    assert sorted(len(v) for v in rows.values()) == list(range(1, 11))


def check_ramps(objs):
    ramps = [o for o in objs if strip_digits(o[0]) == "Anchor"]
    cubes = [o for o in objs if strip_digits(o[0]) != "Anchor"]
    assert len(ramps) == 1 + RAMP_COUNT and len(cubes) == RAMP_CUBES
    assert all(o[1] == ["Default"] for o in cubes)
    assert all(o[1] == ["Concrete"] for o in ramps)
    ramp_top = max(box_of(o[2])[1][1] for o in ramps)
    boxes = [box_of(o[2]) for o in cubes]
    for b in boxes:
        assert all(abs(b[1][i] - b[0][i] - 0.2) < 1e-6 for i in range(3))
    lowest = min(b[0][1] for b in boxes)
    print("  ramps: highest ramp point y=%r, lowest cube bottom y=%r" % (ramp_top, lowest))
    # Each cube is above every ramp part below it: check the cube's bottom
    # against the top of the ramp it is placed over.
    for ramp in ramps[1:]:
        rb = box_of(ramp[2])
        over = [b for b in boxes if rb[0][2] <= b[0][2] and b[1][2] <= rb[1][2]]
        assert over and min(b[0][1] for b in over) > rb[1][1]
    # No two cubes overlap (sort-and-sweep on x).
    order = sorted(range(len(boxes)), key=lambda i: boxes[i][0][0])
    for a in range(len(order)):
        ba = boxes[order[a]]
        for c in range(a + 1, len(order)):
            bc = boxes[order[c]]
            if bc[0][0] >= ba[1][0]:
                break
            assert not boxes_overlap(ba, bc)


def check_mixed(objs):
    by = {o[0]: o for o in objs}
    floor = box_of(by["Anchor"][2])
    assert floor[0][1] == floor[1][1] == 0.0
    dyn = [o for o in objs if strip_digits(o[0]) != "Anchor"]
    boxes = [box_of(o[2]) for o in dyn]
    for o, b in zip(dyn, boxes):
        print("  %-10s usemtl %-9s %3d verts, lowest y %.6f" % (o[0], o[1][0], len(o[2]), b[0][1]))
        assert b[0][1] > 0.0
    for i in range(len(boxes)):
        for j in range(i + 1, len(boxes)):
            assert not boxes_overlap(boxes[i], boxes[j]), (dyn[i][0], dyn[j][0])
    slab = box_of(by["Anchor.002"][2])
    crate = box_of(by["Crate"][2])
    assert crate[0][1] > slab[1][1]
    for o, b in zip(dyn, boxes):
        if o[0] != "Crate":
            assert not boxes_overlap(b, slab)


SCENES = [
    ("stack.obj", build_stack, check_stack),
    ("ramps.obj", build_ramps, check_ramps),
    ("mixed.obj", build_mixed, check_mixed),
    ("pyramid.obj", build_pyramid, check_pyramid),
]


def main():
    d = out_dir()
    os.makedirs(d, exist_ok=True)
    for fname, build, scene_check in SCENES:
        builder = build()
        path = os.path.join(d, fname)
        builder.export(path)
        scene_check(check(path, builder))
    print("all scenes written and checked")


main()
