#!/usr/bin/env bash
# Builds tools/d3d12_repro/mixed_blas_batch.c for Windows (mingw-w64 against
# Debian's DirectX-Headers, as Penumbra's cross build) and its shaders with DXC,
# then runs it under Wine with vkd3d-proton (scripts/wine-d3d12.sh), without and
# with a barrier after the triangle build. Exit status 0 when both runs hit
# the box, 1 while the run without the barrier misses it (vkd3d-proton 3.0.1
# on lavapipe, Mesa 25.0.7).   bash tools/d3d12_repro/run.sh [WORKDIR]
# The same source builds natively against vkd3d-proton's Linux library, as
# ../shared/tools/d3d12-on-linux/README.md shows for dxr_smoke.c.
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
