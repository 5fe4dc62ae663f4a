#!/usr/bin/env bash
# One entry point for a fresh Debian 12 machine:
#   ./build.sh demo   install what is missing, build, render the example scene to build/demo/
#   ./build.sh test   install what is missing, build, run the whole test suite (ctest under Xvfb)
#   ./build.sh build  install what is missing and build only
#   ./build.sh install  build, then cmake --install into PREFIX (/usr/local): python3 -c
#                     "import penumbra" and find_package(Penumbra) work without further setup
#   ./build.sh bench [ARGS]  also matplotlib; build, run the speed-versus-error benchmark into
#                     build/bench/ (results.csv, speed_vs_error.png); ARGS go to PenumbraBench
#   ./build.sh fuzz [SECONDS]  also clang; libFuzzer on the geometry core for SECONDS (600) in
#                     build-fuzz/ (corpus/, artifacts/); see Documentation/fuzzing.md
#   ./build.sh load [ARGS]  build, run the load test (1000 actors, 8 lights, a 4M-triangle mesh)
#                     into build/load/ (load.csv, one PNG per scene); ARGS go to PenumbraLoad
set -euo pipefail
cd "$(dirname "$0")"
ROOT=$PWD
BUILD_DIR=${BUILD_DIR:-$ROOT/build}
JOBS=${JOBS:-$(nproc)}

PACKAGES=(build-essential cmake libvtk9-dev python3-vtk9 libglm-dev libembree-dev
          xvfb xauth python3-numpy libpolyclipping-dev libcgal-dev libmpfr-dev python3-vedo
          clang-format)
# Only the benchmark needs these (its plot).
BENCH_PACKAGES=(python3-matplotlib)
# Only the libFuzzer run needs these (Clang and its fuzzer and sanitizer runtimes).
FUZZ_PACKAGES=(clang libclang-rt-14-dev)
FUZZ_DIR=${FUZZ_DIR:-$ROOT/build-fuzz}

install_missing() {
  local missing=()
  for p in "${PACKAGES[@]}"; do
    dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "== installing: ${missing[*]}"
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}"
}

# A tree configured before keeps its configuration (a developer's Debug tree stays Debug).
configure_and_build() {
  if [ -f "$BUILD_DIR/CMakeCache.txt" ]; then
    cmake -S "$ROOT" -B "$BUILD_DIR" >/dev/null
  else
    cmake -S "$ROOT" -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release \
      -DPython3_EXECUTABLE=/usr/bin/python3 >/dev/null
  fi
  cmake --build "$BUILD_DIR" -j "$JOBS"
}

# Whether installing into $1 needs root: its nearest existing folder is not writable.
needs_root() {
  local dir=$1
  while [ ! -d "$dir" ]; do dir=$(dirname "$dir"); done
  [ ! -w "$dir" ]
}

# libFuzzer on Penumbra::Geometry for $1 seconds, in its own Clang build tree; the seed corpus
# is copied so that what the run learns stays out of the source tree. Exits non-zero on a crash.
run_fuzzer() {
  local seconds=$1
  PACKAGES+=("${FUZZ_PACKAGES[@]}")
  install_missing
  CC=clang CXX=clang++ cmake -S "$ROOT" -B "$FUZZ_DIR" -DCMAKE_BUILD_TYPE=Release \
    -DPython3_EXECUTABLE=/usr/bin/python3 -DPENUMBRA_ENABLE_FUZZING=ON -DBUILD_TESTING=ON >/dev/null
  cmake --build "$FUZZ_DIR" -j "$JOBS" --target penumbraGeometryFuzzer
  mkdir -p "$FUZZ_DIR/corpus" "$FUZZ_DIR/artifacts"
  cp "$ROOT"/Testing/Fuzz/corpus/* "$FUZZ_DIR/corpus/"
  echo "== fuzzing the geometry core for $seconds s (crashes go to $FUZZ_DIR/artifacts/)"
  "$FUZZ_DIR/bin/penumbraGeometryFuzzer" "$FUZZ_DIR/corpus" -max_total_time="$seconds" \
    -timeout=10 -rss_limit_mb=2048 -max_len=4096 -print_final_stats=1 \
    -artifact_prefix="$FUZZ_DIR/artifacts/"
}

# Debian's VTK talks to X only: every render runs under a virtual display.
with_display() {
  if [ -n "${DISPLAY:-}" ]; then "$@"; else xvfb-run -a -s "-screen 0 1920x1080x24" "$@"; fi
}

cmd=${1:-}
case "$cmd" in
  build)
    install_missing; configure_and_build ;;
  demo)
    install_missing; configure_and_build
    mkdir -p "$BUILD_DIR/demo"
    with_display "$BUILD_DIR/bin/PenumbraDemo" --output "$BUILD_DIR/demo" ;;
  test)
    install_missing; configure_and_build
    cd "$BUILD_DIR"
    with_display ctest --output-on-failure -j "$JOBS"
    # Then a bounded libFuzzer run on the geometry core (FUZZ_SECONDS=0 skips it).
    if [ "${FUZZ_SECONDS:-60}" -gt 0 ]; then run_fuzzer "${FUZZ_SECONDS:-60}"; fi ;;
  bench)
    shift
    PACKAGES+=("${BENCH_PACKAGES[@]}")
    install_missing; configure_and_build
    mkdir -p "$BUILD_DIR/bench"
    with_display "$BUILD_DIR/bin/PenumbraBench" --output "$BUILD_DIR/bench" "$@" ;;
  install)
    # Libraries, headers, the CMake package and the Python package under PREFIX (/usr/local),
    # where Debian's python3 and find_package(Penumbra) find them.
    # The InstalledPackage test runs this into a prefix of its own.
    install_missing; configure_and_build
    prefix=${PREFIX:-/usr/local}
    sudo=""
    needs_root "$prefix" && [ "$(id -u)" -ne 0 ] && sudo="sudo"
    $sudo cmake --install "$BUILD_DIR" --prefix "$prefix" ;;
  fuzz)
    run_fuzzer "${2:-600}" ;;
  load)
    shift
    install_missing; configure_and_build
    mkdir -p "$BUILD_DIR/load"
    with_display "$BUILD_DIR/bin/PenumbraLoad" --output "$BUILD_DIR/load" "$@" ;;
  *)
    echo "usage: $0 {demo|test|build|install|bench [PenumbraBench options]|fuzz [SECONDS]|load [PenumbraLoad options]}" >&2; exit 2 ;;
esac
