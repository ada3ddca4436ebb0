"""Export tests/data/blender/shapes.obj with Blender and compute its expected values.

Run headless (Blender 3.4):

    blender -b --factory-startup --python-exit-code 1 \
        --python tests/data/blender/make_expected.py [-- OUTDIR]

1. The script builds about a dozen objects from Blender's own primitives and exports them with
   bpy.ops.export_scene.obj (defaults: forward -Z, up Y, materials on, modifiers applied, whole scene).
2. It reads shapes.obj back with plain Python. Everything below uses the exported text coordinates
   (Y up) as doubles, never Blender's internal Z-up data.
3. For every object it computes:
     name, anchor (DESIGN.md section 3: remove every '.' followed by digits; static iff exactly "Anchor"),
     material (the usemtl name if it is a preset, case-insensitive, in the preset's spelling; else "Default"),
     vertex_mean (mean of the object's v entries, each counted once),
     hull_volume and hull_centroid. bmesh.ops.convex_hull runs on the exported points. bmesh works in single
     precision with a tolerance, and on this file its hull leaves points up to 7.6e-5 m outside its faces,
     which moves volumes by up to 2.9e-7. Its hull vertices therefore seed an incremental hull in double
     precision (exact_hull) over all the exported points. That hull is certified: it is closed, V - E + F = 2,
     and no point lies more than 1e-9 m in front of any face. Volume and centroid then come from the
     divergence theorem in double precision. For a flat object the volume is 0 and the centroid is the area
     centroid of its 2-D hull.
4. It writes shapes_expected.json: {"bodies": [{"name", "anchor", "material", "vertex_mean",
   "hull_volume", "hull_centroid"}]}. Floats are Python repr (shortest round trip).

Cross-checks printed: the closed forms for the cube, box and 32-gon cylinders. For every closed convex mesh,
the volume of its own faces equals the hull volume. The worst distance of any point outside a hull face shows
how convex the hull is in double precision.
"""

import json
import math
import os
import sys

import bmesh
import bpy
from mathutils import Matrix, Vector

PRESETS = ("Default", "Steel", "Wood", "Rubber", "Ice", "Concrete", "Plastic")

# OBJ (x, y, z) -> Blender (x, -z, y)
TO_BLENDER = Matrix(((1.0, 0.0, 0.0, 0.0),
                     (0.0, 0.0, -1.0, 0.0),
                     (0.0, 1.0, 0.0, 0.0),
                     (0.0, 0.0, 0.0, 1.0)))


def out_dir():
    if "--" in sys.argv:
        rest = sys.argv[sys.argv.index("--") + 1:]
        if rest:
            return os.path.abspath(rest[0])
    return os.path.dirname(os.path.abspath(__file__))


# ----------------------------------------------------------------------------
# 1. Build and export
# ----------------------------------------------------------------------------

def make_mesh(kind, **kwargs):
    getattr(bpy.ops.mesh, "primitive_%s_add" % kind)(**kwargs)
    tmp = bpy.context.active_object
    mesh = tmp.data
    bpy.data.objects.remove(tmp, do_unlink=True)
    return mesh


