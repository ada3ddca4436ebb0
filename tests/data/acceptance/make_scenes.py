"""Acceptance scenes for issue 4, made the way a reviewer makes them: in Blender, by hand-style bpy calls.

Run headless with Blender 3.4 (writes next to this script unless an output folder follows "--"):

    blender -b --factory-startup --python-exit-code 1 --python tests/data/acceptance/make_scenes.py [-- OUTDIR]

Objects are placed in Blender's own frame (Z up, metres), with Blender's primitive operators, and exported with
Blender's own exporters at their default options, as a user would:
- OBJ: bpy.ops.export_scene.obj(filepath=...) (the 3.4 legacy exporter; forward -Z, up Y, whole scene);
- FBX: bpy.ops.export_scene.fbx, once at its defaults (Y up) and once with axis_up='Z', axis_forward='Y';
- glTF: bpy.ops.export_scene.gltf (GLB, +Y up).
Masses, friction and restitution that no material preset gives come from JSON .rlscene files written at the end,
which take the bodies out of the exported OBJ files ("shape": {"obj": ..., "object": ...}) and override them.

The legacy OBJ exporter writes "o <object>_<mesh>" when the two names differ, so every object here gets a mesh of
the same name (as Blender's own primitives do), except in tower20_legacy_names.obj, which keeps the mesh names a
user gets after renaming only the object: "o Anchor_Plane", which the anchor rule makes dynamic (tst_acceptance's
blenderRenamedFloor).
"""

import json
import math
import os
import sys

import bpy

OUT = os.path.dirname(os.path.abspath(__file__))
if "--" in sys.argv and sys.argv.index("--") + 1 < len(sys.argv):
    OUT = os.path.abspath(sys.argv[sys.argv.index("--") + 1])
os.makedirs(OUT, exist_ok=True)


def reset():
    bpy.ops.wm.read_factory_settings(use_empty=True)


def material(obj, name):
    mat = bpy.data.materials.get(name) or bpy.data.materials.new(name)
    obj.data.materials.clear()
    obj.data.materials.append(mat)


def named(name, rename_mesh=True, mat=None):
    """Name the active object (Blender appends .001, ... on clashes) and, by default, its mesh the same."""
    obj = bpy.context.active_object
    obj.name = name
    if rename_mesh:
        obj.data.name = obj.name
    if mat:
        material(obj, mat)
    return obj


def cube(name, size=1.0, location=(0, 0, 0), scale=(1, 1, 1), rotation=(0, 0, 0), mat=None, rename_mesh=True):
    bpy.ops.mesh.primitive_cube_add(size=size, location=location, rotation=rotation, scale=scale)
    obj = named(name, rename_mesh, mat)
    bpy.ops.object.transform_apply(location=False, rotation=False, scale=True)
    return obj


def floor_plane(size=20.0, mat=None, rename_mesh=True):
    bpy.ops.mesh.primitive_plane_add(size=size)
    return named("Anchor", rename_mesh, mat)


def floor_box(mat=None):
    """A 40 x 40 x 1 m box whose top face is z = 0."""
    return cube("Anchor", location=(0, 0, -0.5), scale=(40, 40, 1), mat=mat)


def export_obj(name, **kw):
    path = os.path.join(OUT, name)
    bpy.ops.export_scene.obj(filepath=path, **kw)
    print("exported", path, len(bpy.context.scene.objects), "objects")


def tower(n, box_floor):
    reset()
    if box_floor:
        floor_box()
    else:
        floor_plane()
    for i in range(n):
        cube("Cube", location=(0, 0, 0.5 + i))


def write_json(name, doc):
    path = os.path.join(OUT, name)
    with open(path, "w") as f:
        json.dump(doc, f, indent=2)
        f.write("\n")
    print("wrote", path)


def obj_body(file, obj, **extra):
    body = {"name": obj, "shape": {"obj": file, "object": obj}}
    if obj.split(".")[0] == "Anchor":
        body["anchor"] = True
    body.update(extra)
    return body


def scene(bodies, **world):
    doc = {"format": "rigidlab-scene", "version": 1}
    if world:
        doc["world"] = world
    doc["bodies"] = bodies
    return doc


