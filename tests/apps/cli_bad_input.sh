#!/usr/bin/env bash
# Bad input to `penumbra`: one line on stderr saying what and where, a
# non-zero exit, no crash, no output file left behind.
set -u
penumbra="$1"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

expect_error() {  # expect_error "description" "stderr pattern" args...
  local what="$1" pattern="$2"
  shift 2
  "$penumbra" "$@" >"$work/stdout" 2>"$work/stderr"
  local rc=$?
  local lines
  lines=$(grep -c . "$work/stderr")
  if [ "$rc" -eq 0 ] || [ "$rc" -ge 128 ]; then
    echo "FAIL $what: exit code $rc (want 1..127)"; failures=$((failures + 1))
  elif [ "$lines" -ne 1 ]; then
    echo "FAIL $what: $lines lines on stderr (want 1):"; cat "$work/stderr"; failures=$((failures + 1))
  elif ! grep -q -- "$pattern" "$work/stderr"; then
    echo "FAIL $what: stderr lacks '$pattern':"; cat "$work/stderr"; failures=$((failures + 1))
  else
    echo "ok   $what: $(cat "$work/stderr")"
  fi
  if ls "$work"/out* >/dev/null 2>&1; then
    echo "FAIL $what: left an output file behind: $(ls "$work"/out*)"; failures=$((failures + 1))
    rm -f "$work"/out*
  fi
}

