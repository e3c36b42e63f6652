#!/usr/bin/env bash
# Checks an installed and a packaged zrender (docs/design.md, Install): installs build/ into a
# temporary prefix, then from another folder renders a model file to .png, .jpg, a .tif depth
# image and an .mp4, runs `view` under Xvfb for a few frames, checks that the installed program
# reads no settings of the source tree, refers to neither tree, and loads none of OpenCV's
# imgcodecs, videoio, highgui (nor GDAL) at its start but links its core; then builds the .deb (cpack) and checks
# its files and declared dependencies. Run by CI after tools/test.sh.
#   tools/install-test.sh [BUILD]      default build/
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
prefix=$(mktemp -d "${TMPDIR:-/tmp}/zrender-prefix.XXXXXX")
work=$(mktemp -d "${TMPDIR:-/tmp}/zrender-elsewhere.XXXXXX")
trap 'rm -rf "$prefix" "$work"' EXIT
fail() { echo "install-test: error: $*" >&2; exit 1; }

cmake --install "$build" --prefix "$prefix" >/dev/null
z=$prefix/bin/zrender
for f in bin/zrender lib/zrender/libzrender_codecs.so lib/zrender/libzrender_window.so \
  lib/zrender/libzrender_models.so share/doc/zrender/README.md; do
  [ -f "$prefix/$f" ] || fail "not installed: $f"
done
if grep -rlF -e "$root" -e "$build" "$prefix" >/dev/null; then
  fail "installed files refer to the source or build tree: $(grep -rlF -e "$root" -e "$build" "$prefix" | tr '\n' ' ')"
fi

cd "$work"
cp "$root/models/shapes/shapes.obj" .
"$z" shapes.obj -o a.png
"$z" shapes.obj -o a.jpg --depth d.tif
"$z" shapes.obj --turntable 4 -o v.mp4
# A PLY through the assimp plugin: the same ids as the OBJ.
printf 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n' >t.ply
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >t.obj
"$z" t.ply --ids ply-ids.png -o ply.png
"$z" t.obj --ids obj-ids.png -o obj.png
cmp -s ply-ids.png obj-ids.png || fail "a PLY and its OBJ gave different ids"
for f in a.png a.jpg d.tif v.mp4 ply.png; do [ -s "$f" ] || fail "no $f"; done
# The source tree's settings.json names "bunny"; an installed zrender does not read it.
set +e
msg=$("$z" bunny 2>&1)
rc=$?
set -e
[ "$rc" -eq 2 ] || fail "'zrender bunny' outside the tree exited $rc: $msg"
case $msg in *"no settings.json found"*) ;; *) fail "unexpected message: $msg" ;; esac
# The help is captured before grep reads it: `grep -q` stops at its match, and under pipefail a
# zrender still writing would die of SIGPIPE and fail the check.
help=$("$z" --help)
grep -q -- "--settings TEXT *settings file (default: ./settings.json)$" <<<"$help" ||
  fail "--help names a settings file of a tree"
XDG_RUNTIME_DIR=$work xvfb-run -a "$z" view shapes.obj --frames 5 --save-last last.png >/dev/null
[ -s last.png ] || fail "view wrote no last.png"

libs=$(ldd "$z")
grep -q libopencv_core <<<"$libs" || fail "the installed zrender does not link OpenCV's core"
if grep -Ei 'opencv_(imgcodecs|videoio|highgui)|gdal|assimp' <<<"$libs"; then
  fail "the installed zrender links a library it should load only when needed"
fi
echo "install-test: installed into a prefix, rendered .png .jpg .tif .mp4 and a PLY, and ran view from $work"

(cd "$build" && cpack -G DEB >/dev/null)
deb=$(ls -t "$build"/zrender_*.deb | head -1)
files=$(dpkg-deb -c "$deb" | awk '{print $6}')
for f in ./usr/bin/zrender ./usr/lib/zrender/libzrender_codecs.so \
  ./usr/lib/zrender/libzrender_window.so ./usr/lib/zrender/libzrender_models.so \
  ./usr/share/doc/zrender/README.md; do
  grep -qxF "$f" <<<"$files" || fail "$deb lacks $f"
done
depends=$(dpkg-deb -f "$deb" Depends)
for lib in libopencv-imgcodecs libopencv-videoio libopencv-highgui libassimp5 libpng16 libisal2 libjsoncpp libtbb; do
  grep -q "$lib" <<<"$depends" || fail "$deb does not declare $lib: $depends"
done
echo "install-test: $(basename "$deb"): $(wc -l <<<"$files") entries, depends on $(tr ',' '\n' <<<"$depends" | wc -l) packages"
