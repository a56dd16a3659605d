#!/usr/bin/env bash
# Builds the project (scripts/setup.sh), then opens the editor on scenes/seed.json.
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."
bash scripts/setup.sh
exec build/bin/whitted scenes/seed.json
