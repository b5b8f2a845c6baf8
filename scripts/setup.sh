#!/usr/bin/env bash
# Installs every Debian package Penumbra needs to build, test and run on
# Debian 12 (bookworm). Idempotent: packages already present are left alone.
# `setup.sh --render` installs only what building and running the renderer
# needs (README's first command): no viewer, tests, Wine or cross compiler.
#
# bookworm's own Mesa (22.3) has no ray tracing in lavapipe, its Catch2 is
# 2.x and its DirectX-Headers older than the D3D12 backend uses, so those
# three come from bookworm-backports. The backports entry is
# derived from the machine's existing Debian source entry (same archive, same
# keyring) so no archive address is written into this repository.
#
# The Windows cross build's viewer needs GLFW and Dear ImGui compiled for
# Windows; Debian ships them for Linux only, so their Debian SOURCE packages,
# at the versions of the Linux packages (WINDOWS_SOURCES below), are fetched
# from the same archive (a deb-src entry in a temporary apt configuration; the
# system's is left alone; apt checks the files against the signed index) and
# unpacked into $PENUMBRA_WINDOWS_SOURCES (default /usr/local/src/penumbra-deps:
# imgui/, glfw3/ and catch2/, the last for the Windows test executable), where cmake/CrossDependencies.cmake looks for them
# (its PENUMBRA_WINDOWS_SOURCES cache variable). Skipped when already there.
set -euo pipefail
render_only=0
case "${1:-}" in
  --render) render_only=1 ;;
  "") ;;
  *) echo "setup.sh: unknown option '$1' (--render: only what the renderer needs)" >&2; exit 2 ;;
esac

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then SUDO="sudo"; else
    echo "setup.sh: need root or sudo to install packages" >&2; exit 1
  fi
fi

# What building and running the renderer (`penumbra`) needs: the first README
# command installs only these (`setup.sh --render`).
RENDER_PACKAGES=(
  build-essential cmake ninja-build pkg-config git
  libvulkan-dev vulkan-validationlayers vulkan-tools
  glslang-tools glslang-dev spirv-tools
  libspirv-cross-c-shared-dev
  libglm-dev libtinygltf-dev libcli11-dev nlohmann-json3-dev libstb-dev
  libtinyexr-dev libfmt-dev libxxhash-dev
  # glTF's compressed data: EXT_texture_webp, EXT_meshopt_compression,
  # KHR_draco_mesh_compression.
  libwebp-dev libmeshoptimizer-dev libdraco-dev
)
# The rest: the viewer, the tests, the sanitizer build and the Windows cross
# build.
BASE_PACKAGES=(
  "${RENDER_PACKAGES[@]}"
  # Boost.Math's distributions for the sampling tests' chi-square p-values.
  libboost-dev
  # The render farm's tests start a real Slurm controller and node
  # (tests/farm/slurm_cluster.sh), authenticated by munge.
  slurm-wlm munge
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
  # dpkg-source unpacks the viewer's GLFW and Dear ImGui sources for it.
  dpkg-dev
  # The sanitizer build and the fuzz targets (scripts/sanitize.sh): clang
  # with its ASan, UBSan and libFuzzer runtimes.
  clang libclang-rt-dev
  # penumbra study's report: its plots, and the headless browser that
  # tests the page.
  python3-matplotlib chromium
)
BACKPORT_PACKAGES=(mesa-vulkan-drivers catch2 directx-headers-dev)
# Wine runs the cross-built penumbra.exe on D3D12 (vkd3d-proton on lavapipe)
# in the tests; installed with its recommended packages (winevulkan's Vulkan
# loader, the X libraries its display driver opens), as that is what was
# verified.
WINE_PACKAGES=(wine wine64)
# DXC and vkd3d-proton, which Debian does not package: prebuilt from their
# release tags in ../shared/tools/d3d12-on-linux (its README says how), unpacked
# into $PENUMBRA_D3D12_TOOLS; dxc is linked into /usr/local/bin, where the
# Windows build finds it (cmake/Shaders.cmake), and scripts/wine-d3d12.sh takes
# vkd3d-proton's DLLs from there.
D3D12_KIT=${PENUMBRA_D3D12_KIT:-$(cd "$(dirname "$0")/../.." && pwd)/shared/tools/d3d12-on-linux}
D3D12_TOOLS=${PENUMBRA_D3D12_TOOLS:-/usr/local/lib/penumbra}
DXC_ARCHIVE=dxc-1.9.2607-linux-x64.tar.xz
VKD3D_ARCHIVE=vkd3d-proton-3.0.1-win64-dlls.tar.xz
# Source packages for the cross build's viewer and its test executable: the
# versions of bookworm's libimgui-dev and libglfw3-dev and of backports'
# catch2 (source=version, pinned).
WINDOWS_SOURCES=(imgui=1.86+ds-1 glfw3=3.3.8-1 catch2=3.7.1-0.4~bpo12+1)
WINDOWS_SOURCES_DIR=${PENUMBRA_WINDOWS_SOURCES:-/usr/local/src/penumbra-deps}

