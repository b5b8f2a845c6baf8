#!/usr/bin/env python3
"""Variants of scenes/implicit-surfaces.json, one thing removed or replaced in
each, for finding where the scene's time goes (docs/results.md, "Where
implicit-surfaces' time goes"): the floor plane as a quad of triangles, the
glass ball Lambertian, only the analytic kinds, no point light, the room
alone. Usage: scripts/implicit_variants.py OUT_DIR; then render each file
with `penumbra render --scene OUT_DIR/NAME.json` (scripts/realtime_bench.sh's
settings)."""
import copy
import json
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
ANALYTIC = {"plane", "sphere", "box"}


def analytic(s):
    s["implicits"] = [o for o in s["implicits"] if o["kind"] in ANALYTIC]


def floor_quad(s):
    s["implicits"] = [o for o in s["implicits"] if o["kind"] != "plane"]
    s["meshes"].append({"name": "floor quad", "material": "floor",
                        "quads": [[[-50, 0, 50], [50, 0, 50], [50, 0, -50], [-50, 0, -50]]]})


def lambert_glass(s):
    s["materials"]["glass"] = {"model": "lambert", "albedo": [0.73, 0.73, 0.73]}


def no_point_light(s):
    s["lights"] = []


def plane_only(s):
    s["implicits"] = [o for o in s["implicits"] if o["kind"] == "plane"]


def room(s):
    s["implicits"] = []


VARIANTS = {
    "imp-full": [],
    "imp-full-floorquad": [floor_quad],
    "imp-full-lambertglass": [lambert_glass],
    "imp-analytic": [analytic],
    "imp-analytic-floorquad": [analytic, floor_quad],
    "imp-analytic-lambertglass": [analytic, lambert_glass],
    "imp-analytic-nopoint": [analytic, no_point_light],
    "imp-analytic-floorquad-nopoint": [analytic, floor_quad, no_point_light],
    "imp-planeonly": [plane_only],
    "imp-room-floorquad": [room, floor_quad],
    "imp-room-floorquad-nopoint": [room, floor_quad, no_point_light],
    "imp-room": [room],
}


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: implicit_variants.py OUT_DIR")
    out = pathlib.Path(sys.argv[1])
    out.mkdir(parents=True, exist_ok=True)
    base = json.loads((ROOT / "scenes" / "implicit-surfaces.json").read_text())
    for name, edits in VARIANTS.items():
        s = copy.deepcopy(base)
        for edit in edits:
            edit(s)
        s["name"] = name
        (out / f"{name}.json").write_text(json.dumps(s, indent=1))
        print(out / f"{name}.json")


if __name__ == "__main__":
    main()
