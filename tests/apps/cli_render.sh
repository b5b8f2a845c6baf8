#!/usr/bin/env bash
# The main job end to end: render the default scene to PNG and EXR through the
# CLI with validation on, and check what it prints and writes.
set -eu
penumbra="$1"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# A failed check names its line and command, and shows what the renders
# printed to stderr (a rare failure under ctest -j2 printed nothing).
trap 'echo "cli_render.sh: line $LINENO failed: $BASH_COMMAND" >&2; cat "$work"/*.err >&2 2>/dev/null || true' ERR
"$penumbra" render --size 48x32 --spp 4 --seed 3 --validation --out "$work/cornell.png" | tee "$work/log"
grep -q "^device: " "$work/log"
grep -q "48x32, 4 spp" "$work/log"
grep -qE "^rays: [1-9][0-9]* \([0-9.]+ Mrays/s\)" "$work/log"
grep -qE "^GPU time: [0-9.]+ ms" "$work/log"
# A PNG of the right size (IHDR width/height at bytes 16..23).
[ "$(head -c 8 "$work/cornell.png" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ]
[ "$(od -An -tu1 -j16 -N8 "$work/cornell.png" | tr -s ' ')" = " 0 0 0 48 0 0 0 32" ]
"$penumbra" render --size 48x32 --spp 4 --seed 3 --validation --out "$work/cornell.exr" >/dev/null
[ "$(head -c 4 "$work/cornell.exr" | od -An -tx1 | tr -d ' \n')" = "762f3101" ]
# The Cornell box calls for its area light only (Lambertian walls); the full
# pipeline is one flag away, and the render says which it built.
[ "$("$penumbra" render --print-effects)" = "area-lights" ]
grep -q "^pipeline effects: area-lights$" "$work/log"
"$penumbra" render --size 16x16 --spp 1 --all-effects --out "$work/full.exr" | grep -q "^pipeline effects: area-lights, delta-lights, specular, transmission, clearcoat, sheen, textures, alpha-mask, environment, orthographic, specular-color, gltf-coat, gltf-sheen, diffuse-transmission, iridescence, dispersion (--all-effects)$"
# bench times both pipelines in one run and finds their images identical.
"$penumbra" bench --size 16x16 --frames 2 | tee "$work/bench"
grep -qE "^full / specialized GPU time \(medians\): [0-9.]+$" "$work/bench"
# Identical on lavapipe; GPUs may contract a * b + c differently in the two
# variants (measured on the H200: 6e-8), so up to 1e-5 passes.
diff=$(sed -nE 's/^images: max \|difference\| ([0-9.e+-]+),.*/\1/p' "$work/bench")
awk -v d="$diff" 'BEGIN { exit !(d != "" && d + 0 <= 1e-5) }'

# The material test with a varied parameter and constants from the command line.
"$penumbra" render --scene material-test --vary metallic --set roughness=0.3,baseColor=0.9,0.6,0.2 \
  --size 48x16 --spp 2 --validation --out "$work/row.png" >/dev/null
[ -s "$work/row.png" ]
# A .glb straight from the command line, from a camera chosen by name.
gltf_data="$(cd "$(dirname "$0")/../data/gltf" && pwd)"
"$penumbra" render --scene "$gltf_data/cameras.gltf" --camera side --size 16x16 --spp 1 --validation \
  --out "$work/gltf.png" | grep -q "^scene: cameras (1 triangles, 0 implicit objects)"
"$penumbra" render --scene "$gltf_data/triangle.glb" --size 16x16 --spp 1 --validation \
  --out "$work/glb.png" >/dev/null
[ -s "$work/glb.png" ]
# A camera placed on the command line: the same view as the file's camera
# (cameras.gltf's 'side': at (5,0,0) looking along -x, 0.5 rad) given as a
# position, a look-at point and a field of view renders the same image.
"$penumbra" render --scene "$gltf_data/cameras.gltf" --camera side --size 16x16 --spp 2 \
  --out "$work/named.exr" >/dev/null
"$penumbra" render --scene "$gltf_data/cameras.gltf" --camera-position 5,0,0 --look-at 0,0,0 \
  --fov 28.6478897565 --size 16x16 --spp 2 --out "$work/placed.exr" >/dev/null
"$penumbra" compare "$work/placed.exr" "$work/named.exr" --tolerance 1e-4 >/dev/null
# An orthographic view does not change with distance: the triangle seen
# from 5 m and from 50 m along the same parallel rays is the same image.
for distance in 5 50; do
  "$penumbra" render --scene "$gltf_data/cameras.gltf" --camera-position 0.3,0.3,$distance \
    --look-at 0.3,0.3,0 --orthographic 1.5 --size 16x16 --spp 2 --out "$work/ortho$distance.exr" \
    >/dev/null
done
"$penumbra" compare "$work/ortho50.exr" "$work/ortho5.exr" --tolerance 1e-4 >/dev/null
"$penumbra" render --scene "$gltf_data/cameras.gltf" --camera 1 --size 16x16 --spp 2 \
  --out "$work/indexed.exr" >/dev/null
"$penumbra" compare "$work/indexed.exr" "$work/named.exr" --tolerance 0 >/dev/null
# An animation at a chosen time: --time alone is the first animation's
# ("Bend"), the same image as naming it; at 0 s the strip stands straight,
# another image.
for pose in "--time 1" "--animation Bend --time 1" "--animation Bend"; do
  "$penumbra" render --scene "$gltf_data/animated.gltf" $pose --camera-position 0,1,6 --look-at 0,1,0 \
    --size 16x16 --spp 2 --validation --out "$work/pose-${pose//[ -]/}.exr" >/dev/null
done
"$penumbra" compare "$work/pose-time1.exr" "$work/pose-animationBendtime1.exr" --tolerance 0 >/dev/null
if "$penumbra" compare "$work/pose-time1.exr" "$work/pose-animationBend.exr" --tolerance 1e-3 >/dev/null; then
  echo "the animation did not move the skinned strip"; exit 1
fi
# A glTF file without lights is lit by the default environment and says so
# (one line); --env none leaves it black, and says nothing.
"$penumbra" render --scene "$gltf_data/attributes.gltf" --size 16x16 --spp 4 --validation \
  --out "$work/studio.exr" 2>"$work/studio.err" >/dev/null
[ "$(grep -c "has no light: lit by the default studio environment" "$work/studio.err")" = 1 ]
"$penumbra" render --scene "$gltf_data/attributes.gltf" --env none --size 16x16 --spp 4 \
  --out "$work/dark.exr" 2>"$work/dark.err" >/dev/null
# (A render past a second reports its progress there too: a loaded machine
# or a cold shader cache makes this one that slow.)
if grep -v '^progress: ' "$work/dark.err" | grep -q .; then
  echo "--env none still said something:"; cat "$work/dark.err"; exit 1
fi
# Emissive materials of a glTF file are not its lighting: it is lit too, and
# the line says why.
"$penumbra" render --scene "$gltf_data/emissive_quad.gltf" --size 16x16 --spp 1 \
  --out "$work/label.exr" 2>"$work/label.err" >/dev/null
grep -q "has no light (its glTF emissive materials are not counted as lights): lit by the default studio environment" "$work/label.err"
if "$penumbra" compare "$work/studio.exr" "$work/dark.exr" --tolerance 1e-3 >/dev/null; then
  echo "the default environment did not light the glTF file"; exit 1
fi
# An environment from a file for any scene, turned, scaled, behind a hidden
# background; --print-effects lists the branch features after the variant bits.
"$penumbra" render --scene "$gltf_data/attributes.gltf" --env "$work/studio.exr" --env-rotation 90 \
  --env-intensity 2 --env-background hidden --size 16x16 --spp 2 --validation --out "$work/env.png" >/dev/null
[ -s "$work/env.png" ]
[ "$("$penumbra" render --scene "$gltf_data/attributes.gltf" --aperture 0.01 --aperture-blades 5 --orthographic 2 \
  --print-effects)" = "$(printf 'specular\nenvironment\northographic\nthin-lens (branch)\nlens-blades (branch)')" ]
# The denoiser on the final image with every AOV as an EXR layer (the header
# names the channels), and the temporal denoiser frame by frame.
"$penumbra" render --size 32x32 --spp 2 --denoise atrous --aov albedo,normal,depth,emission,motion,variance \
  --validation --out "$work/denoised.exr" | tee "$work/dlog"
grep -qE "^denoiser \(atrous\): [0-9.]+ ms GPU time$" "$work/dlog"
for channel in R G B A albedo.R albedo.G albedo.B normal.X normal.Y normal.Z depth.Z emission.R motion.X \
  motion.Y variance.Y noisy.R; do
  grep -qa "$channel" "$work/denoised.exr" || { echo "denoised.exr lacks channel $channel"; exit 1; }
done
"$penumbra" render --size 32x32 --spp 4 --spp-per-frame 1 --denoise svgf --validation --out "$work/svgf.png" |
  grep -qE "^denoiser \(svgf\): [0-9.]+ ms GPU time$"
[ -s "$work/svgf.png" ]
# bench times the denoiser on its own frames and measures their steadiness.
"$penumbra" bench --size 24x24 --frames 3 --denoise svgf | tee "$work/dbench"
grep -qE "^denoiser \(svgf\) GPU ms/frame median [0-9.]+, mean [0-9.]+$" "$work/dbench"
grep -qE "^frame-to-frame mean \|luminance change\|: raw [0-9.e+-]+, denoised [0-9.e+-]+" "$work/dbench"
# Along a camera pan: the flicker of what stays in view, reprojected (the
# temporal filter must be steadier than the raw frames), and the last frame's
# error by history length, whose three groups cover every pixel that shows a
# surface (most of the square image: the Cornell box fills it).
"$penumbra" bench --size 32x32 --frames 4 --spp-per-frame 2 --denoise svgf --camera-pan 0.005 \
  --reference-spp 32 | tee "$work/pan"
steadier=$(sed -nE 's/^frame-to-frame mean \|luminance change\| along the pan, reprojected, over the [0-9]+ % of pixels kept in history: raw [0-9.e+-]+, denoised [0-9.e+-]+ \(([0-9.]+)x steadier\)$/\1/p' "$work/pan")
awk -v s="$steadier" 'BEGIN { exit !(s > 1.5) }'
covered=$(sed -nE 's/^  (just disoccluded|history [0-9+-]+ frames).* ([0-9]+) pixels: [0-9.e+-]+ \/ [0-9.e+-]+$/\2/p' "$work/pan" |
  awk '{ n += $1 } END { print n }')
surface=$(sed -nE 's/^last frame of the pan against a 32 spp reference, the ([0-9]+) pixels with a surface.*/\1/p' "$work/pan")
[ "$covered" -eq "$surface" ] && [ "$surface" -gt 512 ]
# Settled pixels: the denoised frame is at least twice as close to the
# reference as the raw one. A pan slower than half a pixel per frame once
# dragged the light's emission along behind its edge (denoised 3x worse
# than raw here).
settled=$(sed -nE 's/^  history 5\+ frames +[0-9]+ pixels: ([0-9.e+-]+) \/ ([0-9.e+-]+)$/\1 \2/p' "$work/pan")
awk -v r="${settled% *}" -v d="${settled#* }" 'BEGIN { exit !(d < 0.5 * r) }'
# The same pan through an orthographic camera (bench takes the camera
# options too): everything in view moves alike, so all but the pixels
# entering at the edge keep their history (93 % in perspective above).
"$penumbra" bench --size 32x32 --frames 4 --spp-per-frame 2 --denoise svgf --camera-pan 0.005 \
  --reference-spp 32 --orthographic 0.5 | tee "$work/orthopan"
kept=$(sed -nE 's/^frame-to-frame mean \|luminance change\| along the pan, reprojected, over the ([0-9]+) % of pixels kept in history: .*\(([0-9.]+)x steadier\)$/\1 \2/p' "$work/orthopan")
awk -v k="${kept% *}" -v s="${kept#* }" 'BEGIN { exit !(k >= 97 && s > 1.5) }'
if "$penumbra" bench --size 16x16 --frames 1 --camera-pan 0.01 2> "$work/pan-err"; then exit 1; fi
grep -q "^error: --camera-pan: the camera path measures the denoiser" "$work/pan-err"
"$penumbra" devices | grep -q "ray tracing pipeline: yes"
"$penumbra" render --help | grep -q -- "--spp"
echo "render CLI ok"
