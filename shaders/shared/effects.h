// The effects a scene can call for. A pipeline is built from shader variants
// compiled with PT_EFFECTS set to the scene's effect set, so code a scene does
// not need (refraction without glass, NEE without area lights, ...) is not in
// its pipeline at all. Without PT_EFFECTS a shader holds every effect.
//
// Plain integers, not 1u: preprocessor #if expressions use them too, in GLSL,
// HLSL and C++. The host derives the set in engine/penumbra/render/effect_set.cpp; a bit
// may be off only if no material, light or camera of the scene could use the
// code.
#ifndef PENUMBRA_EFFECTS_H
#define PENUMBRA_EFFECTS_H

// One line each: the build reads these lines (shaders/CMakeLists.txt).
// clang-format off
#define PT_EFFECT_AREA_LIGHTS 1    // emissive geometry: emission on hit, NEE on triangles, MIS
#define PT_EFFECT_DELTA_LIGHTS 2   // point and spot lights
#define PT_EFFECT_SPECULAR 4       // a GGX specular layer: metallic > 0 or specular > 0 (Phong: ks, mirrors)
#define PT_EFFECT_TRANSMISSION 8   // specTrans > 0 (Phong: transparency > 0)
#define PT_EFFECT_CLEARCOAT 16     // clearcoat > 0
#define PT_EFFECT_SHEEN 32         // sheen > 0
#define PT_EFFECT_TEXTURES 64      // surface detail: material textures (base colour, metallic-roughness, emission, normal maps), COLOR_0, unlit materials and glTF anisotropy
#define PT_EFFECT_ALPHA_MASK 128   // MASK (textured or COLOR_0 alpha) or BLEND: an any-hit shader cuts
#define PT_EFFECT_ENVIRONMENT 512  // an environment map: seen by rays that escape, sampled by NEE
#define PT_EFFECT_ORTHOGRAPHIC 1024 // an orthographic camera: parallel rays from the film plane
#define PT_EFFECT_SPECULAR_COLOR 2048 // a coloured dielectric F0, or one above 0.08: specularColor != 1, its texture, specularTint > 0; or glTF's F90 below 1 (specularF90, the specular texture)
#define PT_EFFECT_GLTF_COAT 4096   // glTF's coat (the lambert model's clearcoat > 0): full strength, GGX, instead of Disney's GTR1
#define PT_EFFECT_GLTF_SHEEN 8192  // glTF's sheen (the lambert model's sheen > 0): Charlie fibres and their albedo table, instead of Burley's
#define PT_EFFECT_DIFFUSE_TRANSMISSION 16384 // diffuseTransmission > 0: part of the diffuse lobe passes to the other side
#define PT_EFFECT_IRIDESCENCE 32768 // iridescence > 0 over a specular layer: a thin film's interference colours its Fresnel
#define PT_EFFECT_DISPERSION 65536 // dispersion > 0 on a refracting volume: paths carry one wavelength through it
// clang-format on
// Every effect: the eight bits above, the environment, the orthographic camera,
// the coloured F0, glTF's coat and sheen, diffuse transmission, iridescence and
// dispersion.
#define PT_EFFECTS_ALL                                                                            \
  (PT_EFFECT_AREA_LIGHTS | PT_EFFECT_DELTA_LIGHTS | PT_EFFECT_SPECULAR | PT_EFFECT_TRANSMISSION | \
   PT_EFFECT_CLEARCOAT | PT_EFFECT_SHEEN | PT_EFFECT_TEXTURES | PT_EFFECT_ALPHA_MASK |            \
   PT_EFFECT_ENVIRONMENT | PT_EFFECT_ORTHOGRAPHIC | PT_EFFECT_SPECULAR_COLOR |                    \
   PT_EFFECT_GLTF_COAT | PT_EFFECT_GLTF_SHEEN | PT_EFFECT_DIFFUSE_TRANSMISSION |                  \
   PT_EFFECT_IRIDESCENCE | PT_EFFECT_DISPERSION)
// Not a scene effect but an output: the path tracer writes the denoiser's
// guide buffers (PathTracerSettings::writeGuides). Its code and the state it
// keeps alive across every trace cost about a tenth of a Cornell box frame,
// so a render nobody denoises builds without it.
#define PT_OUTPUT_GUIDES 256

// The effects each entry point is compiled in variants of (the subsets listed
// in shaders/effect_variants.cmake). Alpha masking is no variant: it adds an
// any-hit shader to the triangles' hit group instead.
#define PT_PATH_TRACE_EFFECT_BITS ((PT_EFFECTS_ALL | PT_OUTPUT_GUIDES) & ~PT_EFFECT_ALPHA_MASK)
// Whitted shades Phong materials, which have no dielectric F0 colour.
#define PT_WHITTED_EFFECT_BITS                                                                \
  (PT_EFFECT_SPECULAR | PT_EFFECT_TRANSMISSION | PT_EFFECT_TEXTURES | PT_EFFECT_ENVIRONMENT | \
   PT_EFFECT_ORTHOGRAPHIC)

#ifndef PT_EFFECTS
#define PT_EFFECTS (PT_EFFECTS_ALL | PT_OUTPUT_GUIDES)
#endif
#define PT_HAS_EFFECT(effect) ((PT_EFFECTS & (effect)) != 0)
// glTF's coat has a normal of its own (its normal map, else the vertex
// normal) only where both the coat and surface detail are built.
#define PT_COAT_NORMALS (PT_HAS_EFFECT(PT_EFFECT_GLTF_COAT) && PT_HAS_EFFECT(PT_EFFECT_TEXTURES))

#endif
