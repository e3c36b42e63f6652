#!/usr/bin/env bash
# Sets up (tools/setup.sh) and runs the whole test suite with ctest. Safe to run again.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/tools/setup.sh"
cd "$root/build"
ctest --output-on-failure -j 2
