#!/usr/bin/env bash
# Builds with ThreadSanitizer (-DZRENDER_TSAN=ON, -O1 -g1) in its own folder the tests of the code
# that runs on several threads (the thread-count identity tests, PNG encoding, the command line
# with --threads, a turntable's frames at once, jobs side by side, the OBJ parse in parts, the
# transform's chunks, and the bands' order: the files tests/CMakeLists.txt keeps for this build),
# and runs them; a data race reported there fails the test.
#   tools/tsan.sh [CTEST_ARGS...]
# Environment: ZRENDER_TSAN_BUILD (default build-tsan), JOBS (default: processor count).
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
build=${ZRENDER_TSAN_BUILD:-$root/build-tsan}
jobs=${JOBS:-$(nproc)}

if [[ ! -f $build/build.ninja ]]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DCMAKE_UNITY_BUILD=ON \
    -DZRENDER_TSAN=ON >/dev/null
fi
ninja -C "$build" zrender_tests

# oneTBB's scheduler is not built with ThreadSanitizer: its suppressions file names the
# library, whose own synchronisation ThreadSanitizer cannot see. report_atomic_races=0: a
# loop's wait counter lives on the calling thread's stack, a worker decrements it atomically
# (inline oneTBB code) after the task's last TaskEdges mark, and the caller sees it inside the
# library; the caller's later writes to that stack were reported as races with it. Our own
# code mixes no atomic and plain accesses to one variable. history_size=7 (the most): a
# worker's plain read of that stack in oneTBB's inline code (fold_tree), old by the time the
# caller's stack reuse was reported, came without its stack trace, which the suppressions then
# could not match (1 run in about 70, 2026-11-26).
export TSAN_OPTIONS=${TSAN_OPTIONS:-halt_on_error=1:second_deadlock_stack=1:ignore_noninstrumented_modules=1:report_atomic_races=0:history_size=7:suppressions=$root/tools/tsan.supp}
cd "$build"
ctest --output-on-failure -j "$jobs" "$@"
