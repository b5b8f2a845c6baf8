#!/usr/bin/env bash
# Builds tools/d3d12_repro/mixed_blas_batch.c for Windows (mingw-w64 against
# Debian's DirectX-Headers, as Penumbra's cross build) and its shaders with DXC,
# then runs it under Wine with vkd3d-proton (scripts/wine-d3d12.sh), without and
# with a barrier between the two bottom-level builds. Exit status 0 when both
# runs hit the box.   bash tools/d3d12_repro/run.sh [WORKDIR]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd); root=$(cd "$here/../.." && pwd)
w=${1:-$(mktemp -d)}; mkdir -p "$w/inc"
ln -sfn /usr/include/directx "$w/inc/directx"; ln -sfn /usr/include/dxguids "$w/inc/dxguids"
dxc -T lib_6_3 "$here/mixed_blas_batch.hlsl" -Fo "$w/mixed_blas_batch.dxil" >/dev/null
x86_64-w64-mingw32-gcc-posix -O1 -DUSE_DIRECTX_HEADERS -D__REQUIRED_RPCNDR_H_VERSION__=475 -I"$w/inc" \
  -o "$w/mixed_blas_batch.exe" "$here/mixed_blas_batch.c" -ld3d12 -luuid
status=0
bash "$root/scripts/wine-d3d12.sh" "$w/mixed_blas_batch.exe" "$w/mixed_blas_batch.dxil" || status=1
bash "$root/scripts/wine-d3d12.sh" "$w/mixed_blas_batch.exe" "$w/mixed_blas_batch.dxil" --barrier || status=1
exit $status
