# The effect variants built ahead of time (docs/ARCHITECTURE.md, "Effect
# specialization"): not every subset of the bits (512 path-tracer variants)
# but the ones the built-in scenes, the test suite and the size checks use.
# A scene whose exact set is not here renders with the smallest built
# variant that holds every effect it needs (render::effectVariant): the same
# image, a little less saved. tests/render/test_effect_set.cpp fails when a
# built-in scene's set is missing. Masks are PT_EFFECT_* sums (effects.h):
# 1 area lights, 2 delta lights, 4 specular, 8 transmission, 16 clearcoat,
# 32 sheen, 64 textures, 256 guide output, 512 environment.

# Each built-in scene as it is (e), with the denoiser's guides (e+256), under
# an environment (e+512) and both: cornell-box 1, material-test 5,
# performance 7, cornell-box-whitted 14, implicit-surfaces 31.
set(_builtin_path_trace
  1 257 513 769
  5 261 517 773
  7 263 519 775
  14 270 526 782
  31 287 543 799)
# What the test scenes call for (logged over the whole suite).
set(_tests_path_trace
  0 2 4 6 8 9 11 13 63 64 65 66 69 70 260 512 516 523 639 772)
# Every effect but one (895 without each bit): what each effect costs in
# code size and time (test_effect_set, scripts/feature_costs.sh).
set(_all_but_one_path_trace 894 893 891 887 879 863 831 639 383)
list(APPEND PENUMBRA_PATH_TRACE_VARIANTS ${_builtin_path_trace} ${_tests_path_trace}
     ${_all_but_one_path_trace})
list(REMOVE_DUPLICATES PENUMBRA_PATH_TRACE_VARIANTS)

# Whitted's bits are 4 specular, 8 transmission, 64 textures, 512 environment:
# cornell-box 0, material-test and performance 4, cornell-box-whitted and
# implicit-surfaces 12, each also under an environment; the test scenes' 8,
# 64, 520; every bit but one.
set(PENUMBRA_WHITTED_VARIANTS 0 512 4 516 12 524 8 64 520 584 580 524 76)
list(REMOVE_DUPLICATES PENUMBRA_WHITTED_VARIANTS)
