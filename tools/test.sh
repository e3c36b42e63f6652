#!/usr/bin/env bash
# Sets up (tools/setup.sh) and runs the whole test suite with ctest. Safe to run again.
# assimp-testmodels: the model files assimp's own tests use, read by ModelFormats.AssimpTestModels.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/tools/setup.sh"
if ! dpkg-query -W -f='${Status}' assimp-testmodels 2>/dev/null | grep -q "install ok installed"; then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  echo "test: installing assimp-testmodels"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq assimp-testmodels >/dev/null
fi
cd "$root/build"
ctest --output-on-failure -j 2
