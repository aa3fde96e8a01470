#!/usr/bin/env bash
# Consumer test: installs the package built in BUILD_DIR into a temporary prefix and builds
# test/consumer against it with find_package(CGAL_pmsum); then builds it again with
# add_subdirectory() of the source tree (where tests and tools must stay off). Runs both.
#   run.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
src=$1
build=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# Debug: the consumer's one translation unit compiles fastest without optimisation
cmake --install "$build" --prefix "$work/prefix" > /dev/null
test -x "$work/prefix/bin/pmsum" || { echo "the tool was not installed"; exit 1; }
cmake -S "$src/test/consumer" -B "$work/installed" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Debug \
      -DCGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE=TRUE > /dev/null
cmake --build "$work/installed" > /dev/null
"$work/installed/consumer"
cmake -S "$src/test/consumer" -B "$work/subdir" -DPMSUM_SOURCE_DIR="$src" -DCMAKE_BUILD_TYPE=Debug \
      -DCGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE=TRUE > /dev/null
# the parent's cache keeps its own build type, and the package adds no target of its own to 'all'
grep -q "^CMAKE_BUILD_TYPE:STRING=Debug" "$work/subdir/CMakeCache.txt" || { echo "build type overwritten"; exit 1; }
targets=$(cmake --build "$work/subdir" --target help | grep -c -E "^\.\.\. (pmsum|test_|example_)" || true)
[ "$targets" = 0 ] || { echo "add_subdirectory added $targets targets of the package"; exit 1; }
cmake --build "$work/subdir" > /dev/null
"$work/subdir/consumer"
echo "consumer: find_package and add_subdirectory OK"
