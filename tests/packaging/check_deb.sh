#!/usr/bin/env bash
# Builds the .deb with CPack into a temporary directory and checks its control
# data and contents: Depends found by dpkg-shlibdeps (Qt, OpenImageIO) plus the
# SVG plugin, and the programs, desktop file and icons under /usr; with the
# Python module, its files, its Python and NumPy, and that it imports.
# Usage: check_deb.sh BUILD_DIR
set -euo pipefail
build=$1
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

cpack -G DEB --config "$build/CPackConfig.cmake" -B "$out" >"$out/cpack.log" 2>&1 ||
  { cat "$out/cpack.log" >&2; exit 1; }
deb=$(find "$out" -maxdepth 1 -name 'whitted_*.deb' | head -n 1)
[[ -n "$deb" ]] || { echo "cpack made no whitted_*.deb" >&2; cat "$out/cpack.log" >&2; exit 1; }

depends=$(dpkg-deb -f "$deb" Depends)
echo "Depends: $depends"
for lib in libqt6widgets6 'libopenimageio2\.[0-9]' libqt6svg6 'libc6 '; do
  grep -Eq "(^|, )$lib" <<<"$depends" || { echo "Depends lacks $lib" >&2; exit 1; }
done
[[ $(dpkg-deb -f "$deb" Section) == graphics ]] || { echo "Section is not graphics" >&2; exit 1; }
[[ $(dpkg-deb -f "$deb" Architecture) == amd64 ]] || { echo "Architecture is not amd64" >&2; exit 1; }

contents=$(dpkg-deb -c "$deb" | awk '{print $6}')
for path in ./usr/bin/whitted ./usr/bin/whitted-render \
  ./usr/share/applications/io.github.whitted.Whitted.desktop \
  ./usr/share/icons/hicolor/scalable/apps/io.github.whitted.Whitted.svg \
  ./usr/share/whitted/scenes/seed.json ./usr/lib/whitted/whitted_oiio.so; do
  grep -qxF "$path" <<<"$contents" || { echo "the package lacks $path" >&2; exit 1; }
done
if ! grep -q '^WHITTED_BUILD_PYTHON:BOOL=ON' "$build/CMakeCache.txt"; then
  echo "$(basename "$deb"): Depends from the shared libraries, programs, image plug-in, desktop file, icons and scenes under /usr"
  exit 0
fi
for path in ./usr/lib/python3/dist-packages/whitted/__init__.py \
  ./usr/lib/python3/dist-packages/whitted/__init__.pyi \
  "./usr/lib/python3/dist-packages/whitted/$(basename "$build"/python/whitted/_whitted.*.so)"; do
  grep -qxF "$path" <<<"$contents" || { echo "the package lacks $path" >&2; exit 1; }
done
for lib in 'python3-numpy' 'python3 '; do
  grep -Eq "(^|, )$lib" <<<"$depends, " || { echo "Depends lacks $lib" >&2; exit 1; }
done
# The package's Python module, unpacked, imports with Debian's python3 and
# writes an image through the package's own plug-in.
dpkg-deb -x "$deb" "$out/root"
(cd "$out" && PYTHONPATH="$out/root/usr/lib/python3/dist-packages" /usr/bin/python3 -c "
import whitted
assert whitted.__file__.startswith('$out/root/'), whitted.__file__
scene = whitted.load('root/usr/share/whitted/scenes/seed.json')
whitted.write_image(whitted.render(scene, width=32, height=24), 'seed-from-the-deb.png')
")
[[ -s "$out/seed-from-the-deb.png" ]] || { echo "the packaged module wrote no image" >&2; exit 1; }
echo "$(basename "$deb"): Depends from the shared libraries, programs, image plug-in, Python module (imported from the unpacked package), desktop file, icons and scenes under /usr"
