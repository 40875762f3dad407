#!/usr/bin/env bash
# frontpack developer entry point: installs what is missing, configures, builds, runs.
#
#   tools/dev.sh demo   install packages, build (Release), fill a bundled shape (CSV + SVG in build/)
#   tools/dev.sh test   install packages, build, run the whole test suite under AddressSanitizer +
#                       UndefinedBehaviorSanitizer (Clang), in Release, and in Release built with
#                       Clang (the pinned packings must come out the same bits), then run each fuzz
#                       target, from the sanitizer build, for FRONTPACK_FUZZ_SECONDS (default 20)
#                       (what CI runs)
#   tools/dev.sh build  install packages and build (Release) only
#   tools/dev.sh fuzz [SECONDS]  build the libFuzzer programs (Clang) and run each target
#
# Works on a fresh Debian bookworm machine as root (or with sudo), and again incrementally.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

packages=(
  g++ cmake ninja-build pkg-config
  libcgal-dev libboost-dev libgmp-dev libmpfr-dev
  libgtest-dev libgmock-dev libbenchmark-dev libcli11-dev
  libcairo2-dev nlohmann-json3-dev
  libgdal-dev libdxflib-dev
  # the Python module (python/), for Debian's /usr/bin/python3
  pybind11-dev python3-dev python3-numpy
)
# The programs that read our files back in the real-reader tests (tests/readers/) and run the
# simulator decks (LAMMPS, LIGGGHTS, Yade; shapely checks the final positions), and ezdxf for
# the CAD tests' exact check (tests/cad/) and ogr2ogr for their fixtures: `test` only.
# The Python module's tests (python/tests/): pytest, shapely domains, the progress bar, the example's plot.
test_packages=(lammps liggghts python3 python3-vtk9 python3-shapely yade python3-ezdxf gdal-bin
  python3-pytest python3-tqdm python3-matplotlib)
# libFuzzer: Clang and its runtime (`fuzz`, and `test`, which fuzzes each target for a while).
fuzz_packages=(clang libclang-rt-14-dev)
fuzz_targets=(wkt fill disks dxf)

install_packages() {
  local missing=()
  for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "==> installing Debian packages: ${missing[*]}"
  local sudo=()
  if [ "$(id -u)" != 0 ]; then
    command -v sudo >/dev/null || { echo "error: need root (or sudo) to install: ${missing[*]}" >&2; exit 1; }
    sudo=(sudo)
  fi
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -q
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}"
}

build() {  # $1 = configure preset, $2 = build preset (default: the same name)
  echo "==> configuring and building (${2:-$1})"
  cmake --preset "$1" >/dev/null
  cmake --build --preset "${2:-$1}"
}

run_tests() {  # $1 = preset
  echo "==> testing ($1)"
  ctest --preset "$1"
}

# Runs every fuzz target for $1 seconds, from the committed seed corpus and regressions (read
# only) plus a working corpus in build/fuzz/corpus. A crash, a sanitizer report, an input slower
# than 30 s or above 4 GB stops the run with the input saved in build/fuzz/findings/<target>/:
# commit it to tests/fuzz/regressions/<target>/ under a name that says what it found.
run_fuzzers() {
  # The fuzz programs come from the sanitizer build (the `asan` configure preset, of which the
  # `fuzz` build preset builds only them): the library is compiled once for the tests and for them.
  build asan fuzz
  for t in "${fuzz_targets[@]}"; do
    mkdir -p "build/fuzz/corpus/$t" "build/fuzz/findings/$t"
    echo "==> fuzzing $t for $1 s"
    local rc=0
    "build/asan/tests/fuzz/fuzz_$t" -max_total_time="$1" -timeout=30 -rss_limit_mb=4096 -print_final_stats=1 \
      -artifact_prefix="build/fuzz/findings/$t/" "build/fuzz/corpus/$t" "tests/fuzz/corpus/$t" \
      "tests/fuzz/regressions/$t" > "build/fuzz/findings/$t.log" 2>&1 || rc=$?
    grep -E '^(stat::|==|SUMMARY|frontpack fuzz|artifact|INFO: +[0-9]+ files found)' "build/fuzz/findings/$t.log" || true
    if [ "$rc" -ne 0 ]; then
      tail -n 40 "build/fuzz/findings/$t.log" >&2
      echo "error: fuzz_$t failed (exit $rc; log and inputs in build/fuzz/findings/)" >&2
      exit 1
    fi
  done
}

case "${1:-}" in
  demo)
    install_packages
    build release
    shape="${2:-shapes/concave_polygon.wkt}"
    build/release/tools/frontpack info "$shape"
    echo "==> build/release/tools/frontpack fill $shape --radius uniform:0.004,0.02 -o build/demo.csv -o build/demo.svg"
    build/release/tools/frontpack fill "$shape" --radius uniform:0.004,0.02 -o build/demo.csv -o build/demo.svg
    ;;
  build)
    install_packages
    build release
    ;;
  test)
    packages+=("${test_packages[@]}" "${fuzz_packages[@]}")
    install_packages
    export FRONTPACK_REQUIRE_READERS=1  # a reader test may not skip here
    build asan
    run_tests asan
    build release
    run_tests release
    build clang
    run_tests clang
    run_fuzzers "${FRONTPACK_FUZZ_SECONDS:-20}"
    ;;
  fuzz)
    packages+=("${fuzz_packages[@]}")
    install_packages
    run_fuzzers "${2:-60}"
    ;;
  *)
    sed -n '2,11p' "$0" | sed 's/^# \{0,1\}//'
    exit 1
    ;;
esac
