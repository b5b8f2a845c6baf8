#!/usr/bin/env bash
# Real keyboard and mouse input, end to end: the viewer runs in a real window
# under Xvfb and xdotool sends X events to it, as a person's keyboard and
# mouse would. The camera is read back from screenshot records, each taken by
# clicking the Scene menu's Screenshot button (so a menu click is tested too).
#   W, D, E, S, A and Q held for a second each move the camera forward,
#     right, up, back, left and down:
#     the direction within 2.6 degrees (dot > 0.999) of the camera's own
#     axes, the distance the viewer's walking speed (the scene's diagonal / 5
#     per second, computed here from scenes/cornell-box.json) times the hold,
#     within [0.5, 1.6] x (the hold is timed by this script, the motion by
#     the viewer's frames, which lavapipe draws every 30-60 ms); a key that
#     did nothing or moved the wrong way fails.
#   A 50-pixel drag to the right with the left button turns the camera 10
#     degrees right (0.2 degrees a pixel, README), +-1, without pitching or
#     moving it. Home returns to the scene's camera exactly.
#   A double-click on the image focuses: the camera turns to the clicked
#     surface and the record's focus distance becomes that surface's
#     distance (the back wall, 1.0-1.6 m away; 1.0 exactly, the default,
#     would mean it did not focus, so that value fails).
#   F1, tapped, hides the menus: over half of the pixels under the menu
#     window change between xwd captures of the window before and after.
set -eu
viewer=$(readlink -f "$1")
source_dir=$(readlink -f "$2")
for tool in Xvfb xdotool xwd xwdtopnm python3; do
  command -v "$tool" >/dev/null 2>&1 || { echo "viewer input test: $tool not found (scripts/setup.sh installs it)" >&2; exit 1; }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
[ -n "${KEEP:-}" ] && trap - EXIT
cat > "$work/idle.script" <<SCRIPT
set spp-per-frame 1
set max-samples 1
wait-frames 100000000   # the test closes the viewer
SCRIPT
cat > "$work/session.sh" <<'SESSION'
set -eu
work="$1" viewer="$2"
cd "$work"
"$viewer" --scene cornell-box --size 640x480 --render-scale 0.25 --config "$work/viewer.json" \
  --script "$work/idle.script" > "$work/log" 2>&1 &
pid=$!
trap 'kill $pid 2>/dev/null || true' EXIT
wid=""
for i in $(seq 1 150); do
  kill -0 $pid 2>/dev/null || { echo "the viewer exited before its window appeared" >&2; exit 1; }
  wid=$(xdotool search --name "Penumbra viewer" 2>/dev/null | head -1) && [ -n "$wid" ] && break
  sleep 0.2
done
[ -n "$wid" ] || { echo "no viewer window after 30 s" >&2; exit 1; }
sleep 2
# The Scene menu's Screenshot button (the menu window at its first-use
# place, 640x480): the record lands in penumbra-screenshot.json.
shot() {
  rm -f penumbra-screenshot.json
  xdotool mousemove --window "$wid" 265 113 click 1
  for i in $(seq 1 150); do [ -s penumbra-screenshot.json ] && break; sleep 0.2; done
  [ -s penumbra-screenshot.json ] || { echo "no screenshot after clicking the Screenshot button" >&2; exit 1; }
  cp penumbra-screenshot.json "$1.json"
}
hold() {  # KEY: held for one second, the pointer over the image
  xdotool mousemove --window "$wid" 480 300
  xdotool keydown --window "$wid" "$1"
  sleep 1
  xdotool keyup --window "$wid" "$1"
  sleep 0.5
}
shot start
hold w; shot w
hold d; shot d
hold e; shot e
hold s; shot s
hold a; shot a
hold q; shot q
xdotool mousemove --window "$wid" 480 300
sleep 0.3
xdotool mousedown 1
for x in 490 500 510 520 530; do xdotool mousemove --window "$wid" "$x" 300; sleep 0.1; done
xdotool mouseup 1
sleep 0.5
shot drag
xdotool key --window "$wid" Home
sleep 0.5
shot home
xdotool mousemove --window "$wid" 400 300
sleep 0.3
xdotool click --repeat 2 --delay 80 1
sleep 1
shot focus
xdotool mousemove --window "$wid" 600 470
sleep 1
xwd -silent -id "$wid" > "$work/menus.xwd"
xdotool key --window "$wid" F1
sleep 1.5
xwd -silent -id "$wid" > "$work/hidden.xwd"
SESSION
# A display of the test's own: -displayfd picks a free one without the lock
# race of `xvfb-run -a` against the other window tests running beside it.
source "$(dirname "$0")/xvfb_display.sh"
trap 'kill "$xvfb_pid" 2>/dev/null || true; [ -n "${KEEP:-}" ] || rm -rf "$work"' EXIT
bash "$work/session.sh" "$work" "$viewer" || { cat "$work/log" 2>/dev/null; exit 1; }
cat "$work/log"
xwdtopnm "$work/menus.xwd" > "$work/menus.ppm" 2>/dev/null
xwdtopnm "$work/hidden.xwd" > "$work/hidden.ppm" 2>/dev/null
python3 - "$work" "$source_dir/scenes/cornell-box.json" "$(dirname "$(readlink -f "$0")")" <<'PY'
import json, math, subprocess, sys
work, scene_file, tests = sys.argv[1], sys.argv[2], sys.argv[3]
def record(name):
    return json.load(open(f"{work}/{name}.json"))["camera"]
