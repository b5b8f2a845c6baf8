#!/usr/bin/env bash
# `penumbra render --settings FILE`: the record's camera and settings are
# used, and options given on the command line override it.
set -eu
penumbra="$1"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat > "$work/job.json" <<JSON
{ "format": "penumbra-render", "version": 1, "scene": "cornell-box",
  "camera": { "position": [0.2, 0.25, -0.6], "forward": [0.1, 0, 1], "up": [0, 1, 0],
              "verticalFovDegrees": 50 },
  "width": 40, "height": 30, "spp": 6, "sppPerFrame": 2, "seed": 4, "maxDepth": 3 }
JSON
"$penumbra" render --settings "$work/job.json" --validation --out "$work/a.exr" | tee "$work/log"
grep -q "40x30, 6 spp, seed 4" "$work/log"
# The same job spelled out on the command line, except for the camera.
"$penumbra" render --size 40x30 --spp 6 --spp-per-frame 2 --seed 4 --max-depth 3 --out "$work/scene-camera.exr" >/dev/null
if "$penumbra" compare "$work/a.exr" "$work/scene-camera.exr" --tolerance 1e-6 >/dev/null; then
  echo "the settings file's camera was not used" >&2; exit 1
fi
# Explicit options win over the file.
"$penumbra" render --settings "$work/job.json" --spp 2 --out "$work/b.exr" | grep -q "40x30, 2 spp, seed 4"
# A broken record is one line and a non-zero exit.
echo '{"format": "penumbra-render", "version": 1, "strategy": "best"}' > "$work/bad.json"
if "$penumbra" render --settings "$work/bad.json" --out "$work/c.exr" 2>"$work/err"; then exit 1; fi
grep -q "bad.json: \"strategy\" 'best' is not a known value" "$work/err"
[ ! -e "$work/c.exr" ]
# A material override names its material: applied to another scene (or a
# changed one) the record fails instead of editing the wrong material.
cat > "$work/other.json" <<JSON
{ "format": "penumbra-render", "version": 1, "scene": "cornell-box", "width": 8, "height": 8,
  "materials": [ { "index": 0, "name": "marble", "model": "disney", "baseColor": [1, 0, 0],
    "metallic": 0, "roughness": 0.5, "anisotropic": 0, "specular": 0.5, "specularTint": 0,
    "sheen": 0, "sheenTint": 0.5, "clearcoat": 0, "clearcoatGloss": 1, "specTrans": 0,
    "ior": 1.5, "subsurface": 0, "thin": false, "ks": 0, "exponent": 32, "reflectivity": 0,
    "transparency": 0 } ] }
JSON
if "$penumbra" render --settings "$work/other.json" --out "$work/d.exr" 2>"$work/err"; then exit 1; fi
grep -q "other.json: \"materials\[0\].name\" 'marble' does not match material 0 of scene" "$work/err"
[ "$(wc -l < "$work/err")" -eq 1 ]
[ ! -e "$work/d.exr" ]
# --f-number needs a focal length where the lens renders: a record's
# perspective camera has one even when its scene's camera is orthographic.
sed 's/"verticalFovDegrees": 39.3077/"orthographicHeight": 600/' \
  "$(dirname "$0")/../../scenes/cornell-box.json" > "$work/flat-box.json"
grep -q '"orthographicHeight": 600' "$work/flat-box.json"
cat > "$work/lens.json" <<JSON
{ "format": "penumbra-render", "version": 1, "scene": "$work/flat-box.json",
  "camera": { "position": [0.278, 0.273, -0.8], "forward": [0, 0, 1], "up": [0, 1, 0],
              "verticalFovDegrees": 40 },
  "width": 8, "height": 8, "spp": 1 }
JSON
"$penumbra" render --settings "$work/lens.json" --f-number 2 --focus-distance 1 --out "$work/lens.exr" >/dev/null
[ -s "$work/lens.exr" ]
if "$penumbra" render --scene "$work/flat-box.json" --f-number 2 --size 8x8 --spp 1 --out "$work/flat.exr" 2>"$work/err"; then exit 1; fi
grep -q "camera: --f-number needs a focal length, which an orthographic camera has not" "$work/err"
[ ! -e "$work/flat.exr" ]
echo "render --settings ok"
