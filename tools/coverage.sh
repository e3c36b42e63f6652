#!/usr/bin/env bash
# Line coverage of src/ and include/ by the test suite: builds with gcc --coverage (-O0) in its
# own folder, runs ctest one test at a time (parallel runs of the same binaries can garble the
# .gcda counters), and prints gcovr's table with the lines no test reaches. Installs gcovr
# when missing. Not part of CI: it is a tool for finding untested code.
#   tools/coverage.sh            ZRENDER_COVERAGE_BUILD (default build-cov) holds the build
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${ZRENDER_COVERAGE_BUILD:-$root/build-cov}

if ! command -v gcovr >/dev/null; then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq gcovr >/dev/null
fi
if [[ ! -f $build/build.ninja ]]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS="--coverage -O0" \
    -DCMAKE_EXE_LINKER_FLAGS=--coverage -DCMAKE_SHARED_LINKER_FLAGS=--coverage \
    -DCMAKE_MODULE_LINKER_FLAGS=--coverage >/dev/null
fi
ninja -C "$build" >/dev/null
find "$build" -name '*.gcda' -delete
# HardOutput.ExistingOutputIsReplacedOnlyByACompleteFile caps the child's file size, so gcov
# cannot write its counters and prints errors where the test expects one error line.
(cd "$build" && ctest -j1 -E 'ExistingOutputIsReplacedOnlyByACompleteFile' | tail -3)
gcovr -r "$root" --filter "$root/src/" --filter "$root/include/" --object-directory "$build" "$build"
