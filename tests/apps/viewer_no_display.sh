#!/usr/bin/env bash
# Without a display the viewer says so in one line and exits non-zero.
set -u
viewer="$1"
err=$(mktemp)
trap 'rm -f "$err"' EXIT
env -u DISPLAY -u WAYLAND_DISPLAY "$viewer" --scene cornell-box >/dev/null 2>"$err"
status=$?
cat "$err"
[ "$status" -ne 0 ] || { echo "expected a non-zero exit without a display" >&2; exit 1; }
[ "$(wc -l < "$err")" -eq 1 ] || { echo "expected exactly one line on stderr" >&2; exit 1; }
grep -q "^error: cannot open a window: no display (DISPLAY and WAYLAND_DISPLAY are unset)$" "$err"
