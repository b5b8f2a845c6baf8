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
echo "render --settings ok"