# debian_archive: sets uri and keyring from the machine's bookworm entry
# (deb822 or one-line form); exits if there is none.
debian_archive() {
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
    echo "setup.sh: no Debian bookworm source entry found to derive $1 from" >&2
    exit 1
  fi
  [ -n "$keyring" ] || keyring=/usr/share/keyrings/debian-archive-keyring.gpg
}

# fetch_windows_sources: downloads and unpacks WINDOWS_SOURCES not yet in
# WINDOWS_SOURCES_DIR at their pinned version (the version is recorded in
# <dir>/<source>/.penumbra-source-version once unpacked).
fetch_windows_sources() {
  local wanted=() spec name version
  for spec in "${WINDOWS_SOURCES[@]}"; do
    name=${spec%%=*} version=${spec#*=}
    if [ "$(cat "$WINDOWS_SOURCES_DIR/$name/.penumbra-source-version" 2>/dev/null)" != "$version" ]; then
      wanted+=("$spec")
    fi
  done
  if [ ${#wanted[@]} -eq 0 ]; then
    echo "setup.sh: Windows viewer sources present in $WINDOWS_SOURCES_DIR"
    return
  fi
  debian_archive "the source packages' archive"
  local tmp
  tmp=$(mktemp -d)
  # shellcheck disable=SC2064  # the directory is known now; tmp is local
  trap "rm -rf '$tmp'" EXIT
  chmod 755 "$tmp"
  mkdir -p "$tmp/lists/partial" "$tmp/cache" "$tmp/download" "$tmp/unpacked"
  # apt downloads as _apt where it can write.
  if id _apt >/dev/null 2>&1 && [ "$(id -u)" -eq 0 ]; then chown _apt "$tmp/download"; fi
  printf 'deb-src [signed-by=%s] %s %s main\n' "$keyring" "$uri" bookworm "$keyring" "$uri" bookworm-backports \
    > "$tmp/sources.list"
  local apt_options=(-o "Dir::Etc::SourceList=$tmp/sources.list" -o Dir::Etc::SourceParts=/dev/null
                     -o "Dir::State::Lists=$tmp/lists" -o "Dir::Cache=$tmp/cache")
  if ! $SUDO apt-get "${apt_options[@]}" update -q ||
     ! (cd "$tmp/download" && $SUDO apt-get "${apt_options[@]}" source --download-only -q "${wanted[@]}"); then
    echo "setup.sh: could not download the Debian source packages ${wanted[*]} from $uri (bookworm and bookworm-backports, deb-src);" \
         "the Windows cross build's viewer is compiled from them" >&2
    exit 1
  fi
  $SUDO mkdir -p "$WINDOWS_SOURCES_DIR"
  for spec in "${wanted[@]}"; do
    name=${spec%%=*} version=${spec#*=}
    # --no-check: apt has checked these files against the archive's signed
    # index (dpkg-source would look for the uploader's key in keyrings this
    # machine does not have).
    $SUDO dpkg-source --no-check -x "$tmp/download/${name}_${version}.dsc" "$tmp/unpacked/$name" >/dev/null ||
      { echo "setup.sh: dpkg-source could not unpack $name $version" >&2; exit 1; }
    echo "$version" | $SUDO tee "$tmp/unpacked/$name/.penumbra-source-version" >/dev/null
    $SUDO rm -rf "${WINDOWS_SOURCES_DIR:?}/$name"
    $SUDO mv "$tmp/unpacked/$name" "$WINDOWS_SOURCES_DIR/$name"
    echo "setup.sh: unpacked $name $version into $WINDOWS_SOURCES_DIR/$name"
  done
}

# install_d3d12_tools: unpacks DXC and vkd3d-proton's DLLs from D3D12_KIT
# into D3D12_TOOLS/<archive name> (skipped when there).
install_d3d12_tools() {
  if [ ! -f "$D3D12_KIT/$DXC_ARCHIVE" ] || [ ! -f "$D3D12_KIT/$VKD3D_ARCHIVE" ]; then
    echo "setup.sh: no DXC/vkd3d-proton kit at $D3D12_KIT: the Windows build will embed no DXIL and the D3D12 tests will report themselves as not run"
    return
  fi
  local archive dir
  for archive in "$DXC_ARCHIVE" "$VKD3D_ARCHIVE"; do
    dir="$D3D12_TOOLS/${archive%.tar.xz}"
    if [ ! -f "$dir/.unpacked" ]; then
      $SUDO rm -rf "$dir"
      $SUDO mkdir -p "$dir"
      $SUDO tar xJf "$D3D12_KIT/$archive" -C "$dir"
      $SUDO touch "$dir/.unpacked"
    fi
  done
  $SUDO ln -sfn "$D3D12_TOOLS/${DXC_ARCHIVE%.tar.xz}/bin/dxc" /usr/local/bin/dxc
  echo "setup.sh: DXC and vkd3d-proton in $D3D12_TOOLS ($(/usr/local/bin/dxc --version 2>/dev/null | head -1))"
}

if [ $render_only = 1 ]; then
  # Mesa's lavapipe (backports) is the renderer's device on a machine without a GPU.
  BASE_PACKAGES=("${RENDER_PACKAGES[@]}")
  BACKPORT_PACKAGES=(mesa-vulkan-drivers)
  WINE_PACKAGES=()
fi
missing=()
for p in "${BASE_PACKAGES[@]}" "${BACKPORT_PACKAGES[@]}" "${WINE_PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# Mesa must be the backports version (25.x); bookworm's 22.3 lacks ray tracing.
mesa_version=$(dpkg-query -W -f='${Version}' mesa-vulkan-drivers 2>/dev/null || true)
case "$mesa_version" in 2[5-9].*|[3-9][0-9].*) ;; *) missing+=(mesa-vulkan-drivers) ;; esac
if [ $render_only = 0 ]; then
  catch_version=$(dpkg-query -W -f='${Version}' catch2 2>/dev/null || true)
  case "$catch_version" in 3.*) ;; *) missing+=(catch2) ;; esac
  # DirectX-Headers 1.614 (backports) for DXR 1.1 declarations; bookworm has 1.606.
  dxh_version=$(dpkg-query -W -f='${Version}' directx-headers-dev 2>/dev/null || true)
  case "$dxh_version" in 1.61[4-9]*|1.6[2-9]*|1.[7-9]*|[2-9].*) ;; *) missing+=(directx-headers-dev) ;; esac
fi

install_packages() {
  backports_file=/etc/apt/sources.list.d/penumbra-bookworm-backports.sources
  if ! grep -rqs "bookworm-backports" /etc/apt/sources.list /etc/apt/sources.list.d/; then
    # Take URI and keyring from the existing bookworm entry.
    debian_archive bookworm-backports
    printf 'Types: deb\nURIs: %s\nSuites: bookworm-backports\nComponents: main\nSigned-By: %s\n' \
      "$uri" "$keyring" | $SUDO tee "$backports_file" >/dev/null
  fi

  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -q
  $SUDO apt-get install -y -q --no-install-recommends "${BASE_PACKAGES[@]}"
  $SUDO apt-get install -y -q --no-install-recommends -t bookworm-backports "${BACKPORT_PACKAGES[@]}"
  if [ ${#WINE_PACKAGES[@]} -gt 0 ]; then $SUDO apt-get install -y -q "${WINE_PACKAGES[@]}"; fi
}

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup.sh: all packages present"
else
  install_packages
fi
if [ $render_only = 0 ]; then
  fetch_windows_sources
  install_d3d12_tools
fi
echo "setup.sh: done"