# (name, primitive, primitive args, material or None, OBJ location, (OBJ axis, degrees) or None, scale)
# Transforms are in OBJ coordinates; the primitive's local axes are read as OBJ axes too (a cylinder's axis is y).
SHAPES = [
    ("Cube", "cube", {"size": 1.0}, "Wood",
     (0.25, 0.6, -0.5), None, (1.0, 1.0, 1.0)),
    ("Box", "cube", {"size": 1.0}, "Plastic",
     (3.0, 1.0, 1.0), ((0.0, 1.0, 0.0), 30.0), (2.0, 0.5, 1.0)),
    ("Sphere", "uv_sphere", {"segments": 32, "ring_count": 16, "radius": 0.5}, "Rubber",
     (-2.0, 1.0, 0.0), None, (1.0, 1.0, 1.0)),
    ("Ellipsoid", "uv_sphere", {"segments": 24, "ring_count": 12, "radius": 0.5}, "Steel",
     (-3.0, 2.0, 3.0), ((1.0, 0.0, 1.0), 25.0), (1.5, 0.6, 1.0)),
    ("Cylinder", "cylinder", {"vertices": 32, "radius": 0.4, "depth": 1.5, "end_fill_type": 'NGON'}, "Steel",
     (2.0, 0.85, -2.0), None, (1.0, 1.0, 1.0)),
    ("Cylinder.001", "cylinder", {"vertices": 32, "radius": 0.3, "depth": 1.0, "end_fill_type": 'NGON'}, "Ice",
     (0.0, 2.0, 3.0), ((0.3, 0.0, 1.0), 70.0), (1.0, 1.0, 1.0)),
    ("Cone", "cone", {"vertices": 32, "radius1": 0.5, "radius2": 0.0, "depth": 1.0, "end_fill_type": 'NGON'},
     "MyPaint", (-1.0, 0.6, -3.0), None, (1.0, 1.0, 1.0)),
    ("Torus", "torus", {"major_radius": 0.75, "minor_radius": 0.25, "major_segments": 48, "minor_segments": 12},
     "Wood", (4.0, 1.5, -3.0), ((0.0, 1.0, 0.0), 20.0), (1.0, 1.0, 1.0)),
    ("Anchor", "plane", {"size": 16.0}, "Concrete",
     (1.0, 0.0, -0.5), None, (1.0, 1.0, 1.0)),
    ("Anchor.001", "cube", {"size": 1.0}, "Concrete",
     (-4.0, 0.8, -4.0), ((0.0, 0.0, 1.0), 15.0), (3.0, 0.4, 2.0)),
    ("Anchor.2.001", "ico_sphere", {"subdivisions": 1, "radius": 0.4}, "Rubber",
     (5.0, 0.5, 3.0), None, (1.0, 1.0, 1.0)),
    ("AnchorPost", "cube", {"size": 1.0}, None,
     (-5.0, 1.5, 1.0), ((0.0, 1.0, 0.0), 10.0), (0.3, 3.0, 0.3)),
]


def build_and_export(path):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    col = bpy.context.scene.collection
    mats = {}
    objs = []
    for name, kind, args, mat, loc, rot, scale in SHAPES:
        mesh = make_mesh(kind, **args)
        obj = bpy.data.objects.new(name, mesh)
        assert obj.name == name, (name, obj.name)
        col.objects.link(obj)
        if mat is not None:
            if mat not in mats:
                mats[mat] = bpy.data.materials.new(mat)
                assert mats[mat].name == mat
            mesh.materials.append(mats[mat])
        r = Matrix.Identity(4)
        if rot is not None:
            r = Matrix.Rotation(math.radians(rot[1]), 4, Vector(rot[0]).normalized())
        m = Matrix.Translation(Vector(loc)) @ r @ Matrix.Diagonal(Vector((scale[0], scale[1], scale[2], 1.0)))
        obj.matrix_world = TO_BLENDER @ m @ TO_BLENDER.inverted()
        objs.append(obj)
    # The legacy exporter writes "o <object>_<mesh>" when the names differ.
    for i, obj in enumerate(objs):
        obj.data.name = "tmp_%d" % i
    for obj in objs:
        obj.data.name = obj.name
        assert obj.data.name == obj.name
    assert [o.name for o in bpy.context.scene.objects] == [s[0] for s in SHAPES]
    bpy.ops.export_scene.obj(filepath=path, use_selection=False, use_mesh_modifiers=True,
                             use_materials=True, axis_forward='-Z', axis_up='Y')


# ----------------------------------------------------------------------------
# 2. Read back (plain Python)
# ----------------------------------------------------------------------------

