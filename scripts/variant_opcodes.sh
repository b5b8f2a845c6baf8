#!/usr/bin/env bash
# What an effect variant of the path tracer compiles to, opcode by opcode:
# compiles shaders/stages/path_trace.rgen of two source trees for each
# effect mask (-DPT_EFFECTS=M, as the build does), optimises both with
# spirv-opt -O (debug names stripped), and prints the opcodes whose counts
# differ. Nothing printed under a mask: the same instructions in both trees,
# so a change costs that variant nothing (docs/results.md).
#   scripts/variant_opcodes.sh OLD_TREE NEW_TREE MASK...
# e.g. git worktree add /tmp/old 117764f && scripts/variant_opcodes.sh /tmp/old . 0 261 287
set -euo pipefail
old=$1 new=$2
shift 2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
printf '#version 460\n#extension GL_GOOGLE_include_directive : require\n#include "prelude.glsl"\n#include "path_trace.rgen"\n' >"$work/entry.glsl"
histogram() {  # tree mask -> "count opcode" lines
  local root=$1 mask=$2 out="$work/$RANDOM.spv"
  glslangValidator --target-env vulkan1.2 -S rgen -DPT_STAGE_RAY_TRACING=1 -DPT_EFFECTS="$mask" \
    -I"$root/shaders/stages" -I"$root/shaders/shared" -I"$root/shaders/glsl" --quiet \
    -o "$out" "$work/entry.glsl"
  spirv-opt -O --strip-debug "$out" -o "$out"
  spirv-dis --raw-id "$out" | sed -E 's/^ *%[0-9a-zA-Z_]+ = //' | awk '{print $1}' | sort | uniq -c
}
for mask in "$@"; do
  echo "== effects $mask"
  diff <(histogram "$old" "$mask") <(histogram "$new" "$mask") | grep '^[<>]' || true
done