# Towers: 20 unit cubes on a floor plane, 40 on a floor box.
tower(20, box_floor=False)
export_obj("tower20.obj")
# The same tower through FBX (Y up, the default; and Z up) and glTF.
bpy.ops.export_scene.fbx(filepath=os.path.join(OUT, "tower20.fbx"))
bpy.ops.export_scene.fbx(filepath=os.path.join(OUT, "tower20_zup.fbx"), axis_up='Z', axis_forward='Y')
bpy.ops.export_scene.gltf(filepath=os.path.join(OUT, "tower20.glb"))
tower(40, box_floor=True)
export_obj("tower40.obj")

# The same tower through Blender 3.4's new exporter (File > Export > Wavefront (.obj) in the menu), at its defaults;
# it names objects without the mesh name, so the floor keeps the name a user gave it.
tower(20, box_floor=False)
bpy.ops.wm.obj_export(filepath=os.path.join(OUT, "tower20_new_exporter.obj"))

# Every other cube turned 45 degrees about the vertical, on a floor plane.
reset()
floor_plane()
for i in range(20):
    cube("Cube", location=(0, 0, 0.5 + i), rotation=(0, 0, math.radians(45.0 * (i % 2))))
export_obj("tower20_rot45.obj")

# 20 of Blender's default cubes (2 m, primitive_cube_add() with no size) on a 60 m floor plane.
reset()
floor_plane(size=60)
for i in range(20):
    cube("Cube", size=2.0, location=(0, 0, 1 + 2 * i))
export_obj("tower20_2m.obj")

# The tower a user gets after renaming only the plane object to Anchor: the exporter writes "o Anchor_Plane".
reset()
floor_plane(rename_mesh=False)
for i in range(20):
    cube("Cube", location=(0, 0, 0.5 + i), rename_mesh=False)
export_obj("tower20_legacy_names.obj")

# The 20-cube tower at other sizes and as users build it (2026-12-02): 10 cm and 5 cm cubes on a floor plane five
# tower widths across; unit cubes 1 cm apart, which fall and settle; unit cubes each turned by a random angle about
# the vertical and shifted by up to 5 cm; and unit cubes 500 m from the origin, on a plane there.
for size, name in ((0.1, "tower20_10cm.obj"), (0.05, "tower20_5cm.obj")):
    reset()
    floor_plane(size=100 * size)
    for i in range(20):
        cube("Cube", size=size, location=(0, 0, size * (0.5 + i)))
    export_obj(name)
reset()
floor_plane()
for i in range(20):
    cube("Cube", location=(0, 0, 0.5 + 1.01 * i))
export_obj("tower20_gaps.obj")
reset()
floor_plane()
jitter = __import__("random").Random(3)
for i in range(20):
    cube("Cube", location=(jitter.uniform(-0.05, 0.05), jitter.uniform(-0.05, 0.05), 0.5 + i),
         rotation=(0, 0, jitter.uniform(0, math.pi)))
export_obj("tower20_jitter.obj")
reset()
bpy.ops.mesh.primitive_plane_add(size=20, location=(500, 500, 0))
named("Anchor")
for i in range(20):
    cube("Cube", location=(500, 500, 0.5 + i))
export_obj("tower20_far.obj")

# Pyramid, base 20 (210 unit cubes), each row shifted by half a cube.
reset()
floor_plane(size=40)
for row in range(20):
    n = 20 - row
    for k in range(n):
        cube("Cube", location=(-0.5 * (n - 1) + k, 0, 0.5 + row))
export_obj("pyramid20.obj")

# 20 x 20 x 1 m slab on two unit cubes 16 m apart.
reset()
floor_plane(size=40)
cube("Left", location=(-8, 0, 0.5))
cube("Right", location=(8, 0, 0.5))
cube("Slab", location=(0, 0, 1.5), scale=(20, 20, 1))
export_obj("slab.obj")

# 30-layer Jenga tower: Jenga blocks scaled 10x (0.75 x 0.25 x 0.15 m), three per layer, layers crossed, Wood.
reset()
floor_box(mat="Wood")
for layer in range(30):
    z = 0.075 + 0.15 * layer
    for k in (-1, 0, 1):
        if layer % 2 == 0:
            cube("Block", location=(0, 0.25 * k, z), scale=(0.75, 0.25, 0.15), mat="Wood")
        else:
            cube("Block", location=(0.25 * k, 0, z), scale=(0.25, 0.75, 0.15), mat="Wood")