def read_obj(path):
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
                verts.append((float(parts[1]), float(parts[2]), float(parts[3])))
                cur["v"].append(len(verts) - 1)
            elif parts[0] == "usemtl":
                cur["mtl"].append(line[7:].strip())
            elif parts[0] == "f":
                idx = []
                for t in parts[1:]:
                    i = int(t.split("/")[0])
                    idx.append(i - 1 if i > 0 else len(verts) + i)
                cur["f"].append(idx)
    for o in objs:
        base = o["v"][0]
        assert o["v"] == list(range(base, base + len(o["v"])))
        assert {i for face in o["f"] for i in face} == set(o["v"]), o["name"]
        o["points"] = [verts[i] for i in o["v"]]
        o["faces"] = [[i - base for i in face] for face in o["f"]]
    return objs


# ----------------------------------------------------------------------------
# 3. Rules and geometry
# ----------------------------------------------------------------------------

def is_anchor(name):
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
    return "".join(out) == "Anchor"


def material_of(usemtl):
    if not usemtl:
        return "Default"
    name = usemtl[-1]
    for p in PRESETS:
        if p.lower() == name.lower():
            return p
    return "Default"


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def mean(points):
    n = len(points)
    return [math.fsum(p[i] for p in points) / n for i in range(3)]


def flat_normal(points):
    """Unit normal if all points are coplanar (to 1e-9 relative), else None."""
    p0 = points[0]
    p1 = max(points, key=lambda p: dot(sub(p, p0), sub(p, p0)))
    e1 = sub(p1, p0)
    p2 = max(points, key=lambda p: dot(cross(e1, sub(p, p0)), cross(e1, sub(p, p0))))
    n = cross(e1, sub(p2, p0))
    ln = math.sqrt(dot(n, n))
    size = math.sqrt(dot(e1, e1))
    n = (n[0] / ln, n[1] / ln, n[2] / ln)
    off = max(abs(dot(n, sub(p, p0))) for p in points)
    return n if off <= 1e-9 * size else None


