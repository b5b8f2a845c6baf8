#!/usr/bin/env bash
# Installs every Debian package Penumbra needs to build, test and run on
# Debian 12 (bookworm). Idempotent: packages already present are left alone.
#
# bookworm's own Mesa (22.3) has no ray tracing in lavapipe, its Catch2 is
# 2.x and its DirectX-Headers older than the D3D12 backend uses, so those
# three come from bookworm-backports. The backports entry is
# derived from the machine's existing Debian source entry (same archive, same
# keyring) so no archive address is written into this repository.
set -euo pipefail

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then SUDO="sudo"; else
    echo "setup.sh: need root or sudo to install packages" >&2; exit 1
  fi
fi

BASE_PACKAGES=(
  build-essential cmake ninja-build pkg-config git
  libvulkan-dev vulkan-validationlayers vulkan-tools
  glslang-tools glslang-dev spirv-tools
  libspirv-cross-c-shared-dev
  libglm-dev libtinygltf-dev libcli11-dev nlohmann-json3-dev libstb-dev
  libtinyexr-dev libfmt-dev libboost-dev
  clang-format
  # The viewer: GLFW (its native-window header needs Xrandr's), Dear ImGui
  # (core library + backend sources), and a virtual X server for its tests.
  libglfw3-dev libxrandr-dev libimgui-dev xvfb xauth
  # The viewer's on-screen test: xwd captures the window, netpbm compares it;
  # xdotool sends the input tests' keyboard and mouse events.
  x11-apps netpbm xdotool
  # The Windows cross build (scripts/build-windows-cross.sh): compiler, and
  # zlib for tinyexr; DirectX-Headers come from backports below.
  g++-mingw-w64-x86-64-posix libz-mingw-w64-dev
  # penumbra study's report: its plots, and the headless browser that
  # tests the page.
  python3-matplotlib chromium
)
BACKPORT_PACKAGES=(mesa-vulkan-drivers catch2 directx-headers-dev)

missing=()
for p in "${BASE_PACKAGES[@]}" "${BACKPORT_PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# Mesa must be the backports version (25.x); bookworm's 22.3 lacks ray tracing.
mesa_version=$(dpkg-query -W -f='${Version}' mesa-vulkan-drivers 2>/dev/null || true)
case "$mesa_version" in 2[5-9].*|[3-9][0-9].*) ;; *) missing+=(mesa-vulkan-drivers) ;; esac
catch_version=$(dpkg-query -W -f='${Version}' catch2 2>/dev/null || true)
case "$catch_version" in 3.*) ;; *) missing+=(catch2) ;; esac
# DirectX-Headers 1.614 (backports) for DXR 1.1 declarations; bookworm has 1.606.
dxh_version=$(dpkg-query -W -f='${Version}' directx-headers-dev 2>/dev/null || true)
case "$dxh_version" in 1.61[4-9]*|1.6[2-9]*|1.[7-9]*|[2-9].*) ;; *) missing+=(directx-headers-dev) ;; esac

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup.sh: all packages present"
  exit 0
fi

backports_file=/etc/apt/sources.list.d/penumbra-bookworm-backports.sources
if ! grep -rqs "bookworm-backports" /etc/apt/sources.list /etc/apt/sources.list.d/; then
  # Take URI and keyring from the existing bookworm entry (deb822 or one-line form).
  uri="" keyring=""
  for f in /etc/apt/sources.list.d/*.sources; do
    [ -f "$f" ] || continue
    if grep -qE '^Suites:.*\bbookworm\b' "$f"; then
      uri=$(awk '/^URIs:/{print $2; exit}' "$f")
      keyring=$(awk '/^Signed-By:/{print $2; exit}' "$f")
      break
    fi
  done
  if [ -z "$uri" ] && [ -f /etc/apt/sources.list ]; then
    line=$(grep -E '^deb .* bookworm( |$)' /etc/apt/sources.list | head -1 || true)
    uri=$(echo "$line" | sed -E 's/^deb (\[[^]]*\] )?([^ ]+) .*/\2/')
    keyring=$(echo "$line" | sed -nE 's/.*signed-by=([^] ]+).*/\1/p')
  fi
  if [ -z "$uri" ]; then
    echo "setup.sh: no Debian bookworm source entry found to derive bookworm-backports from" >&2
    exit 1
  fi
  [ -n "$keyring" ] || keyring=/usr/share/keyrings/debian-archive-keyring.gpg
  printf 'Types: deb\nURIs: %s\nSuites: bookworm-backports\nComponents: main\nSigned-By: %s\n' \
    "$uri" "$keyring" | $SUDO tee "$backports_file" >/dev/null
fi

export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${BASE_PACKAGES[@]}"
$SUDO apt-get install -y -q --no-install-recommends -t bookworm-backports "${BACKPORT_PACKAGES[@]}"
echo "setup.sh: done"
