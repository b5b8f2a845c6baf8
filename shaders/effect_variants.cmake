# The effect variants built ahead of time (docs/ARCHITECTURE.md, "Effect
# specialization"): not every subset of the bits (65536 path-tracer variants)
# but the ones the built-in scenes, the test suite and the size checks use.
# A scene whose exact set is not here renders with the smallest built
# variant that holds every effect it needs (render::effectVariant): the same
# image, a little less saved. tests/render/test_effect_set.cpp fails when a
# built-in scene's set is missing. Sets are named by shaders/shared/effects.h's
# bits (penumbra_effect_masks, shaders/CMakeLists.txt).

# Each built-in scene as it is, with the denoiser's guides, under an
# environment and both; and seen through an orthographic camera, with and
# without the guides (an unlisted set takes a superset that can cost 2x).
penumbra_effect_masks(_builtin_scenes
  AREA_LIGHTS                                              # cornell-box
  AREA_LIGHTS+SPECULAR                                     # material-test
  AREA_LIGHTS+DELTA_LIGHTS+SPECULAR                        # performance
  DELTA_LIGHTS+SPECULAR+TRANSMISSION                       # cornell-box-whitted
  AREA_LIGHTS+DELTA_LIGHTS+SPECULAR+TRANSMISSION+CLEARCOAT # implicit-surfaces
)
penumbra_effect_masks(_scene_extras NONE GUIDES ENVIRONMENT GUIDES+ENVIRONMENT ORTHOGRAPHIC
  GUIDES+ORTHOGRAPHIC)
set(_builtin_path_trace)
foreach(scene ${_builtin_scenes})
  foreach(extra ${_scene_extras})
    math(EXPR mask "${scene} | ${extra}")
    list(APPEND _builtin_path_trace ${mask})
  endforeach()
endforeach()
# What the test scenes call for (logged over the whole suite; the two with
# GLTF_COAT+GLTF_SHEEN serve the glTF-model coat and sheen cases of
# test_effect_set and test_textures, which the two before them served until
# those bits had code of their own).
penumbra_effect_masks(_tests_path_trace
  NONE DELTA_LIGHTS SPECULAR DELTA_LIGHTS+SPECULAR TRANSMISSION
  AREA_LIGHTS+TRANSMISSION AREA_LIGHTS+DELTA_LIGHTS+TRANSMISSION
  AREA_LIGHTS+SPECULAR+TRANSMISSION
  AREA_LIGHTS+DELTA_LIGHTS+SPECULAR+TRANSMISSION+CLEARCOAT+SHEEN
  TEXTURES AREA_LIGHTS+TEXTURES DELTA_LIGHTS+TEXTURES AREA_LIGHTS+SPECULAR+TEXTURES
  DELTA_LIGHTS+SPECULAR+TEXTURES SPECULAR+GUIDES ENVIRONMENT SPECULAR+ENVIRONMENT
  AREA_LIGHTS+DELTA_LIGHTS+TRANSMISSION+ENVIRONMENT
  AREA_LIGHTS+DELTA_LIGHTS+SPECULAR+TRANSMISSION+CLEARCOAT+SHEEN+TEXTURES+ENVIRONMENT
  AREA_LIGHTS+DELTA_LIGHTS+SPECULAR+TRANSMISSION+CLEARCOAT+SHEEN+GLTF_COAT+GLTF_SHEEN
  AREA_LIGHTS+DELTA_LIGHTS+SPECULAR+TRANSMISSION+CLEARCOAT+SHEEN+TEXTURES+ENVIRONMENT+GLTF_COAT+GLTF_SHEEN
  SPECULAR+GUIDES+ENVIRONMENT AREA_LIGHTS+SPECULAR+SPECULAR_COLOR
  DELTA_LIGHTS+SPECULAR+TEXTURES+SPECULAR_COLOR
  AREA_LIGHTS+DELTA_LIGHTS+SPECULAR+DIFFUSE_TRANSMISSION ENVIRONMENT+DIFFUSE_TRANSMISSION
  AREA_LIGHTS+DELTA_LIGHTS+SPECULAR+IRIDESCENCE AREA_LIGHTS+TRANSMISSION+DISPERSION
  AREA_LIGHTS+SPECULAR+TRANSMISSION+DISPERSION)
# Every effect but one: what each effect costs in code size and time
# (test_effect_set, scripts/feature_costs.sh).
penumbra_all_but_one(_all_but_one_path_trace ${_path_trace_effects})
set(PENUMBRA_PATH_TRACE_VARIANTS ${_builtin_path_trace} ${_tests_path_trace}
    ${_all_but_one_path_trace})
list(REMOVE_DUPLICATES PENUMBRA_PATH_TRACE_VARIANTS)

# Whitted: the built-in scenes' sets (cornell-box; material-test and
# performance; cornell-box-whitted and implicit-surfaces), each also under an
# environment; the test scenes'; every bit but one.
penumbra_effect_masks(PENUMBRA_WHITTED_VARIANTS
  NONE ENVIRONMENT SPECULAR SPECULAR+ENVIRONMENT SPECULAR+TRANSMISSION
  SPECULAR+TRANSMISSION+ENVIRONMENT
  TRANSMISSION TEXTURES TRANSMISSION+ENVIRONMENT)
penumbra_all_but_one(_all_but_one_whitted ${_whitted_effects})
list(APPEND PENUMBRA_WHITTED_VARIANTS ${_all_but_one_whitted})
list(REMOVE_DUPLICATES PENUMBRA_WHITTED_VARIANTS)
