#!/usr/bin/env bash
# One entry point for a fresh Debian 12 machine:
#   tools/build.sh demo   install packages, build (Release), mesh the bundled molecule
#   tools/build.sh test   install packages, build (Release), run every test (slow ones too)
#   tools/build.sh build  install packages and build only
# Re-running is cheap: apt skips what is installed and the build is incremental.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
mode="${1:-demo}"
build_dir="${MOLMESH_BUILD_DIR:-$here/build}"
jobs="$(nproc)"

install_packages() {
  mapfile -t wanted < <(grep -v '^\s*#' "$here/tools/debian-packages.txt" | grep -v '^\s*$')
  local missing=()
  for p in "${wanted[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  echo "molmesh: installing Debian packages: ${missing[*]}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

build() {
  cmake -S "$here" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release
  cmake --build "$build_dir" -j "$jobs"
}

install_packages
build
case "$mode" in
  build) ;;
  demo)
    out="$build_dir/demo"
    mkdir -p "$out"
    "$here/tools/demo.sh" "$build_dir/tools/molmesh" "$here/examples" "$out"
    ;;
  test)
    cd "$build_dir"
    ctest --output-on-failure -j "$jobs" --timeout 1500
    ;;
  *) echo "usage: tools/build.sh [demo|test|build]" >&2; exit 2 ;;
esac
