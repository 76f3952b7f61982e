#!/bin/bash
# .ci/setup.sh - install what is missing, configure and build.
#
# Sourced by .ci/main and .ci/test. Idempotent: packages are installed only
# when missing (apt-get update runs only then), CMake configures once and
# then builds incrementally. BUILD_DIR and CMAKE_ARGS may be set by callers.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

PACKAGES=(cmake make gcc pkg-config liblua5.4-dev libcairo2-dev libpng-dev
          libfontconfig-dev fonts-dejavu-core libosmesa6-dev libegl-dev libegl-mesa0
          libgl-dev libopengl-dev valgrind libreadline-dev
          libfreetype-dev zlib1g-dev python3-meshio clang parallel chromium
          libmicrohttpd-dev chromium-driver python3-selenium ccache)
# VTK's own readers, which tests/io/vtk_check.py opens lamina's files with
PACKAGES+=(python3-vtk9)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# The compiler cache (ccache) across clean clones on one machine (issue 36
# item 4: the test command's three builds are a quarter of its time): paths
# are made relative to the clone (CCACHE_BASEDIR) and the build directory is
# left out of the hash, so a second clone of a commit compiles only what
# changed. A cold cache builds as before; LAMINA_NO_CCACHE=1 turns it off.
LAMINA_LAUNCHER=()
if [ -z "${LAMINA_NO_CCACHE:-}" ] && command -v ccache >/dev/null; then
  export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=1
  LAMINA_LAUNCHER=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi

lamina_build() {   # lamina_build DIR [cmake args...]
  local dir=$1; shift
  if [ ! -f "$dir/CMakeCache.txt" ]; then
    cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo "${LAMINA_LAUNCHER[@]}" "$@" >/dev/null
  elif [ $# -gt 0 ]; then   # an existing build dir gets the options too (e.g. LAMINA_WERROR)
    cmake -S . -B "$dir" "$@" >/dev/null
  fi
  cmake --build "$dir" -j"$(nproc)" -- --no-print-directory >/dev/null
}
