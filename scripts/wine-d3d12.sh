#!/usr/bin/env bash
# Runs a Windows program of Penumbra's (penumbra.exe, penumbra-viewer.exe,
# the Windows test executable) under Wine, with vkd3d-proton as its D3D12, on
# the default Vulkan device (lavapipe here; VK_ICD_FILENAMES chooses as for a
# native program):
#   bash scripts/wine-d3d12.sh build-mingw/apps/render/penumbra.exe devices --backend d3d12
# Unix paths in the arguments reach the program through Wine's Z: drive.
#
# The Wine prefix (default build-mingw/wineprefix, or $WINEPREFIX) is made on
# first use, and vkd3d-proton's d3d12.dll and d3d12core.dll are copied into
# its system32, as vkd3d-proton's own setup script does, with a "native"
# override for both. Wine's DXGI needs an X display: Xvfb gives one when
# DISPLAY is not set. The exit status is the program's.
#
# PENUMBRA_VKD3D_PROTON: the folder with vkd3d-proton's x64 DLLs (default:
# where scripts/setup.sh unpacks them).
set -euo pipefail
if [ $# -lt 1 ]; then
  echo "usage: wine-d3d12.sh PROGRAM.exe [ARGS...]" >&2
  exit 2
fi
root=$(cd "$(dirname "$0")/.." && pwd)
vkd3d=${PENUMBRA_VKD3D_PROTON:-/usr/local/lib/penumbra/vkd3d-proton-3.0.1-win64-dlls/x64}
if ! command -v wine >/dev/null 2>&1; then
  echo "wine-d3d12.sh: wine is not installed (scripts/setup.sh installs it)" >&2
  exit 2
fi
for dll in d3d12.dll d3d12core.dll; do
  if [ ! -f "$vkd3d/$dll" ]; then
    echo "wine-d3d12.sh: no vkd3d-proton $dll in $vkd3d (scripts/setup.sh unpacks it from ../shared/tools/d3d12-on-linux; or set PENUMBRA_VKD3D_PROTON)" >&2
    exit 2
  fi
done

export WINEPREFIX=${WINEPREFIX:-$root/build-mingw/wineprefix}
export WINEDEBUG=${WINEDEBUG:--all}
export WINEDLLOVERRIDES="d3d12,d3d12core=n;${WINEDLLOVERRIDES:-}"
export WINE_D3D_CONFIG=renderer=vulkan
# vkd3d-proton's pipeline cache goes into the prefix, not the current folder.
export VKD3D_SHADER_CACHE_PATH=${VKD3D_SHADER_CACHE_PATH:-$WINEPREFIX/vkd3d-proton-cache}
# No Wine dialogs or Mono/Gecko installers in a headless run.
export WINEDLLOVERRIDES="$WINEDLLOVERRIDES;mscoree,mshtml="

# One process makes the prefix; concurrent runs (ctest -j) wait for it.
mkdir -p "$(dirname "$WINEPREFIX")"
(
  flock 9
  system32="$WINEPREFIX/drive_c/windows/system32"
  if [ ! -f "$WINEPREFIX/.penumbra-vkd3d" ] || ! cmp -s "$vkd3d/d3d12.dll" "$system32/d3d12.dll"; then
    wineboot -u >/dev/null 2>&1 || { echo "wine-d3d12.sh: wineboot could not make the prefix $WINEPREFIX" >&2; exit 2; }
    wineserver -w
    cp "$vkd3d/d3d12.dll" "$vkd3d/d3d12core.dll" "$system32/"
    mkdir -p "$VKD3D_SHADER_CACHE_PATH"
    touch "$WINEPREFIX/.penumbra-vkd3d"
  fi
) 9>"$WINEPREFIX.lock"

if [ -n "${DISPLAY:-}" ]; then
  exec wine "$@"
fi
exec xvfb-run -a -s "-screen 0 1280x1024x24" wine "$@"
