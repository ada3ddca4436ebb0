# Builds the binary-format import fixtures with Blender's own exporters, so the tests read what users will import.
# Run from the repository root: blender -b --factory-startup --python tests/data/import/make_fixtures.py
import math
import os
import sys

import bpy

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "blender")
os.makedirs(OUT, exist_ok=True)


def clear_scene():
    bpy.ops.object.select_all(action="SELECT")
    bpy.ops.object.delete()
    for mesh in list(bpy.data.meshes):
        bpy.data.meshes.remove(mesh)


def material(name):
    mat = bpy.data.materials.get(name) or bpy.data.materials.new(name)
    return mat


def finish(obj, name, mat_name):
    obj.name = name
    # The legacy OBJ exporter writes "o Object_Mesh" when the names differ; keep them equal so names match.
    obj.data.name = name
    obj.data.materials.clear()
    obj.data.materials.append(material(mat_name))
    return obj


def build_scene():
    clear_scene()
    # Blender is Z-up; every exporter below converts to Y-up.
    bpy.ops.mesh.primitive_cube_add(size=2.0, location=(0.0, 0.0, 1.0))
    finish(bpy.context.active_object, "Cube", "Steel")

    bpy.ops.mesh.primitive_cube_add(size=2.0, location=(3.0, -1.0, 2.5))
    box = finish(bpy.context.active_object, "Box.001", "wood")
    box.rotation_euler = (math.radians(30.0), math.radians(10.0), math.radians(45.0))
    box.scale = (0.5, 1.0, 2.0)

    # An octagonal prism: its caps are N-gons, which the importers must triangulate.
    bpy.ops.mesh.primitive_cylinder_add(vertices=8, radius=0.75, depth=1.5, location=(-2.5, 1.0, 1.0),
                                        end_fill_type="NGON")
    prism = finish(bpy.context.active_object, "Prism", "MyPaint")
    prism.rotation_euler = (0.0, math.radians(20.0), 0.0)

    bpy.ops.mesh.primitive_plane_add(size=10.0, location=(0.0, 0.0, 0.0))
    finish(bpy.context.active_object, "Anchor", "Concrete")

    bpy.context.view_layer.update()


def select_only(obj):
    bpy.ops.object.select_all(action="DESELECT")
    obj.select_set(True)
    bpy.context.view_layer.objects.active = obj


def export_all():
    bpy.ops.object.select_all(action="SELECT")
    bpy.ops.export_scene.obj(filepath=os.path.join(OUT, "scene.obj"), use_selection=False,
                             axis_forward="-Z", axis_up="Y", use_triangles=False, use_materials=True)
    bpy.ops.export_scene.gltf(filepath=os.path.join(OUT, "scene.glb"), export_format="GLB", export_yup=True,
                              export_apply=True)
    bpy.ops.export_scene.gltf(filepath=os.path.join(OUT, "scene.gltf"), export_format="GLTF_SEPARATE",
                              export_yup=True, export_apply=True)
    bpy.ops.export_scene.fbx(filepath=os.path.join(OUT, "scene.fbx"), use_selection=False, object_types={"MESH"},
                             axis_forward="-Z", axis_up="Y", apply_unit_scale=True, mesh_smooth_type="OFF")
    # The same scene declared Z-up and in metres (no unit scale applied): the importer must convert it back.
    bpy.ops.export_scene.fbx(filepath=os.path.join(OUT, "scene_zup.fbx"), use_selection=False, object_types={"MESH"},
                             axis_forward="Y", axis_up="Z", apply_unit_scale=False, mesh_smooth_type="OFF")
    # COLLADA as Blender writes it by default: Z-up in the file, which assimp turns to Y-up itself.
    bpy.ops.wm.collada_export(filepath=os.path.join(OUT, "scene.dae"), apply_modifiers=True, selected=False)
    # PLY and STL hold one unnamed mesh per file, so each object gets its own file named after it.
    for obj in list(bpy.context.scene.objects):
        select_only(obj)
        bpy.ops.export_mesh.ply(filepath=os.path.join(OUT, obj.name + ".ply"), use_selection=True,
                                axis_forward="-Z", axis_up="Y", use_normals=True, use_uv_coords=False,
                                use_colors=False)
        bpy.ops.export_mesh.stl(filepath=os.path.join(OUT, obj.name + ".stl"), use_selection=True,
                                axis_forward="-Z", axis_up="Y", ascii=(obj.name == "Cube"))


build_scene()
export_all()
print("fixtures written to", OUT)
sys.exit(0)
