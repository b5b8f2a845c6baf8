#!/usr/bin/env bash
# The D3D12 backend against the Vulkan backend, pixel for pixel: the Windows
# penumbra.exe renders on D3D12 under Wine (vkd3d-proton on lavapipe,
# scripts/wine-d3d12.sh), the Linux penumbra on Vulkan (lavapipe), with the
# same scene, size, samples and seed; `penumbra compare` then checks
#  - per pixel: no channel differs by more than 1e-3 of its value (1e-3
#    absolute near black) in more than the case's allowed fraction of pixels
#    (0.2 % by default: float rounding between the two compilers, DXC and
#    glslang, parts a few paths; the scenes where more part say why below);
#  - the image means: no channel's mean difference beyond 4 standard errors
#    of the per-pixel differences plus 1e-5 of its mean, so paths parted by
#    rounding (unbiased noise) pass and a systematic difference (light lost,
#    a surface or texture missing) fails;
#  - no NaN or Inf pixel on either side.
# A bug confined to fewer pixels than the allowed fraction whose effect on
# the mean hides within 4 standard errors would pass: at 64x64 and 0.2 %,
# about 8 pixels.
#
#   d3d12_backends.sh GROUP PENUMBRA PENUMBRA_EXE SOURCE_DIR
# GROUP: showcase (the five built-in scenes, Whitted), gltf (the glTF test
# files and scene files), paths (environment maps, denoisers, AOV layers,
# sample-split pieces, devices, both backends in one Windows process, the
# viewer offscreen on D3D12).
# Without wine, vkd3d-proton or a penumbra.exe with DXIL the group is not run:
# it says why and exits 77 (ctest: "Not Run"), never 0.
set -u
group="$1" penumbra="$2" exe="$3" source="$4"
wine_run="$source/scripts/wine-d3d12.sh"
data="$source/tests/data"
work=$(mktemp -d)
xvfb_pid=""
cleanup() {
  [ -n "$xvfb_pid" ] && kill "$xvfb_pid" 2>/dev/null
  rm -rf "$work"
}
trap cleanup EXIT
fail() { echo "FAIL: $*"; exit 1; }
not_run() { echo "NOT RUN (D3D12 $group): $*"; exit 77; }

command -v wine >/dev/null 2>&1 || not_run "wine is not installed (scripts/setup.sh installs it)"
[ -f "$exe" ] || not_run "no Windows build at $exe (scripts/build.sh makes it; PENUMBRA_SKIP_WINDOWS skips it)"

source "$(dirname "$0")/xvfb_display.sh"

d3d12() { bash "$wine_run" "$exe" "$@"; }

# The build must carry DXIL; a build without DXC is not run, by name.
if ! d3d12 render --backend d3d12 --size 8x8 --spp 1 --out "$work/probe.exr" >"$work/probe.log" 2>&1; then
  grep -q "has no DXIL" "$work/probe.log" &&
    not_run "$exe was built without DXC (no DXIL): $(grep -m1 'has no DXIL' "$work/probe.log")"
  grep -q "no vkd3d-proton" "$work/probe.log" && not_run "$(grep -m1 'no vkd3d-proton' "$work/probe.log")"
  cat "$work/probe.log"
  fail "penumbra.exe render --backend d3d12 failed"
fi

common=(--size 64x64 --spp 8 --seed 3)
failures=0
# compare_case NAME ALLOWED_FRACTION ARGS...: renders ARGS on both backends
# and compares (the beauty image, and each layer named in $layers).
layers=""
compare_case() {
  local name="$1" allowed="$2"
  shift 2
  local start end
  "$penumbra" render "$@" --out "$work/$name.vulkan.exr" >"$work/$name.vulkan.log" 2>&1 ||
    { cat "$work/$name.vulkan.log"; echo "FAIL $name: Vulkan render"; failures=$((failures + 1)); return; }
  start=$(date +%s.%N)
  d3d12 render --backend d3d12 "$@" --out "$work/$name.d3d12.exr" >"$work/$name.d3d12.log" 2>&1 ||
    { grep -v '^progress' "$work/$name.d3d12.log"; echo "FAIL $name: D3D12 render"; failures=$((failures + 1)); return; }
  end=$(date +%s.%N)
  local layer
  for layer in "" $layers; do
    local label="$name${layer:+ ($layer)}"
    "$penumbra" compare "$work/$name.vulkan.exr" "$work/$name.d3d12.exr" ${layer:+--layer "$layer"} \
      --tolerance 1e-3 --allowed-fraction "$allowed" --max-bias-sigmas 4 >"$work/$name.compare.log" 2>&1
    local status=$?
    printf '%-34s D3D12 %5.1f s  %s; %s; %s\n' "$label" "$(awk -v a="$start" -v b="$end" 'BEGIN { print b - a }')" \
      "$(grep -m1 'pixels beyond' "$work/$name.compare.log")" "$(grep -m1 'max absolute' "$work/$name.compare.log")" \
      "$(grep -m1 '^mean difference' "$work/$name.compare.log")"
    if [ $status -ne 0 ]; then
      cat "$work/$name.compare.log"
      echo "FAIL $label: the backends differ"
      failures=$((failures + 1))
    fi
  done
}

