"""Renders a Penumbra scene file made of Lambertian quads (scenes/cornell-box.json)
with Blender Cycles on the CPU, for side-by-side error and time comparisons:

  blender -b --factory-startup -P scripts/cycles_render.py -- \
      --scene scenes/cornell-box.json --size 128 --spp 256 --seed 1 --out cycles.exr

The settings match Penumbra's path tracer: a 1-pixel box filter (Penumbra
jitters uniformly in the pixel), no clamping, no denoising, no adaptive
sampling, `--max-depth` bounces of every kind, emitters that emit from their
front face only (the quad's winding gives its normal, as in Penumbra). It
writes a linear RGBA EXR and prints one line, `cycles: render_s=S spp=N
pattern=P`: the wall time of the render alone (scene setup excluded) and
Cycles' sampling pattern (its default; Blender 3.4: progressive
multi-jittered).
"""

import argparse
import json
import math
import sys
import time

import bpy


def parse_args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    p = argparse.ArgumentParser(prog="cycles_render.py")
    p.add_argument("--scene", required=True)
    p.add_argument("--size", type=int, default=128)
    p.add_argument("--spp", type=int, default=256)
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--max-depth", type=int, default=64)
    p.add_argument("--threads", type=int, default=0, help="0: every core")
    p.add_argument("--out", required=True)
    return p.parse_args(argv)


def to_blender(v, scale):
    # Penumbra scenes are +y up; Blender is +z up. A rotation (not a mirror)
    # of 90 degrees about x keeps the quads' winding, hence their normals.
    return (v[0] * scale, -v[2] * scale, v[1] * scale)


def make_material(name, spec):
    if spec.get("model", "lambert") != "lambert":
        sys.exit(f"cycles_render.py: material '{name}': only lambert materials are supported")
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    nodes, links = mat.node_tree.nodes, mat.node_tree.links
    nodes.clear()
    out = nodes.new("ShaderNodeOutputMaterial")
    diffuse = nodes.new("ShaderNodeBsdfDiffuse")
    albedo = spec.get("albedo", [0.8, 0.8, 0.8])
    diffuse.inputs["Color"].default_value = (*albedo, 1.0)
    diffuse.inputs["Roughness"].default_value = 0.0  # Lambert, not Oren-Nayar
    emission = spec.get("emission")
    if not emission:
        links.new(diffuse.outputs["BSDF"], out.inputs["Surface"])
        return mat
    emit = nodes.new("ShaderNodeEmission")
    emit.inputs["Color"].default_value = (*emission, 1.0)
    emit.inputs["Strength"].default_value = 1.0
    front = nodes.new("ShaderNodeAddShader")
    links.new(diffuse.outputs["BSDF"], front.inputs[0])
    links.new(emit.outputs["Emission"], front.inputs[1])
    # Backfaces reflect but do not emit.
    geometry = nodes.new("ShaderNodeNewGeometry")
    mix = nodes.new("ShaderNodeMixShader")
    links.new(geometry.outputs["Backfacing"], mix.inputs["Fac"])
    links.new(front.outputs["Shader"], mix.inputs[1])
    links.new(diffuse.outputs["BSDF"], mix.inputs[2])
    links.new(mix.outputs["Shader"], out.inputs["Surface"])
    return mat


def build_scene(doc):
    scale = doc.get("unitScale", 1.0)
    materials = {name: make_material(name, spec) for name, spec in doc["materials"].items()}
    for mesh_spec in doc["meshes"]:
        if "quads" not in mesh_spec:
            sys.exit(f"cycles_render.py: mesh '{mesh_spec.get('name')}': only quads are supported")
        verts, faces = [], []
        for quad in mesh_spec["quads"]:
            faces.append(tuple(range(len(verts), len(verts) + 4)))
            verts.extend(to_blender(v, scale) for v in quad)
        mesh = bpy.data.meshes.new(mesh_spec["name"])
        mesh.from_pydata(verts, [], faces)
        mesh.materials.append(materials[mesh_spec["material"]])
        obj = bpy.data.objects.new(mesh_spec["name"], mesh)
        bpy.context.scene.collection.objects.link(obj)

    c = doc["camera"]
    if "orthographicHeight" in c:
        sys.exit("cycles_render: the scene's camera is orthographic, which this exporter "
                 "does not write; give the scene a perspective camera")
    cam_data = bpy.data.cameras.new("camera")
    cam_data.sensor_fit = "VERTICAL"
    cam_data.angle_y = math.radians(c["verticalFovDegrees"])
    cam = bpy.data.objects.new("camera", cam_data)
    cam.location = to_blender(c["position"], scale)
    # Blender cameras look along their local -z with +y up.
    from mathutils import Matrix, Vector

    forward = Vector(to_blender(c["forward"], 1.0)).normalized()
    up = Vector(to_blender(c["up"], 1.0)).normalized()
    right = forward.cross(up).normalized()
    up = right.cross(forward)
    rotation = Matrix((right, up, -forward)).transposed()
    cam.matrix_world = Matrix.Translation(cam.location) @ rotation.to_4x4()
    bpy.context.scene.collection.objects.link(cam)
    bpy.context.scene.camera = cam


def main():
    args = parse_args()
    with open(args.scene) as f:
        doc = json.load(f)
    if doc.get("lights") or doc.get("implicits"):
        sys.exit("cycles_render.py: point lights and implicit surfaces are not supported")
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    build_scene(doc)
    world = bpy.data.worlds.new("black")
    world.color = (0, 0, 0)
    scene.world = world

    scene.render.engine = "CYCLES"
    cy = scene.cycles
    cy.device = "CPU"
    cy.samples = args.spp
    cy.seed = args.seed
    cy.use_adaptive_sampling = False
    cy.use_denoising = False
    cy.pixel_filter_type = "BOX"
    cy.filter_width = 1.0
    cy.max_bounces = args.max_depth
    cy.diffuse_bounces = args.max_depth
    cy.glossy_bounces = args.max_depth
    cy.transmission_bounces = args.max_depth
    cy.transparent_max_bounces = args.max_depth
    cy.sample_clamp_direct = 0.0
    cy.sample_clamp_indirect = 0.0
    cy.caustics_reflective = True
    cy.caustics_refractive = True
    cy.blur_glossy = 0.0
    scene.render.threads_mode = "FIXED" if args.threads > 0 else "AUTO"
    if args.threads > 0:
        scene.render.threads = args.threads
    scene.render.resolution_x = args.size
    scene.render.resolution_y = args.size
    scene.render.resolution_percentage = 100
    scene.render.film_transparent = False
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.image_settings.color_depth = "32"
    scene.render.image_settings.color_mode = "RGBA"
    scene.render.image_settings.exr_codec = "ZIP"
    scene.render.filepath = args.out

    start = time.perf_counter()
    bpy.ops.render.render(write_still=True)
    seconds = time.perf_counter() - start
    print(f"cycles: render_s={seconds:.4f} spp={args.spp} pattern={cy.sampling_pattern}", flush=True)


main()
