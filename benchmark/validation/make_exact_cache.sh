#!/usr/bin/env bash
# Computes the exact Nef sums of the small suite cases once and stores them in data/exact/
# (CGAL's exact .nef3 format), where test_validation reads them.
#   benchmark/validation/make_exact_cache.sh [BUILD_DIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
pmsum=${1:-$root/build}/pmsum
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$root/data/exact"

shape() { # a preset name or a file of data/
  case "$1" in
    *.off) echo "$root/data/$1" ;;
    *) "$pmsum" generate "$1" -o "$work/$1.off"; echo "$work/$1.off" ;;
  esac
}
cache() { # P Q: the cached name is P+Q without .off
  local p q name
  p=$(shape "$1"); q=$(shape "$2")
  name="${1%.off}+${2%.off}"
  # d only matters for our side of the validation, not for the exact sum: keep it coarse
  "$pmsum" validate "$p" "$q" -d 0.1 --relative --quiet --save-exact "$root/data/exact/$name.nef3" > "$work/out.txt"
  echo "$name: $(grep -E 'seconds' "$work/out.txt" | sed 's/ \+/ /g')"
}

cache plates cube-small
cache hollow-box cube-large
cache blocks cube
cache blocks cube-0.95
cache hook-a hook-b
cache cross.off star.off
