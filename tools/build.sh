#!/usr/bin/env bash
# One entry point for a fresh Debian 12 machine:
#   tools/build.sh demo   install packages, build (Release), mesh the bundled molecule
#   tools/build.sh test   install packages, build (Release), run every test: the slow
#                         tests in the Release build, the whole fast suite (CLI, Python,
#                         molmesh-petsc, FETK and package tests too) and the fuzz-corpus
#                         replays in a second build under ASan/UBSan/_GLIBCXX_ASSERTIONS
#                         (build-asan; MOLMESH_SANITIZE=1, the default). MOLMESH_SANITIZE=library
#                         runs every test in Release and then only the library's own tests
#                         under the sanitizers (build-asan-library); 0 every test in Release
#                         and no sanitizer build (docs/testing.md)
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

# Release, in build/. ARGS: more cmake options (the test command's `-DMOLMESH_TESTS_SLOW_ONLY=ON`;
# every other mode builds every test).
build() {
  cmake -S "$here" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release "$@"
  cmake --build "$build_dir" -j "$jobs"
}

# The sanitizer legs (docs/testing.md): a second build with AddressSanitizer,
# UndefinedBehaviorSanitizer and libstdc++ assertions, with clang so the reader fuzz targets
# link libFuzzer; any sanitizer report fails (halt on the first one). Leaks inside Debian
# libraries are suppressed in tools/sanitizers/lsan.supp, nothing else.
#   full (MOLMESH_SANITIZE=1, what `test` runs by default, so CI): everything but benchmarks,
#     in build-asan; runs the fast suite (`ctest -LE slow`: the Python tests, with the
#     shared ASan runtime preloaded into python3, and the fuzz-corpus replays among it).
#     The Release build builds and runs only the rest (the slow tests,
#     MOLMESH_TESTS_SLOW_ONLY), so every test is built for and runs in one build. Both come
#     from the same CMake with the same options but benchmarks and fuzzing, which register
#     no fast test in Release. The bounded libFuzzer runs (`ctest -R '^fuzz_run_'` in
#     build-asan, label slow) are not part of it: 60 s per reader (docs/testing.md).
#   library (MOLMESH_SANITIZE=library): only the library (with the solvers), the tests that
#     need no CLI (target sanitizer_tests: the readers and the stages listed in
#     tests/CMakeLists.txt, _library_stages) and the fuzz targets, in build-asan-library,
#     after every test in Release.
# MOLMESH_SANITIZE=0 skips both and runs every test in Release.
sanitizer_env() {
  export ASAN_OPTIONS="abort_on_error=1:detect_leaks=1:strict_string_checks=1"
  export LSAN_OPTIONS="suppressions=$here/tools/sanitizers/lsan.supp:print_suppressions=0"
  export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
}

sanitizer_configure() {
  local dir="$1"
  # -gline-tables-only: the reports' stacks keep function, file and line (inlined frames
  # too) at a quarter of -g's object size and ~10 % less compile time (session 26); rebuild
  # with -g to step through a finding in gdb.
  local flags="-O1 -gline-tables-only -fno-omit-frame-pointer -fsanitize=address,undefined"
  flags+=" -fno-sanitize-recover=undefined -D_GLIBCXX_ASSERTIONS"
  cmake -S "$here" -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_C_COMPILER=clang-14 -DCMAKE_CXX_COMPILER=clang++-14 \
    -DCMAKE_C_FLAGS_RELWITHDEBINFO="$flags" -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$flags" \
    -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
    -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=address,undefined" \
    -DMOLMESH_BUILD_BENCHMARKS=OFF -DMOLMESH_BUILD_PYTHON=ON -DMOLMESH_FUZZ=ON
}

sanitize_library() {
  local dir="${MOLMESH_ASAN_LIBRARY_BUILD_DIR:-$here/build-asan-library}"
  sanitizer_configure "$dir"
  cmake --build "$dir" -j "$jobs" --target sanitizer_tests
  local start=$SECONDS labels
  labels="$(cat "$dir/sanitizer_test_labels.txt")"  # written by tests/CMakeLists.txt
  (cd "$dir" && sanitizer_env &&
    ctest -L "$labels" --output-on-failure -j "$jobs" --timeout 600)
  echo "molmesh: library sanitizer leg tests took $((SECONDS - start)) s"
}

sanitize_full() {
  local dir="${MOLMESH_ASAN_BUILD_DIR:-$here/build-asan}"
  sanitizer_configure "$dir"
  cmake --build "$dir" -j "$jobs"
  local start=$SECONDS
  (cd "$dir" && sanitizer_env && ctest -LE slow --output-on-failure -j "$jobs" --timeout 1500)
  echo "molmesh: sanitizer leg tests took $((SECONDS - start)) s"
}

install_packages
sanitize="${MOLMESH_SANITIZE:-1}"
if [ "$mode" = test ] && [ "$sanitize" = 1 ]; then
  # The fast suite runs in build-asan only, so the Release build makes just the slow group
  # (and everything that is not a test). There is no slow Python test and build-asan
  # builds and tests the Python module, so the Release build leaves it out.
  build -DMOLMESH_TESTS_SLOW_ONLY=ON -DMOLMESH_BUILD_PYTHON=OFF
else
  build -DMOLMESH_TESTS_SLOW_ONLY=OFF -DMOLMESH_BUILD_PYTHON=ON
fi
case "$mode" in
  build) ;;
  demo)
    out="$build_dir/demo"
    mkdir -p "$out"
    "$here/tools/demo.sh" "$build_dir/tools/molmesh" "$here/examples" "$out"
    ;;
  test)
    release_tests() { (cd "$build_dir" && ctest --output-on-failure -j "$jobs" --timeout 1500 "$@"); }
    case "$sanitize" in
      # The fast suite runs under the sanitizers; the slow group, which would take too
      # long there, runs here.
      1) release_tests -L slow && sanitize_full ;;
      0) release_tests ;;
      library) release_tests && sanitize_library ;;
      *) echo "MOLMESH_SANITIZE: 1, library or 0" >&2; exit 2 ;;
    esac
    ;;
  *) echo "usage: tools/build.sh [demo|test|build]" >&2; exit 2 ;;
esac
