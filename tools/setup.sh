#!/usr/bin/env bash
# Prepares a fresh Debian machine for zrender and builds it (Release). Safe to run again:
# installs only missing packages, links only missing models, rebuilds only what changed.
#   tools/setup.sh [PACKAGE...]   install (and the packages named), link models, build into build/
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"

# libopencv-highgui-dev and libx11-dev: the window of `zrender view`; xvfb, xdotool and x11-apps
# (xwd): its tests, which run it on a virtual display, press keys and take screenshots.
# libosmesa6-dev: Mesa's llvmpipe through OSMesa, for tools/llvmpipe/llvmpipe-ref (built only where
# it is found) and its test, Llvmpipe.ImagesAgree.
packages=(g++ cmake ninja-build pkg-config
  libopencv-core-dev libopencv-imgproc-dev libopencv-imgcodecs-dev libopencv-videoio-dev
  libopencv-highgui-dev libx11-dev
  libpng-dev libisal-dev libjsoncpp-dev libgtest-dev libtinyobjloader-dev libcli11-dev libtbb-dev
  libassimp-dev libosmesa6-dev
  xvfb xdotool x11-apps
  "$@")
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  echo "setup: installing ${missing[*]}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}" >/dev/null
fi

mkdir -p models
# The reference models stay out of the history: link them from ../shared/models.
shared="$root/../shared/models"
for model in bunny spot teapot; do
  if [ ! -e "models/$model" ]; then
    if [ ! -d "$shared/$model" ]; then
      echo "setup: error: reference model '$model' not found in $shared" >&2
      exit 2
    fi
    ln -sfn "$(cd "$shared/$model" && pwd)" "models/$model"
  fi
done

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build