export_obj("jenga30.obj")

# Block on a 30 degree slope: a 20 x 4 x 1 m ramp tilted about Blender's y axis (lower at +x), its top face through
# the origin, and a 0.5 m cube resting on it. Concrete on Concrete: mu 0.7 straight from the OBJ.
reset()
theta = math.radians(30.0)
normal = (math.sin(theta), 0.0, math.cos(theta))  # ramp top normal after rotating about +y by theta
cube("Anchor", location=tuple(-0.5 * c for c in normal), scale=(20, 4, 1), rotation=(0, theta, 0), mat="Concrete")
cube("Block", size=0.5, location=tuple(0.25 * c for c in normal), rotation=(0, theta, 0), mat="Concrete")
export_obj("slope30.obj")

# Drop: a UV sphere (r 0.1 m) whose bottom is 5 m above a floor plane.
reset()
floor_plane()
bpy.ops.mesh.primitive_uv_sphere_add(radius=0.1, location=(0, 0, 5.1))
named("Ball")
export_obj("drop.obj")

# Drop of a 0.2 m cube, face down, its bottom 5 m above a floor plane.
reset()
floor_plane()
cube("Box", size=0.2, location=(0, 0, 5.1))
export_obj("drop_cube.obj")

# Two 0.5 m cubes, Light under Heavy (masses come from mass_ratio.rlscene).
reset()
floor_plane()
cube("Light", size=0.5, location=(0, 0, 0.25))
cube("Heavy", size=0.5, location=(0, 0, 0.75))
export_obj("mass.obj")

# Mixed shapes on a floor plane: cubes (and a 3-stack), UV spheres, cylinders, cones, an icosphere, a torus and
# Suzanne (both concave: simulated as their hulls), each 5 cm above what it rests on.
reset()
floor_plane(size=40, mat="Concrete")
mats = ["Wood", "Steel", "Rubber", "Plastic", "Default", "Ice"]


def drop_on_floor(obj, gap=0.05):
    bpy.context.view_layer.update()
    low = min((obj.matrix_world @ v.co).z for v in obj.data.vertices)
    obj.location.z += gap - low


for i in range(3):
    cube("Cube", location=(-6 + 2.5 * i, -3, 0), mat=mats[i])
    drop_on_floor(bpy.context.active_object)
for i in range(3):  # a stack of three 0.6 m cubes, 5 cm apart
    cube("Stacked", size=0.6, location=(3, -3, 0.35 + 0.65 * i), mat="Wood")
for i in range(3):
    bpy.ops.mesh.primitive_uv_sphere_add(radius=0.4, location=(-6 + 2.5 * i, 0, 0))
    named("Sphere", mat=mats[i + 1])
    drop_on_floor(bpy.context.active_object)
for i in range(3):
    bpy.ops.mesh.primitive_cylinder_add(radius=0.4, depth=1.0, location=(-6 + 2.5 * i, 3, 0))
    named("Cylinder", mat=mats[i + 2])
    drop_on_floor(bpy.context.active_object)
for i in range(2):
    bpy.ops.mesh.primitive_cone_add(radius1=0.5, depth=1.0, location=(1.5 + 2.5 * i, 3, 0))
    named("Cone", mat=mats[i])
    drop_on_floor(bpy.context.active_object)
bpy.ops.mesh.primitive_ico_sphere_add(radius=0.5, location=(1.5, 0, 0))
named("Icosphere", mat="Plastic")
drop_on_floor(bpy.context.active_object)
bpy.ops.mesh.primitive_torus_add(major_radius=0.6, minor_radius=0.2, location=(4, 0, 0))
named("Torus", mat="Wood")
drop_on_floor(bpy.context.active_object)
bpy.ops.mesh.primitive_monkey_add(size=1.0, location=(6.5, 0, 0), rotation=(math.radians(-90), 0, 0))
named("Suzanne", mat="Rubber")  # lying on its face
drop_on_floor(bpy.context.active_object)
export_obj("mixed_shapes.obj")

