#!/usr/bin/env bash
# Installs the Debian 12 packages the project needs (only those missing), then
# configures (Release, Ninja) and builds into build/ at the repository root.
# Safe to re-run: installed packages are skipped and the build is incremental.
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."

packages=(
  cmake ninja-build g++ pkg-config
  libopenimageio-dev libpng-dev libopenexr-dev libglm-dev nlohmann-json3-dev libsimdjson-dev libcli11-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  # division by a render's sample count without a division instruction
  libdivide-dev
  # the Qt6 editor, and running it headless in tests
  qt6-base-dev xvfb xauth x11-utils imagemagick
  # scripts/screenshot.sh --precision-view opens the dock with a key press
  xdotool
  # SVG icons at run time (Qt's SVG plugins), the icon's PNG sizes at build time
  libqt6svg6 librsvg2-bin
  # the programs' manual pages, made at build time from their --help
  help2man
  # the packaging tests: desktop file, AppStream and MIME checks, the .deb's
  # Depends from dpkg-shlibdeps, Debian's checks of the .deb
  desktop-file-utils appstream shared-mime-info libxml2-utils dpkg-dev lintian
  # the scene loader's fuzzer (tests/fuzz): clang with libFuzzer's runtime
  clang libclang-rt-14-dev
  # the render farm's tests: a single-node Slurm (scripts/local-slurm.sh)
  slurmctld slurmd slurm-client munge
  # whole-process timings in docs (benchmarks/whole_run_presets.sh)
  hyperfine
  # build time (docs/design/testing.md): a faster linker, objects kept between builds
  mold ccache
  # the Python module (python/, docs/guide/scripting.md): bindings, Debian's Python,
  # NumPy arrays for images, and its tests
  pybind11-dev python3-dev python3-numpy python3-pytest
)

missing=()
for pkg in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null || true)
  if [[ "$status" != "install ok installed" ]]; then
    missing+=("$pkg")
  fi
done

if ((${#missing[@]} > 0)); then
  echo "setup: installing ${missing[*]}"
  if [[ $(id -u) -eq 0 ]]; then
    sudo=()
  elif command -v sudo >/dev/null 2>&1; then
    sudo=(sudo)
  else
    echo "setup: missing packages (${missing[*]}) and not root, and sudo is not available" >&2
    exit 1
  fi
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends "${missing[@]}"
fi

# Choose the generator only on first configure; CMake refuses to switch it later.
generator=()
if [[ ! -f build/CMakeCache.txt ]]; then
  generator=(-G Ninja)
fi
cmake -S . -B build "${generator[@]}" -DCMAKE_BUILD_TYPE=Release
cmake --build build