expect_error "unknown flag" "--bogus" render --bogus --out "$work/out.png"
expect_error "unknown scene" "no-such-scene" render --scene no-such-scene --out "$work/out.png"
echo '{ "format": "penumbra-scene", ' >"$work/broken.json"
expect_error "malformed scene file" "broken.json" render --scene "$work/broken.json" --out "$work/out.png"
expect_error "unwritable output directory" "does not exist" render --size 8x8 --spp 1 --out "$work/missing/out.png"
expect_error "unknown output type" "unknown image type" render --size 8x8 --spp 1 --out "$work/out.bmp"
expect_error "bad size" "--size" render --size 12 --out "$work/out.png"
expect_error "negative aperture" "--aperture" render --aperture -0.1 --size 8x8 --spp 1 --out "$work/out.png"
expect_error "zero focus distance" "--focus-distance" render --aperture 0.1 --focus-distance 0 --size 8x8 --spp 1 --out "$work/out.png"
expect_error "two aperture blades" "2 aperture blades" render --aperture 0.1 --aperture-blades 2 --size 8x8 --spp 1 --out "$work/out.png"
expect_error "missing environment map" "sky.exr" render --env "$work/sky.exr" --size 8x8 --spp 1 --out "$work/out.png"
printf 'P6\n1 1\n255\n\0\0\0' >"$work/sky.ppm"
expect_error "environment map that is no HDR image" "not an HDR image" render --env "$work/sky.ppm" --size 8x8 --spp 1 --out "$work/out.png"
cp "$work/sky.ppm" "$work/sky.hdr"
expect_error "environment .hdr that is no Radiance file" "not a Radiance HDR" render --env "$work/sky.hdr" --size 8x8 --spp 1 --out "$work/out.png"
expect_error "environment setting without an environment" "need an environment" render --env none --env-rotation 30 --size 8x8 --spp 1 --out "$work/out.png"
expect_error "unknown background mode" "--env-background" render --env default --env-background maybe --size 8x8 --spp 1 --out "$work/out.png"
expect_error "glTF spot with outer < inner" "spot cone angles" render --scene "$(dirname "$0")/../data/gltf/invalid_light_cone.gltf" --size 8x8 --spp 1 --out "$work/out.png"
expect_error "d3d12 on Linux" "Windows builds only" render --backend d3d12 --size 8x8 --spp 1 --out "$work/out.png"
expect_error "device index out of range" "does not exist" render --device 99 --size 8x8 --spp 1 --out "$work/out.png"
expect_error "unknown subcommand" "subcommand" bogus
expect_error "unknown --vary parameter" "--vary 'colour'" render --scene material-test --vary colour --out "$work/out.png"
expect_error "--set on a scene without a row" "no material-test row" render --scene cornell-box --set metallic=1 --out "$work/out.png"
expect_error "unknown denoiser" "--denoise" render --denoise bilateral --size 8x8 --spp 1 --out "$work/out.png"
expect_error "denoising Whitted" "--integrator path" render --integrator whitted --denoise atrous --size 8x8 --spp 1 --out "$work/out.png"
expect_error "unknown AOV" "unknown output 'uv'" render --aov albedo,uv --size 8x8 --spp 1 --out "$work/out.exr"
expect_error "AOVs into a PNG" "auxiliary outputs are EXR layers" render --aov albedo --size 8x8 --spp 1 --out "$work/out.png"
gltf_data="$(cd "$(dirname "$0")/../data/gltf" && pwd)"
expect_error "missing glTF file" "no such file" render --scene "$work/missing.glb" --out "$work/out.png"
expect_error "a folder as the scene" "is a folder; give a scene file" render --scene "$gltf_data" --out "$work/out.png"
mkdir -p "$work/folder.gltf"
expect_error "a folder named like a glTF file" "is a folder" render --scene "$work/folder.gltf" --out "$work/out.png"
expect_error "look-at at the camera" "is the camera's position" render --camera-position 1,2,3 --look-at 1,2,3 --size 8x8 --spp 1 --out "$work/out.png"
expect_error "a field of view and an orthographic height" "give --fov (perspective) or --orthographic, not both" render --fov 40 --orthographic 2 --size 8x8 --spp 1 --out "$work/out.png"
expect_error "an f-number for an orthographic camera" "--f-number needs a focal length" render --orthographic 2 --f-number 4 --size 8x8 --spp 1 --out "$work/out.png"
expect_error "a camera position of two numbers" "--camera-position" render --camera-position 1,2 --size 8x8 --spp 1 --out "$work/out.png"
expect_error "an unknown material variant" "no material variant 'dusk'" render --scene "$gltf_data/materials.gltf" --variant dusk --size 8x8 --spp 1 --out "$work/out.png"
expect_error "an unknown animation" "no animation 'Walk' (animations by index and name: 0 'Bend', 1 'Slide')" render --scene "$gltf_data/animated.gltf" --animation Walk --size 8x8 --spp 1 --out "$work/out.png"
expect_error "a time for a file without animations" "the file has no animations to draw at a time" render --scene "$gltf_data/cameras.gltf" --time 1 --size 8x8 --spp 1 --out "$work/out.png"
expect_error "a glTF file needing KTX2" "requires extension KHR_texture_basisu" render --scene "$gltf_data/extension_required_compressed.gltf" --out "$work/out.png"
expect_error "cyclic glTF node graph" "cyclic" render --scene "$gltf_data/invalid_cycle.gltf" --out "$work/out.png"
expect_error "unknown glTF camera" "no camera named 'nope'" render --scene "$gltf_data/emissive_quad.gltf" --camera nope --out "$work/out.png"
# Out of memory says what the scene needs, in one line: a 4000 x 4000
# terrain (32 M triangles) in a 2 GB address space fails uploading it, and
# in 400 MB already generating it.
cat >"$work/terrain.json" <<'JSON'
{ "format": "penumbra-scene", "version": 1, "name": "big terrain",
  "camera": { "position": [0, 5, -17], "forward": [0, -0.3, 1], "up": [0, 1, 0], "verticalFovDegrees": 50 },
  "materials": { "rock": { "model": "lambert", "albedo": [0.45, 0.4, 0.35] } },
  "lights": [ { "type": "point", "position": [6, 20, -12], "intensity": [150, 145, 135] } ],
  "generated": [ { "kind": "terrain", "material": "rock", "resolution": 4000, "size": 40, "height": 2.5 } ] }
JSON
real_penumbra="$penumbra"
for limit in 2000000 400000; do
  printf '#!/bin/sh\nulimit -v %s\nexec "%s" "$@"\n' "$limit" "$real_penumbra" >"$work/limited.sh"
  chmod +x "$work/limited.sh"
  penumbra="$work/limited.sh"
  expect_error "out of memory in ${limit} KB" "GiB" render --scene "$work/terrain.json" --size 16x16 --spp 1 --out "$work/out.png"
  penumbra="$real_penumbra"
done
# A machine without a Vulkan driver: point the loader at an empty driver list.
VK_DRIVER_FILES="$work/none.json" VK_ICD_FILENAMES="$work/none.json" \
  expect_error "no device with ray tracing" "no Vulkan driver" render --size 8x8 --spp 1 --out "$work/out.png"

if [ "$failures" -ne 0 ]; then echo "$failures failure(s)"; exit 1; fi
echo "all bad-input cases handled"