# Card house: 40 cards of 2 mm x 0.3 m x 0.4 m, five levels of A-frames (two cards leaning 18 degrees from the
# vertical, tops touching) with flat cards bridging neighbouring apexes (14, 11, 8, 5 and 2 cards a level), as a user
# stacks them: every card touching what carries it, none inside another. Friction 0.7 comes from card_house.rlscene.
# The same house with the cards leaning 20 and 24 degrees (card_house_20deg.obj, card_house_24deg.obj) for the
# JSON scenes of lower friction below.
def card_house(name, degrees):
    reset()
    floor_box()
    half, thick, width, tilt = 0.2, 0.001, 0.15, math.radians(degrees)
    base = 0.0
    for level in range(5):
        frames = 5 - level
        x0 = -0.5 * (frames - 1) * 2 * half
        for f in range(frames):
            apex = x0 + f * 2 * half
            dx = half * math.sin(tilt) + thick / math.cos(tilt)
            z = base + half * math.cos(tilt) + thick * math.sin(tilt)
            for side in (-1, 1):  # the left card's top leans to +x: a turn of +tilt about Blender's y
                cube("Card", location=(apex + side * dx, 0, z), scale=(2 * thick, 2 * width, 2 * half),
                     rotation=(0, -side * tilt, 0))
        base += 2 * half * math.cos(tilt) + 2 * thick * math.sin(tilt)
        for f in range(frames - 1):
            cube("Card", location=(x0 + (f + 0.5) * 2 * half, 0, base + thick), scale=(2 * half, 2 * width, 2 * thick))
        base += 2 * thick
    export_obj(name)


card_house("card_house.obj", 18.0)
card_house("card_house_20deg.obj", 20.0)
card_house("card_house_24deg.obj", 24.0)

