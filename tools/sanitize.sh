#!/usr/bin/env bash
# Builds the test suite and the program it runs with AddressSanitizer and
# UndefinedBehaviorSanitizer (-DZRENDER_SANITIZE=ON; the tests' own code with ASan alone) in its
# own folder, at -O1 -g1 (reports keep
# their source lines; about half the compile time of -O2 -g), and runs the whole suite there;
# any sanitizer report fails its test (the build passes -fno-sanitize-recover=all, so a report
# aborts the process). Warnings are errors here (-DZRENDER_WERROR=ON), so CI fails on a new one.
#   tools/sanitize.sh [CTEST_ARGS...]     e.g. tools/sanitize.sh -R HardFiles
# Environment: ZRENDER_SANITIZE_BUILD (default build-asan), JOBS (default: processor count).
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
build=${ZRENDER_SANITIZE_BUILD:-$root/build-asan}
jobs=${JOBS:-$(nproc)}

if [[ ! -f $build/build.ninja ]]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DCMAKE_UNITY_BUILD=ON \
    -DZRENDER_SANITIZE=ON -DZRENDER_WERROR=ON >/dev/null
fi
ninja -C "$build" zrender_tests

# Reports name the source line; leaks are checked at exit; UBSan prints a stack.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$root/tools/lsan.supp:print_suppressions=0}
cd "$build"
ctest --output-on-failure -j "$jobs" "$@"
