#!/usr/bin/env bash
# Installs the build tree into a temporary prefix (`cmake --install`) and checks
# what a desktop needs is where the FHS puts it (and the manual pages, copyright
# and changelog), that the installed renderer
# renders the installed seed scene, and that the desktop file starts an
# installed program. Usage: check_install.sh BUILD_DIR
set -euo pipefail
build=$1
prefix=$(mktemp -d)
trap 'rm -rf "$prefix"' EXIT
app=io.github.whitted.Whitted

cmake --install "$build" --prefix "$prefix" >/dev/null

missing=0
expect() {
  if [[ ! -e "$prefix/$1" ]]; then
    echo "not installed: $1" >&2
    missing=1
  fi
}
for program in whitted whitted-render whitted-farm whitted-numerics whitted-tradeoff whitted-field; do
  expect "bin/$program"
  expect "share/man/man1/$program.1.gz"
done
expect share/doc/whitted/copyright
expect share/doc/whitted/changelog.gz
expect "share/applications/$app.desktop"
expect "share/metainfo/$app.metainfo.xml"
expect "share/mime/packages/$app.xml"
expect "share/icons/hicolor/scalable/apps/$app.svg"
for size in 16 32 48 64 128 256; do
  expect "share/icons/hicolor/${size}x${size}/apps/$app.png"
done
expect share/whitted/scenes/seed.json
expect share/whitted/scenes/glass.json
expect share/whitted/scenes/field.json
expect share/whitted/scenes/extremes/README.md
((missing == 0)) || exit 1

# A manual page reads as one: its name line, its options, its examples.
page=$(zcat "$prefix/share/man/man1/whitted-render.1.gz")
for part in '^whitted-render \\- render a Whitted scene file to an image' '^\.SH OPTIONS' \
  '^\.SH EXAMPLES' '^\\fB\\-\\-quality\\fR'; do
  grep -Eq "$part" <<<"$page" || { echo "whitted-render(1) lacks $part" >&2; exit 1; }
done

# Nothing of the build's own: no tests, benchmarks or libraries.
extra=$(find "$prefix/bin" -type f ! -name 'whitted*' -printf '%f\n')
[[ -z "$extra" ]] || { echo "installed but not a program of ours: $extra" >&2; exit 1; }

# The PNGs are the sizes their folders say.
size_of() { od -An -tu1 -j16 -N8 "$1" | awk '{print $1*16777216+$2*65536+$3*256+$4, $5*16777216+$6*65536+$7*256+$8}'; }
for size in 16 256; do
  got=$(size_of "$prefix/share/icons/hicolor/${size}x${size}/apps/$app.png")
  [[ "$got" == "$size $size" ]] || { echo "${size}x${size} icon is $got" >&2; exit 1; }
done

exec_line=$(grep '^Exec=' "$prefix/share/applications/$app.desktop")
program=${exec_line#Exec=}
program=${program%% *}
[[ -x "$prefix/bin/$program" ]] || { echo "Exec=$program is not an installed program" >&2; exit 1; }

out="$prefix/seed.png"
"$prefix/bin/whitted-render" "$prefix/share/whitted/scenes/seed.json" -o "$out" \
  --width 64 --height 48 --quiet
[[ -s "$out" ]] || { echo "the installed whitted-render wrote no image" >&2; exit 1; }

# The Python module, where Debian's python3 looks (dist-packages), imports
# from there alone and writes an image through the installed plug-in.
if grep -q '^WHITTED_BUILD_PYTHON:BOOL=ON' "$build/CMakeCache.txt"; then
  package="$prefix/lib/python3/dist-packages/whitted"
  [[ -f "$package/__init__.py" && -f "$package/__init__.pyi" ]] ||
    { echo "the Python package is not installed in $package" >&2; exit 1; }
  (cd "$prefix" && PYTHONPATH="$prefix/lib/python3/dist-packages" /usr/bin/python3 -c "
import whitted
assert whitted.__file__.startswith('$prefix'), whitted.__file__
image = whitted.render(whitted.load('share/whitted/scenes/seed.json'), width=32, height=24)
whitted.write_image(image, 'seed-from-python.png')
")
  [[ -s "$prefix/seed-from-python.png" ]] || { echo "the installed module wrote no image" >&2; exit 1; }
fi
echo "installed into a temporary prefix: programs, desktop file, metadata, MIME type, icons, scenes, the Python module; whitted-render and the module rendered the installed seed scene"