# 1,000 random boxes dropped on a floor box: a 10 x 10 x 10 grid 1.6 m apart, the lowest layer 1 m up, each box
# 0.3-0.8 m along each side, turned at random and shifted by up to 5 cm (no two overlap at the start).
reset()
floor_box()
rng = __import__("random").Random(7)
for i in range(1000):
    gx, gy, layer = i % 10, (i // 10) % 10, i // 100
    cube("Box", location=((gx - 4.5) * 1.6 + rng.uniform(-0.05, 0.05), (gy - 4.5) * 1.6 + rng.uniform(-0.05, 0.05),
                          1.0 + 1.6 * layer),
         scale=(rng.uniform(0.3, 0.8), rng.uniform(0.3, 0.8), rng.uniform(0.3, 0.8)),
         rotation=(rng.uniform(0, 2 * math.pi), rng.uniform(0, 2 * math.pi), rng.uniform(0, 2 * math.pi)))
export_obj("boxes1000.obj")

# 24 rods dropped tilted onto a floor box, 1.5 m apart (2026-12-07: thin turning bodies gained energy, see
# tst_motion's turningRodsGainNoEnergy): broomsticks (16-sided, 1.2 m x 3 cm), laths (1 m x 4 x 1.5 cm), pencils
# (hexagonal, 18 cm x 7 mm) and knitting needles (8-sided, 35 cm x 4 mm), their lowest point 0.3-2 m up, turned at
# random, of Wood, Steel, Rubber and Plastic.
reset()
floor_box(mat="Concrete")
rng = __import__("random").Random(11)
rod_mats = ["Wood", "Steel", "Rubber", "Plastic"]
for i in range(24):
    kind = i % 4
    location = ((i % 6 - 2.5) * 1.5, (i // 6 - 1.5) * 1.5, 0)
    rotation = (rng.uniform(0, 2 * math.pi), rng.uniform(0, 2 * math.pi), rng.uniform(0, 2 * math.pi))
    if kind == 1:
        cube("Lath", location=location, scale=(1.0, 0.04, 0.015), rotation=rotation, mat=rod_mats[i // 4 % 4])
    else:
        vertices, radius, depth, name = [(16, 0.015, 1.2, "Broomstick"), None, (6, 0.0035, 0.18, "Pencil"),
                                         (8, 0.002, 0.35, "Needle")][kind]
        bpy.ops.mesh.primitive_cylinder_add(vertices=vertices, radius=radius, depth=depth, location=location,
                                            rotation=rotation)
        named(name, mat=rod_mats[i // 4 % 4])
    drop_on_floor(bpy.context.active_object, gap=rng.uniform(0.3, 2.0))
export_obj("rods.obj")

# JSON scenes over the exported OBJ files.
write_json("slope30_mu07.rlscene", scene([
    obj_body("slope30.obj", "Anchor", friction=0.7, restitution=0.0),
    obj_body("slope30.obj", "Block", friction=0.7, restitution=0.0)]))
write_json("slope30_mu03.rlscene", scene([
    obj_body("slope30.obj", "Anchor", friction=0.3, restitution=0.0),
    obj_body("slope30.obj", "Block", friction=0.3, restitution=0.0)]))
write_json("drop_e05.rlscene", scene([
    obj_body("drop.obj", "Anchor", restitution=0.5),
    obj_body("drop.obj", "Ball", restitution=0.5)]))
write_json("drop_cube_e05.rlscene", scene([
    obj_body("drop_cube.obj", "Anchor", restitution=0.5),
    obj_body("drop_cube.obj", "Box", restitution=0.5)]))
write_json("mass_ratio.rlscene", scene([
    obj_body("drop.obj", "Anchor"),
    obj_body("mass.obj", "Light", mass=1.0),
    obj_body("mass.obj", "Heavy", mass=1000.0)]))

# Pure JSON: a 1:10:100:1000 ladder of 0.5 m boxes (lightest at the bottom), and the 1:1000 pair as boxes.
floor = {"name": "Floor", "anchor": True, "shape": {"box": [200, 0.5, 200]}, "position": [0, -0.5, 0]}
write_json("mass_ladder.rlscene", scene([floor] + [
    {"name": "M%d" % m, "shape": {"box": [0.25, 0.25, 0.25]}, "position": [0, 0.25 + 0.5 * i, 0], "mass": m}
    for i, m in enumerate([1.0, 10.0, 100.0, 1000.0])]))
# Heavy and light in other orders: 1,000 kg on two 1 kg boxes, and a 1 kg box between two 1,000 kg ones.
write_json("mass_heavy_on_two_light.rlscene", scene([floor] + [
    {"name": n, "shape": {"box": [0.5, 0.5, 0.5]}, "position": [0, 0.5 + i, 0], "mass": m}
    for i, (n, m) in enumerate([("Light1", 1.0), ("Light2", 1.0), ("Heavy", 1000.0)])]))
write_json("mass_sandwich.rlscene", scene([floor] + [
    {"name": n, "shape": {"box": [0.5, 0.5, 0.5]}, "position": [0, 0.5 + i, 0], "mass": m}
    for i, (n, m) in enumerate([("Heavy1", 1000.0), ("Light", 1.0), ("Heavy2", 1000.0)])]))
write_json("mass_pair_boxes.rlscene", scene([floor,
    {"name": "Light", "shape": {"box": [0.5, 0.5, 0.5]}, "position": [0, 0.5, 0], "mass": 1.0},
    {"name": "Heavy", "shape": {"box": [0.5, 0.5, 0.5]}, "position": [0, 1.5, 0], "mass": 1000.0}]))

# The e = 0.5 drop from lower heights, as plain JSON: a 0.1 m sphere from 1 m and from 1.25 m, a 0.2 m cube from 2 m.
# (Until 2026-12-05 a ball stopped a few millimetres short of the floor at the end of a step bounced from there at
# the floor's speed: second or third apexes 6-15 % high.)
for name, shape, h0 in (("drop_sphere_1m_e05.rlscene", {"sphere": 0.1}, 1.0),
                        ("drop_sphere_1.25m_e05.rlscene", {"sphere": 0.1}, 1.25),
                        ("drop_cube_2m_e05.rlscene", {"box": [0.1, 0.1, 0.1]}, 2.0)):
    write_json(name, scene([dict(floor, restitution=0.5),
                            {"name": "Ball", "shape": shape, "position": [0, h0 + 0.1, 0], "restitution": 0.5}]))

# A 20-cube tower of 2 cm cubes on the floor box, as plain JSON (it fell at the default settings until 2026-12-05).
write_json("tower20_2cm.rlscene", scene([floor] + [
    {"name": "Cube%d" % i, "shape": {"box": [0.01, 0.01, 0.01]}, "position": [0, 0.01 + 0.02 * i, 0]}
    for i in range(20)]))

# The 1:1000 pair with the "world" block of DESIGN.md section 6's example (substeps 4), as a reviewer copying that
# example writes it.
write_json("mass_pair_design_world.rlscene", dict(scene([floor,
    {"name": "Light", "shape": {"box": [0.25, 0.25, 0.25]}, "position": [0, 0.25, 0], "mass": 1.0},
    {"name": "Heavy", "shape": {"box": [0.25, 0.25, 0.25]}, "position": [0, 0.75, 0], "mass": 1000.0}],
    gravity=[0, -9.81, 0], fps=60, substeps=4, integrator="symplectic-euler", effects="auto")))

# Torque-free T-handle (no gravity, no anchor): a 0.8 m bar on a 0.6 m stem as one hull. Principal moments about
# its centre of mass (rigidlab-cli info --json): x 1.140, y 1.187, z 2.269 kg m^2, so y is the intermediate axis.
# Spun at 10 rad/s about y (flips), about z and about x (stable), each with a 0.01 rad/s nudge on the other axes.
t_handle = [[x, y, z] for x in (-0.4, 0.4) for y in (0.3, 0.4) for z in (-0.05, 0.05)] + \
    [[x, y, z] for x in (-0.05, 0.05) for y in (-0.3, 0.3) for z in (-0.05, 0.05)]
for tag, w in (("intermediate", [0.01, 10.0, 0.01]), ("max", [0.01, 0.01, 10.0]), ("min", [10.0, 0.01, 0.01])):
    write_json("t_handle_%s.rlscene" % tag, scene([
        {"name": "THandle", "shape": {"hull": t_handle}, "position": [0, 2, 0], "angular_velocity": w}],
        gravity=[0, 0, 0]))

# Projectiles: a lob in free flight (exact parabola until it lands at about t = 1.7 s), a 0.1 m steel cube at
# 300 m/s into a 5 cm anchor wall, and a 1,000 kg ball at 10 m/s into a 1 kg box resting on the floor.
write_json("projectile_lob.rlscene", scene([floor,
    {"name": "Shot", "shape": {"sphere": 0.1}, "position": [0, 1.1, 0], "velocity": [4, 8, 0]}]))
write_json("projectile_wall.rlscene", scene([floor,
    {"name": "Wall", "anchor": True, "shape": {"box": [0.025, 2, 2]}, "position": [5, 2, 0]},
    {"name": "Bullet", "shape": {"box": [0.05, 0.05, 0.05]}, "material": "Steel", "position": [0, 1, 0],
     "velocity": [300, 0, 0]}]))
write_json("projectile_heavy.rlscene", scene([floor,
    {"name": "Box", "shape": {"box": [0.1, 0.1, 0.1]}, "position": [3, 0.1, 0], "mass": 1.0},
    {"name": "Ball", "shape": {"sphere": 0.5}, "position": [0, 0.5, 0], "velocity": [10, 0, 0], "mass": 1000.0}]))

# The card house with card stock's friction, mu 0.7, on the floor too (no bounce); the steeper houses with less:
# mu 0.4 at 20 degrees and 0.5 at 24 (about 1.1 tan(tilt), what statics asks of the loaded frames and the flat
# cards' ends on the apexes).
for file, obj, mu in (("card_house.rlscene", "card_house.obj", 0.7),
                      ("card_house_20deg_mu04.rlscene", "card_house_20deg.obj", 0.4),
                      ("card_house_24deg_mu05.rlscene", "card_house_24deg.obj", 0.5)):
    write_json(file, {
        "format": "rigidlab-scene", "version": 1,
        "materials": {"Card": {"density": 700.0, "friction": mu, "restitution": 0.0}},
        "bodies": [obj_body(obj, "Anchor", material="Card")] + [
            obj_body(obj, "Card" if i == 0 else "Card.%03d" % i, material="Card") for i in range(40)]})

# Two identical 1 m boxes in the same place, no gravity: they part at no more than the solver's 3 m/s.
write_json("coincident_boxes.rlscene", scene([
    {"name": n, "shape": {"box": [0.5, 0.5, 0.5]}, "position": [0, 0, 0]} for n in ("A", "B")],
    gravity=[0, 0, 0]))
