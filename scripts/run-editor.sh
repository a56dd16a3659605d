#!/usr/bin/env bash
# Builds the project (scripts/setup.sh), then opens the editor on scenes/seed.json.
# Until the editor exists, renders scenes/seed.json with whitted-render instead.
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."
bash scripts/setup.sh

if [[ -x build/bin/whitted ]]; then
  exec build/bin/whitted scenes/seed.json
fi

echo "run-editor: the editor (build/bin/whitted) is not built yet; rendering the seed scene instead"
build/bin/whitted-render scenes/seed.json -o build/seed.png
echo "run-editor: image written to $(pwd)/build/seed.png"
