#!/usr/bin/env bash
# The study report (scripts/study_report.py) from a fixed study
# (tests/data/study: a 24x24 Cornell box study's results and previews, bsdf
# and mis with both samplers),
# opened in a real headless browser: the page loads, every image resolves,
# the techniques table has one row per technique of the CSV and the points
# table one per (technique, spp).
set -eu
root="$(cd "$(dirname "$0")/../.." && pwd)"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp -r "$root/tests/data/study" "$work/s"
# Debian's interpreter, which has python3-matplotlib (a python3 earlier on
# PATH may not).
python=/usr/bin/python3
[ -x "$python" ] || python=python3
"$python" "$root/scripts/study_report.py" "$work/s"
[ -s "$work/s/error_vs_time.png" ] && [ -s "$work/s/error_vs_spp.png" ]
chromium --headless --no-sandbox --disable-gpu --virtual-time-budget=10000 \
  --dump-dom "file://$work/s/report.html" 2>/dev/null >"$work/dom.html"
images=$(sed -nE 's/.*<body data-images="([0-9]+)" data-images-loaded="([0-9]+)".*/\1 \2/p' "$work/dom.html")
echo "images (in the page, loaded): $images"
set -- $images
[ "${1:-0}" -ge 3 ] && [ "$1" = "$2" ]
# Columns by their header names, so a new column does not shift them.
csv_columns() {
  awk -F, -v names="$1" 'NR == 1 { n = split(names, want, ","); for (i = 1; i <= NF; i++) col[$i] = i; next }
    { line = $col[want[1]]; for (k = 2; k <= n; k++) line = line "," $col[want[k]]; print line }' \
    "$work/s/results.csv" | sort -u | wc -l
}
techniques=$(csv_columns technique)
points=$(csv_columns technique,spp)
table_rows() {  # rows of the table with this id, the header row excluded
  sed -n "/<table id=\"$1\"/,/<\/table>/p" "$work/dom.html" | grep -c "<tr><td>"
}
echo "techniques: CSV $techniques, table $(table_rows techniques); points: CSV $points, table $(table_rows points)"
[ "$(table_rows techniques)" = "$techniques" ]
[ "$(table_rows points)" = "$points" ]
grep -q "<p id=\"answer\">Within 33.3 ms the lowest error is <b>" "$work/dom.html"
