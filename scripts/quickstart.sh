#!/usr/bin/env bash
# Quick start on a fresh Debian 12 machine.
#   scripts/quickstart.sh        install what is missing, build the tool (Release), run it on bundled data
#   scripts/quickstart.sh test   same set-up, then run every test; then build the sanitized
#                                subset and the readers' fuzzer with clang (build-san/) and run them
set -euo pipefail
cd "$(dirname "$0")/.."
mode=${1:-demo}

packages=(g++ make cmake libcgal-dev libgmp-dev libmpfr-dev libboost-dev libeigen3-dev libtbb-dev catch2 python3)
# test: clang and its runtime libraries with AddressSanitizer, UBSan and libFuzzer; pybind11,
# numpy and pytest for the Python module's tests; Doxygen for the reference manual's check;
# Open MPI for the tool's MPI build (mpirun -np 2 against one process)
[ "$mode" = test ] && packages+=(clang libclang-rt-14-dev pybind11-dev python3-dev python3-numpy python3-pytest doxygen
                                 libopenmpi-dev openmpi-bin)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "quickstart: installing ${missing[*]}"
  sudo=""
  [ "$(id -u)" = 0 ] || sudo=sudo
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

jobs=$(nproc 2>/dev/null || echo 2)
phase() { echo "quickstart: $1: $(( SECONDS - phase_start )) s"; phase_start=$SECONDS; }
phase_start=$SECONDS
# test: the Python module, the reference manual's check and the MPI build are asked for, so
# that a missing dependency (or an earlier demo configuration without them) fails instead of
# skipping them
extra=()
[ "$mode" = test ] && extra=(-DPMSUM_BUILD_PYTHON=ON -DPMSUM_CHECK_DOCS=ON -DCGAL_PMSUM_WITH_MPI=ON)
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "${extra[@]}" > /dev/null
if [ "$mode" = demo ]; then
  cmake --build build -j "$jobs" --target pmsum_cli   # the demo runs the tool only
else
  cmake --build build -j "$jobs"
fi
phase "Release build"

case "$mode" in
  demo)
    # knot1 (CGAL demo data) + the tetrahedron scaled to 1/32, d = 1% of the sum's diagonal
    build/pmsum sum data/knot1.off data/tetrahedron.off --scale-q 0.03125 -d 0.01 --relative \
      -o knot1_tetrahedron.ply --json knot1_tetrahedron.json
    ;;
  test)
    ctest --test-dir build --output-on-failure -j "$jobs" --timeout 1200
    phase "Release tests"
    # AddressSanitizer + UBSan (-O1, no -g): the pipeline, filters and input checks (Catch2 cases
    # but [long]), the tool's test, the corpus and a 60 s run of the readers' fuzzer; a sanitizer
    # report fails the test.
    cmake -S . -B build-san -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++ -DPMSUM_SANITIZE=ON > /dev/null
    cmake --build build-san -j "$jobs"
    phase "sanitizer build"
    ctest --test-dir build-san --output-on-failure -j "$jobs" --timeout 1200
    phase "sanitized tests and fuzzer"
    ;;
  *)
    echo "usage: scripts/quickstart.sh [demo|test]" >&2
    exit 2
    ;;
esac
