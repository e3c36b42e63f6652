#!/usr/bin/env bash
# Builds everything with ThreadSanitizer (-DZRENDER_TSAN=ON) in its own folder and runs the
# tests of the code that runs on several threads (the thread-count identity tests, PNG encoding,
# the command line with --threads, a turntable's frames at once, jobs side by side, and the OBJ
# parse in parts); a data race reported there fails the test.
#   tools/tsan.sh [CTEST_ARGS...]
# Environment: ZRENDER_TSAN_BUILD (default build-tsan), JOBS (default: processor count).
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
build=${ZRENDER_TSAN_BUILD:-$root/build-tsan}
jobs=${JOBS:-$(nproc)}

if [[ ! -f $build/build.ninja ]]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DZRENDER_TSAN=ON \
    >/dev/null
fi
ninja -C "$build"

# oneTBB's scheduler is not built with ThreadSanitizer: its suppressions file names the
# library, whose own synchronisation ThreadSanitizer cannot see.
export TSAN_OPTIONS=${TSAN_OPTIONS:-halt_on_error=1:second_deadlock_stack=1:ignore_noninstrumented_modules=1:suppressions=$root/tools/tsan.supp}
cd "$build"
ctest --output-on-failure -j "$jobs" -R 'ThreadCounts|ThreadsOption|TurntableThreads|PngWriter|SideBySide|SceneFiles|FrameMemory|ObjParser' "$@"