case "$group" in
  showcase)
    compare_case cornell-box 0.002 --scene cornell-box "${common[@]}"
    compare_case material-test 0.002 --scene material-test "${common[@]}"
    # 6.4 M triangles at 64x64: glossy paths part on about 0.9 % of pixels.
    compare_case performance 0.03 --scene performance "${common[@]}"
    compare_case cornell-box-whitted 0.002 --scene cornell-box-whitted "${common[@]}"
    # The sphere-traced mandelbulb and the glass ball part about 8 % of the
    # paths (scattered pixels; the means agree to within 1.7 standard errors).
    compare_case implicit-surfaces 0.15 --scene implicit-surfaces "${common[@]}"
    compare_case whitted-integrator 0.002 --scene cornell-box-whitted --integrator whitted "${common[@]}"
    # Triangles and implicit surfaces in one scene, with a tinted glass ball:
    # their AABB structure was lost on D3D12 before the barrier after each
    # bottom-level build (backends/d3d12/d3d12_command_list.cpp).
    compare_case sunlit-glass 0.002 --scene "$data/scenes/sunlit-glass.json" "${common[@]}"
    ;;
  gltf)
    for scene in "$data"/gltf/*.gltf "$data"/gltf/*.glb "$data"/gltf/*.json "$data"/scenes/textured-room.json; do
      base=$(basename "$scene")
      case "$base" in invalid_* | leak* | extension_required*.gltf) continue ;; esac
      compare_case "$base" 0.002 --scene "$scene" --allow-external-files "${common[@]}"
    done
    ;;
  paths)
    # An environment map: a render of the material-test scene as a lat-long image.
    "$penumbra" render --scene material-test --size 64x32 --spp 4 --out "$work/sky.exr" >/dev/null 2>&1 ||
      fail "rendering the environment map"
    compare_case environment-map 0.002 --scene "$data/gltf/materials.gltf" --env "$work/sky.exr" \
      --env-rotation 40 "${common[@]}"
    compare_case environment-default 0.002 --scene "$data/gltf/sphere_smooth.gltf" --env default "${common[@]}"
    compare_case denoise-atrous 0.002 --scene cornell-box --denoise atrous "${common[@]}"
    compare_case denoise-svgf 0.002 --scene cornell-box --denoise svgf --spp-per-frame 1 "${common[@]}"
    layers="albedo normal depth emission motion variance"
    compare_case aov 0.002 --scene material-test --denoise atrous \
      --aov albedo,normal,depth,emission,motion,variance "${common[@]}"
    layers=""
    compare_case sobol-thin-lens 0.002 --scene cornell-box --sampler sobol --aperture 0.02 --focus-distance 1.2 \
      "${common[@]}"
    # Parallel camera rays, and the denoiser's reprojection of them.
    compare_case orthographic-svgf 0.002 --scene cornell-box --orthographic 0.6 --denoise svgf \
      --spp-per-frame 1 "${common[@]}"

    # Sample-split pieces rendered on D3D12 merge (Linux penumbra merge) into
    # the image Vulkan renders in one piece.
    piece_args=(--scene cornell-box --size 48x48 --seed 5 --total-spp 32)
    d3d12 render --backend d3d12 "${piece_args[@]}" --samples 0:16 --out "$work/piece0.exr" >"$work/p.log" 2>&1 ||
      { cat "$work/p.log"; fail "D3D12 piece 0:16"; }
    d3d12 render --backend d3d12 "${piece_args[@]}" --samples 16:32 --out "$work/piece1.exr" >"$work/p.log" 2>&1 ||
      { cat "$work/p.log"; fail "D3D12 piece 16:32"; }
    "$penumbra" merge "$work/piece1.exr" "$work/piece0.exr" --out "$work/merged.exr" >"$work/m.log" 2>&1 ||
      { cat "$work/m.log"; fail "merging the D3D12 pieces"; }
    "$penumbra" render "${piece_args[@]}" --samples 0:32 --out "$work/whole.exr" >/dev/null 2>&1 || fail "Vulkan piece"
    "$penumbra" merge "$work/whole.exr" --out "$work/whole-merged.exr" >/dev/null 2>&1 || fail "Vulkan merge"
    "$penumbra" compare "$work/whole-merged.exr" "$work/merged.exr" --tolerance 1e-3 --max-bias-sigmas 4 \
      >"$work/c.log" 2>&1 || { cat "$work/c.log"; fail "merged D3D12 pieces differ from the Vulkan render"; }
    echo "sample-split pieces (D3D12, merged) match the Vulkan render: $(grep 'max absolute' "$work/c.log")"

    # The adapter and its DXR tier.
    d3d12 devices --backend d3d12 >"$work/devices.log" 2>&1 || { cat "$work/devices.log"; fail "devices"; }
    grep -q "DXR tier 1\.[01]" "$work/devices.log" || { cat "$work/devices.log"; fail "no DXR tier listed"; }
    echo "devices: $(head -1 "$work/devices.log")"

    # Both backends in one Windows process: Vulkan through Wine's
    # winevulkan, D3D12 through vkd3d-proton, the same lavapipe underneath.
    d3d12 compare --a vulkan:0 --b d3d12:0 --scene material-test --size 48x48 --spp 4 --seed 9 \
      --max-bias-sigmas 4 >"$work/one.log" 2>&1 || { cat "$work/one.log"; fail "compare --a vulkan:0 --b d3d12:0"; }
    echo "penumbra.exe compare --a vulkan:0 --b d3d12:0: $(grep 'max absolute' "$work/one.log")"

    # The viewer on D3D12 (offscreen): a scripted screenshot that the Linux
    # `penumbra render --settings` reproduces on Vulkan, and the menus drawn
    # through the RHI's raster subset (ImGui) on D3D12.
    viewer="$(dirname "$exe")/../viewer/penumbra-viewer.exe"
    cat >"$work/viewer.script" <<SCRIPT
set ui off
set spp-per-frame 4
set seed 5
set max-samples 16
move 0.03 0 0.05
wait-frames 2
wait-samples 16
wait-frames 2
screenshot $work/shot.exr
capture $work/shown.png
set ui on
wait-frames 3
capture $work/menus.png
quit
SCRIPT
    bash "$wine_run" "$viewer" --offscreen --backend d3d12 --scene cornell-box --size 160x120 --render-scale 1 \
      --config "$work/viewer.json" --script "$work/viewer.script" >"$work/viewer.log" 2>&1 ||
      { cat "$work/viewer.log"; fail "penumbra-viewer.exe --offscreen --backend d3d12"; }
    # (Windows programs end their lines with CR LF.)
    tr -d '\r' <"$work/viewer.log" | grep -q "^device: .* via d3d12, offscreen 160x120$" ||
      { cat "$work/viewer.log"; fail "the viewer did not run on D3D12"; }
    "$penumbra" render --settings "$work/shot.json" --out "$work/viewer-vulkan.exr" >/dev/null 2>&1 ||
      fail "penumbra render --settings of the viewer's screenshot"
    # As every case above, a path may part between the two compilers' float
    # rounding: 0.2 % of the pixels may differ (with Sobol, one of 19200 by 0.0015).
    "$penumbra" compare "$work/viewer-vulkan.exr" "$work/shot.exr" --tolerance 1e-3 --allowed-fraction 0.002 \
      --max-bias-sigmas 4 >"$work/viewer-compare.log" 2>&1 ||
      { cat "$work/viewer-compare.log"; fail "the D3D12 viewer's screenshot differs from render --settings on Vulkan"; }
    pngtopnm "$work/shown.png" >"$work/shown.ppm" && pngtopnm "$work/menus.png" >"$work/menus.ppm" ||
      fail "the viewer's captures are not PNG files"
    changed=$(python3 "$source/tests/apps/changed_pixels.py" "$work/shown.ppm" "$work/menus.ppm")
    awk -v v="$changed" 'BEGIN { exit !(v > 0.05) }' || fail "the D3D12 viewer's capture does not show the menus"
    echo "viewer on D3D12: screenshot vs render --settings on Vulkan: $(grep 'max absolute' "$work/viewer-compare.log"); the menus change $changed of the pixels"

    # Bad input on D3D12: one line, non-zero exit, no output file.
    d3d12 render --backend d3d12 --device 7 --size 8x8 --spp 1 --out "$work/none.exr" >"$work/bad.log" 2>&1 &&
      fail "a missing adapter was accepted"
    grep -q "no adapter 7" "$work/bad.log" || { cat "$work/bad.log"; fail "no clear error for a missing adapter"; }
    [ -e "$work/none.exr" ] && fail "output written despite the error"
    ;;
  *) fail "unknown group '$group'" ;;
esac

[ $failures -eq 0 ] || fail "$failures case(s) differ between D3D12 and Vulkan"
echo "D3D12 $group: every case matches Vulkan"
