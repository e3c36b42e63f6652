#!/usr/bin/env bash
# Runs each libFuzzer target of fuzz/ for SECONDS seconds, starting from the seed corpus.
#   tools/fuzz.sh SECONDS [TARGET...]      TARGET: obj settings render grid model (default: all five)
# Configures and builds build-fuzz/ with clang (-DZRENDER_FUZZ=ON, -O1 with line tables, as the
# sanitizer builds: about half the compile time of -O2 -g) when needed. The corpus is
# copied to a temporary folder, so new corpus entries stay out of the repository. Prints the
# executions of each target and exits non-zero if any target crashed, hung or broke a contract;
# the input that did it is kept under $ZRENDER_FUZZ_ARTIFACTS (default /tmp/zrender-fuzz-artifacts).
# Environment: ZRENDER_FUZZ_BUILD (build folder), ZRENDER_FUZZ_KEEP=1 keeps the grown corpus,
# ZRENDER_FUZZ_SEED (libFuzzer's -seed; 0, the default, picks one at random; CI fixes it so a
# run explores the same inputs each time).
set -euo pipefail

usage() { echo "usage: $0 SECONDS [obj|settings|render|grid|model ...]" >&2; exit 2; }
[[ $# -ge 1 && $1 =~ ^[0-9]+$ && $1 -gt 0 ]] || usage
seconds=$1
shift
targets=("$@")
[[ ${#targets[@]} -gt 0 ]] || targets=(obj settings render grid model)
for t in "${targets[@]}"; do [[ $t =~ ^(obj|settings|render|grid|model)$ ]] || usage; done

root=$(cd "$(dirname "$0")/.." && pwd)
build=${ZRENDER_FUZZ_BUILD:-$root/build-fuzz}
artifacts=${ZRENDER_FUZZ_ARTIFACTS:-/tmp/zrender-fuzz-artifacts}
mkdir -p "$artifacts"

if [[ ! -f $build/build.ninja ]]; then
  CC=${CC:-clang} CXX=${CXX:-clang++} cmake -S "$root" -B "$build" -G Ninja \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only -DNDEBUG" \
    -DZRENDER_FUZZ=ON -DZRENDER_TESTS=OFF >/dev/null
fi
if ! ninja -C "$build" "${targets[@]/#/fuzz_}" >"$build/fuzz-build.log" 2>&1; then
  tail -30 "$build/fuzz-build.log"
  exit 1
fi

work=$(mktemp -d "${TMPDIR:-/tmp}/zrender-fuzz-run.XXXXXX")
cleanup() { [[ ${ZRENDER_FUZZ_KEEP:-0} == 1 ]] && echo "corpus kept in $work" || rm -rf "$work"; }
trap cleanup EXIT

# One target's run; its one-line report (and the log's tail on a failure) goes to $work/$t.report.
fuzz_one() {
  local t=$1
  local corpus=$work/$t
  mkdir -p "$corpus"
  cp "$root"/fuzz/corpus/"$t"/* "$corpus"/
  local dict=()
  case $t in
    obj)
      dict=(-dict="$root/fuzz/obj.dict")
      # The project's own small models join the seeds (the reference models are too large).
      find -L "$root/models" -name '*.obj' -size -64k -exec cp {} "$corpus"/ \; 2>/dev/null || true
      ;;
    settings) dict=(-dict="$root/fuzz/settings.dict") ;;
    render) dict=(-dict="$root/fuzz/obj.dict") ;;
  esac
  local log=$work/$t.log rc
  set +e
  # -timeout: an input taking over 10 s counts as a hang; -rss_limit_mb: as a memory blow-up.
  # TMPDIR: the targets' scratch files (an .mtl beside the model) stay in the work folder.
  TMPDIR=$work LSAN_OPTIONS=suppressions=$root/tools/lsan.supp:print_suppressions=0 "$build/fuzz/fuzz_$t" "${dict[@]}" -max_total_time="$seconds" -seed="${ZRENDER_FUZZ_SEED:-0}" -timeout=10 -rss_limit_mb=2048 \
    -max_len=8192 -print_final_stats=1 -artifact_prefix="$artifacts/$t-" "$corpus" >"$log" 2>&1
  rc=$?
  set -e
  local execs speed size
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  speed=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
  size=$(find "$corpus" -type f | wc -l)
  if [[ $rc -eq 0 ]]; then
    echo "fuzz_$t: ${execs:-?} executions in ${seconds}s (${speed:-?}/s), corpus $size files, no crash" >"$work/$t.report"
  else
    {
      echo "fuzz_$t: FAILED (exit $rc) after ${execs:-?} executions; log tail:"
      grep -E 'contract broken|ERROR: |SUMMARY|runtime error|Test unit written' "$log" | head -20
      tail -5 "$log"
    } >"$work/$t.report"
  fi
}

# The targets run side by side, as many at once as the machine has processors
# (ZRENDER_FUZZ_JOBS), each single-threaded for its SECONDS; reports in the targets' order.
parallel_jobs=${ZRENDER_FUZZ_JOBS:-$(nproc)}
for t in "${targets[@]}"; do
  while (($(jobs -rp | wc -l) >= parallel_jobs)); do wait -n || true; done
  fuzz_one "$t" &
done
wait
status=0
for t in "${targets[@]}"; do
  cat "$work/$t.report"
  grep -q "^fuzz_$t: FAILED" "$work/$t.report" && status=1
done
exit $status
