#!/usr/bin/env bash
# Builds the .deb with CPack into a temporary directory and checks its control
# data and contents: a native build refused, then packed all the same for the
# checks; lintian without errors and the Description as Debian formats it;
# Depends found by dpkg-shlibdeps (Qt, OpenImageIO) plus the SVG plugin, and the
# programs, manual pages, copyright, changelog, desktop file and icons under
# /usr; with the Python module, its files, its Python and NumPy, and that it
# imports.
# Usage: check_deb.sh BUILD_DIR
set -euo pipefail
build=$1
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

# A build for this machine's own CPU is refused, saying why and what to do.
if grep -q '^WHITTED_NATIVE:BOOL=ON' "$build/CMakeCache.txt"; then
  if cpack -G DEB --config "$build/CPackConfig.cmake" -B "$out/refused" >"$out/refused.log" 2>&1; then
    echo "cpack packed a build optimised for this machine's CPU" >&2; exit 1
  fi
  grep -q 'DWHITTED_NATIVE=OFF to package it' "$out/refused.log" ||
    { echo "cpack's refusal does not say what to do:" >&2; cat "$out/refused.log" >&2; exit 1; }
  echo "cpack refuses the native build, saying to configure with -DWHITTED_NATIVE=OFF"
fi
# The contents are checked on this build all the same.
cpack -G DEB --config "$build/CPackConfig.cmake" -B "$out" -D CPACK_WHITTED_ALLOW_NATIVE=ON \
  >"$out/cpack.log" 2>&1 || { cat "$out/cpack.log" >&2; exit 1; }
deb=$(find "$out" -maxdepth 1 -name 'whitted_*.deb' | head -n 1)
[[ -n "$deb" ]] || { echo "cpack made no whitted_*.deb" >&2; cat "$out/cpack.log" >&2; exit 1; }

depends=$(dpkg-deb -f "$deb" Depends)
echo "Depends: $depends"
for lib in libqt6widgets6 'libopenimageio2\.[0-9]' libqt6svg6 'libc6 '; do
  grep -Eq "(^|, )$lib" <<<"$depends" || { echo "Depends lacks $lib" >&2; exit 1; }
done
[[ $(dpkg-deb -f "$deb" Section) == graphics ]] || { echo "Section is not graphics" >&2; exit 1; }
[[ $(dpkg-deb -f "$deb" Architecture) == amd64 ]] || { echo "Architecture is not amd64" >&2; exit 1; }

# Debian's own checks: no error; the warnings left are in docs/guide/install.md.
lintian --fail-on error --tag-display-limit 0 "$deb" >"$out/lintian.log" 2>&1 ||
  { echo "lintian finds errors:" >&2; cat "$out/lintian.log" >&2; exit 1; }
echo "lintian: $(grep -c '^W: ' "$out/lintian.log" || true) warnings, no error"
description=$(dpkg-deb -f "$deb" Description)
if grep -q ';' <<<"$description" || awk 'length > 80' <<<"$description" | grep -q .; then
  echo "Description is not as Debian formats it:" >&2; echo "$description" >&2; exit 1
fi

contents=$(dpkg-deb -c "$deb" | awk '{print $6}')
for path in ./usr/bin/whitted ./usr/bin/whitted-render \
  ./usr/share/man/man1/whitted.1.gz ./usr/share/man/man1/whitted-render.1.gz \
  ./usr/share/man/man1/whitted-farm.1.gz ./usr/share/doc/whitted/copyright \
  ./usr/share/doc/whitted/changelog.gz \
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