def flat_area_centroid(points, n):
    """Area centroid of the 2-D convex hull of coplanar points."""
    k = max(range(3), key=lambda i: abs(n[i]))  # drop the dominant axis
    a, b = [i for i in range(3) if i != k]
    pts = sorted(set((p[a], p[b]) for p in points))

    def turn(o, p, q):
        return (p[0] - o[0]) * (q[1] - o[1]) - (p[1] - o[1]) * (q[0] - o[0])
    lower, upper = [], []
    for p in pts:
        while len(lower) >= 2 and turn(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(pts):
        while len(upper) >= 2 and turn(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    poly = lower[:-1] + upper[:-1]
    area2 = cx = cy = 0.0
    terms_a, terms_x, terms_y = [], [], []
    for i in range(len(poly)):
        x0, y0 = poly[i]
        x1, y1 = poly[(i + 1) % len(poly)]
        c = x0 * y1 - x1 * y0
        terms_a.append(c)
        terms_x.append((x0 + x1) * c)
        terms_y.append((y0 + y1) * c)
    area2 = math.fsum(terms_a)
    cx = math.fsum(terms_x) / (3.0 * area2)
    cy = math.fsum(terms_y) / (3.0 * area2)
    out = [0.0, 0.0, 0.0]
    out[a], out[b] = cx, cy
    p0 = points[0]
    # back onto the plane: n . (c - p0) = 0
    out[k] = p0[k] - (n[a] * (cx - p0[a]) + n[b] * (cy - p0[b])) / n[k]
    return out, abs(area2) / 2.0


def bmesh_hull_triangles(points):
    """Triangles (index triples into points) of Blender's convex hull of the points, and its vertices."""
    bm = bmesh.new()
    bverts = [bm.verts.new(p) for p in points]
    bm.verts.index_update()
    res = bmesh.ops.convex_hull(bm, input=bverts, use_existing_faces=False)
    faces = [g for g in res["geom"] if isinstance(g, bmesh.types.BMFace)]
    tris = []
    for f in faces:
        idx = [v.index for v in f.verts]
        assert all(0 <= i < len(points) for i in idx)
        for j in range(1, len(idx) - 1):  # fan, in case of polygons
            tris.append((idx[0], idx[j], idx[j + 1]))
    bm.free()
    return tris, sorted({i for t in tris for i in t})


def exact_hull(points, first, eps=1e-10):
    """Convex hull in double precision, incremental, outward-wound triangles.

    bmesh works in single precision with a tolerance, so its hull can leave points a little outside
    (up to about 1e-4 m for the rotated cylinder and the torus). The hull is therefore rebuilt here
    from the exported doubles. The points bmesh found (`first`) are inserted first; then every other
    point that is more than eps in front of a face is added: the faces that see it are removed and
    their horizon edges are joined to it.
    """
    def height(f, p):
        a, b, c = points[f[0]], points[f[1]], points[f[2]]
        n = cross(sub(b, a), sub(c, a))
        ln = math.sqrt(dot(n, n))
        return dot(n, sub(p, a)) / ln if ln > 0.0 else 0.0

    # Starting tetrahedron from extreme points.
    i0 = min(range(len(points)), key=lambda i: points[i])
    i1 = max(range(len(points)), key=lambda i: dot(sub(points[i], points[i0]), sub(points[i], points[i0])))
    e = sub(points[i1], points[i0])

    def line_dist2(i):
        c = cross(e, sub(points[i], points[i0]))
        return dot(c, c)
    i2 = max(range(len(points)), key=line_dist2)
    n = cross(e, sub(points[i2], points[i0]))
    i3 = max(range(len(points)), key=lambda i: abs(dot(n, sub(points[i], points[i0]))))
    tet = (i0, i1, i2, i3)
    centre = mean([points[i] for i in tet])
    faces = set()
    for f in ((i0, i1, i2), (i0, i1, i3), (i0, i2, i3), (i1, i2, i3)):
        a, b, c = (points[i] for i in f)
        nn = cross(sub(b, a), sub(c, a))
        faces.add(f if dot(nn, sub(centre, a)) < 0.0 else (f[0], f[2], f[1]))

    def closed(fs):
        edges = set()
        for i, j, k in fs:
            edges.update(((i, j), (j, k), (k, i)))
        return len(edges) == 3 * len(fs) and all((y, x) in edges for x, y in edges)

    order = list(dict.fromkeys(list(first) + list(range(len(points)))))
    for pi in order:
        if pi in tet:
            continue
        p = points[pi]
        visible = [f for f in faces if height(f, p) > eps]
        if not visible:
            continue
        vis_edges = set()
        for i, j, k in visible:
            vis_edges.update(((i, j), (j, k), (k, i)))
        horizon = [(x, y) for x, y in vis_edges if (y, x) not in vis_edges]
        for f in visible:
            faces.discard(f)
        for x, y in horizon:
            faces.add((x, y, pi))
        assert closed(faces), "hull is no longer closed"
    return sorted(faces)


def flip_sensitivity(points, tris, tol=1e-6):
    """Sum of the tetrahedra between neighbouring hull triangles that are coplanar to within tol.

    The exported coordinates have 6 decimals, so faces that were planar in Blender are planar only to about
    1e-6 m. A hull that treats them as planar (any tolerance above that noise) may pick the other diagonal.
    This sum bounds how much its volume can differ from the exact double-precision hull.
    """
    opposite = {}
    for i, j, k in tris:
        opposite[(i, j)] = k
        opposite[(j, k)] = i
        opposite[(k, i)] = j
    total = 0.0
    for (i, j), k in opposite.items():
        if i > j:
            continue
        m = opposite[(j, i)]
        a, b, c, d = points[i], points[j], points[k], points[m]
        n = cross(sub(b, a), sub(c, a))
        ln = math.sqrt(dot(n, n))
        if ln > 0.0 and abs(dot(n, sub(d, a))) / ln < tol:
            total += abs(dot(sub(b, a), cross(sub(c, a), sub(d, a)))) / 6.0
    return total


def solid_volume_centroid(points, tris, orient_to=None):
    """Divergence theorem over triangles: signed tetrahedra from a reference point.

    With orient_to (a point inside a convex hull) each triangle is first turned to face away from it,
    so the result does not depend on how bmesh wound them.
    """
    ref = orient_to if orient_to is not None else points[0]
    vols, cx, cy, cz = [], [], [], []
    for i, j, k in tris:
        a, b, c = points[i], points[j], points[k]
        if orient_to is not None:
            n = cross(sub(b, a), sub(c, a))
            fc = ((a[0] + b[0] + c[0]) / 3.0, (a[1] + b[1] + c[1]) / 3.0, (a[2] + b[2] + c[2]) / 3.0)
            if dot(n, sub(fc, ref)) < 0.0:
                b, c = c, b
        v = dot(sub(a, ref), cross(sub(b, ref), sub(c, ref))) / 6.0
        vols.append(v)
        cx.append(v * (ref[0] + a[0] + b[0] + c[0]) / 4.0)
        cy.append(v * (ref[1] + a[1] + b[1] + c[1]) / 4.0)
        cz.append(v * (ref[2] + a[2] + b[2] + c[2]) / 4.0)
    vol = math.fsum(vols)
    return vol, [math.fsum(cx) / vol, math.fsum(cy) / vol, math.fsum(cz) / vol]


def worst_outside(points, tris, inside):
    """Largest distance of any point in front of a hull face (0 for a perfectly convex hull)."""
    worst = 0.0
    for i, j, k in tris:
        a, b, c = points[i], points[j], points[k]
        n = cross(sub(b, a), sub(c, a))
        ln = math.sqrt(dot(n, n))
        if ln == 0.0:
            continue
        if dot(n, sub(inside, a)) > 0.0:
            n = (-n[0], -n[1], -n[2])
        worst = max(worst, max(dot(n, sub(p, a)) / ln for p in points))
    return worst


def mesh_triangles(faces):
    return [(f[0], f[j], f[j + 1]) for f in faces for j in range(1, len(f) - 1)]


def zero(x):
    return x + 0.0  # turns -0.0 into 0.0


# ----------------------------------------------------------------------------
# 4. Main
# ----------------------------------------------------------------------------

def main():
    d = out_dir()
    os.makedirs(d, exist_ok=True)
    obj_path = os.path.join(d, "shapes.obj")
    build_and_export(obj_path)
    objs = read_obj(obj_path)
    assert [o["name"] for o in objs] == [s[0] for s in SHAPES]
    spec = {s[0]: s for s in SHAPES}

    bodies = []
    print("%-13s %-6s %-8s %4s %22s %22s %10s %10s" % ("name", "anchor", "material", "nv", "hull_volume",
                                                       "mesh_volume", "outside", "hull_tris"))
    for o in objs:
        pts = o["points"]
        vm = mean(pts)
        n = flat_normal(pts)
        if n is not None:
            vol = 0.0
            cen, area = flat_area_centroid(pts, n)
            mesh_vol = 0.0
            outside = 0.0
            ntri = 0
        else:
            raw, raw_verts = bmesh_hull_triangles(pts)
            raw_vol, _ = solid_volume_centroid(pts, raw, orient_to=vm)
            raw_out = worst_outside(pts, raw, vm)
            tris = exact_hull(pts, raw_verts)
            ntri = len(tris)
            vol, cen = solid_volume_centroid(pts, tris)
            outside = worst_outside(pts, tris, vm)
            assert outside <= 1e-9, o["name"]
            n_edges = len({(min(t[a], t[(a + 1) % 3]), max(t[a], t[(a + 1) % 3])) for t in tris for a in range(3)})
            assert len({i for t in tris for i in t}) - n_edges + len(tris) == 2, o["name"]
            hull_verts = sorted({i for t in tris for i in t})
            flips = flip_sensitivity(pts, tris)
            print("  %s: bmesh hull: %d verts, %d tris, points up to %.3g m outside, volume %r;"
                  " double hull: %d verts, %d tris, volume %r (differ by %.3g);"
                  " near-coplanar edge flips could change it by up to %.3g"
                  % (o["name"], len(raw_verts), len(raw), raw_out, raw_vol, len(hull_verts), ntri, vol,
                     vol - raw_vol, flips))
            mesh_vol, _ = solid_volume_centroid(pts, mesh_triangles(o["faces"]))
        body = {
            "name": o["name"],
            "anchor": is_anchor(o["name"]),
            "material": material_of(o["mtl"]),
            "vertex_mean": [zero(x) for x in vm],
            "hull_volume": zero(vol),
            "hull_centroid": [zero(x) for x in cen],
        }
        bodies.append(body)
        print("%-13s %-6s %-8s %4d %22r %22r %10.3g %10d" % (o["name"], body["anchor"], body["material"], len(pts),
                                                           vol, abs(mesh_vol), outside, ntri))

    # Closed-form cross-checks (the exported coordinates carry 6 decimals, so agreement is to ~1e-6).
    by = {b["name"]: b for b in bodies}
    print("cross-checks against closed forms:")

    def cmp(label, got, want):
        print("  %-40s hull %r  closed form %r  diff %.3g" % (label, got, want, got - want))
        assert abs(got - want) < 1e-5, label

    cmp("Cube volume (1 m edges)", by["Cube"]["hull_volume"], 1.0)
    for i in range(3):
        cmp("Cube centroid[%d] = location" % i, by["Cube"]["hull_centroid"][i], spec["Cube"][4][i])
    cmp("Box volume 2 x 0.5 x 1", by["Box"]["hull_volume"], 1.0)

    def prism(r, h, n=32):
        return 0.5 * n * r * r * math.sin(2.0 * math.pi / n) * h
    cmp("Cylinder volume (32-gon prism r .4 h 1.5)", by["Cylinder"]["hull_volume"], prism(0.4, 1.5))
    print("  (a round cylinder pi r^2 h would be %r)" % (math.pi * 0.4 * 0.4 * 1.5))
    for i in range(3):
        cmp("Cylinder centroid[%d] = location" % i, by["Cylinder"]["hull_centroid"][i], spec["Cylinder"][4][i])
    cmp("Cylinder.001 volume (rotated, r .3 h 1)", by["Cylinder.001"]["hull_volume"], prism(0.3, 1.0))
    cmp("Cone volume (32-gon pyramid r .5 h 1)", by["Cone"]["hull_volume"], prism(0.5, 1.0) / 3.0)
    cmp("Cone centroid y = base + h/4", by["Cone"]["hull_centroid"][1], spec["Cone"][4][1] - 0.5 + 0.25)
    cmp("Anchor.001 volume 3 x 0.4 x 2", by["Anchor.001"]["hull_volume"], 2.4)
    cmp("AnchorPost volume 0.3 x 3 x 0.3", by["AnchorPost"]["hull_volume"], 0.27)
    cmp("Ellipsoid centroid x = location", by["Ellipsoid"]["hull_centroid"][0], spec["Ellipsoid"][4][0])

    json_path = os.path.join(d, "shapes_expected.json")
    with open(json_path, "w") as f:
        f.write('{"bodies": [\n')
        f.write(",\n".join("  " + json.dumps(b) for b in bodies))
        f.write("\n]}\n")
    with open(json_path) as f:
        assert json.load(f)["bodies"] == bodies
    print("wrote", obj_path, "and", json_path, "with", len(bodies), "bodies")


main()