def sub(a, b): return [x - y for x, y in zip(a, b)]
def dot(a, b): return sum(x * y for x, y in zip(a, b))
def norm(a): return math.sqrt(dot(a, a))
def unit(a): return [x / norm(a) for x in a]
def cross(a, b): return [a[1]*b[2]-a[2]*b[1], a[2]*b[0]-a[0]*b[2], a[0]*b[1]-a[1]*b[0]]
failures = []
def check(ok, what):
    print(("ok: " if ok else "FAILED: ") + what)
    if not ok: failures.append(what)

# The walking speed: the scene's diagonal / 5 per second (README, viewer).
scene = json.load(open(scene_file))
scale = scene.get("unitScale", 1.0)
points = [p for mesh in scene["meshes"] for quad in mesh["quads"] for p in quad]
lo = [min(p[k] for p in points) * scale for k in range(3)]
hi = [max(p[k] for p in points) * scale for k in range(3)]
speed = norm(sub(hi, lo)) / 5

start = record("start")
for before, after, axis_name, sign in (("start", "w", "forward", 1), ("w", "d", "right", 1),
                                       ("d", "e", "up", 1), ("e", "s", "forward", -1),
                                       ("s", "a", "right", -1), ("a", "q", "up", -1)):
    a, b = record(before), record(after)
    forward = unit(a["forward"])
    up = unit(a["up"])
    axis = {"forward": forward, "right": unit(cross(forward, up)), "up": up}[axis_name]
    axis = [sign * x for x in axis]
    axis_name = ("" if sign > 0 else "-") + axis_name
    delta = sub(b["position"], a["position"])
    moved = norm(delta)
    check(moved > 0 and dot(unit(delta), axis) > 0.999,
          f"{after.upper()} moves along {axis_name} (moved {moved:.4f} m, cos {dot(unit(delta), axis) if moved else 0:.5f})")
    check(0.5 * speed <= moved <= 1.6 * speed,
          f"{after.upper()} held 1 s moves {moved:.4f} m, speed {speed:.4f} m/s")

e, drag = record("q"), record("drag")
right = unit(cross(unit(e["forward"]), unit(e["up"])))
check(norm(sub(drag["position"], e["position"])) < 1e-9, "the drag does not move the camera")
check(dot(unit(drag["forward"]), right) > 0.01,
      f"a drag to the right turns right (forward . old right = {dot(unit(drag['forward']), right):.4f})")

yaw = math.degrees(math.atan2(dot(unit(drag["forward"]), right), dot(unit(drag["forward"]), unit(e["forward"]))))
check(9.0 <= yaw <= 11.0 and abs(drag["forward"][1] - e["forward"][1]) < 1e-6,
      f"a 50-pixel drag turns 10 degrees (0.2 per pixel) and does not pitch ({yaw:.3f} degrees)")

home = record("home")
check(home["position"] == start["position"] and home["forward"] == start["forward"],
      "Home returns to the scene's camera")
focus = record("focus")
check(norm(sub(focus["forward"], home["forward"])) > 1e-3 and focus["position"] == home["position"],
      "the double-click turns the camera to the surface, without moving it")
check(1.0 < focus["focusDistance"] <= 1.6,
      f"the double-click focuses on the back wall ({focus['focusDistance']:.4f} m)")

# Under the menu window: x 12-300, y 12-210.
changed = float(subprocess.run(
    [sys.executable, f"{tests}/changed_pixels.py", f"{work}/menus.ppm", f"{work}/hidden.ppm",
     "12", "12", "300", "210"], check=True, capture_output=True, text=True).stdout)
check(changed > 0.5, f"F1 hides the menus ({changed:.3f} of their pixels change)")
sys.exit(1 if failures else 0)
PY
echo "viewer input ok"
