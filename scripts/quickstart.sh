#!/usr/bin/env bash
# Quick start on a fresh Debian 12 machine.
#   scripts/quickstart.sh        install what is missing, build (Release), run pmsum on bundled data
#   scripts/quickstart.sh test   same set-up, then run every test
set -euo pipefail
cd "$(dirname "$0")/.."
mode=${1:-demo}

packages=(g++ make cmake libcgal-dev libgmp-dev libmpfr-dev libboost-dev libeigen3-dev libtbb-dev catch2 python3)
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
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build build -j "$jobs"

case "$mode" in
  demo)
    # knot1 (CGAL demo data) + the tetrahedron scaled to 1/32, d = 1% of the sum's diagonal
    build/pmsum sum data/knot1.off data/tetrahedron.off --scale-q 0.03125 -d 0.01 --relative \
      -o knot1_tetrahedron.ply --json knot1_tetrahedron.json
    ;;
  test)
    ctest --test-dir build --output-on-failure -j "$jobs"
    ;;
  *)
    echo "usage: scripts/quickstart.sh [demo|test]" >&2
    exit 2
    ;;
esac
