#!/usr/bin/env bash
# What a user of whitted-render waits for: the whole run (start, plan, render,
# write the PNG) of a render to each quality target against the fixed preset
# of the same name (core/analysis/render_presets.h), on the scenes of
# bench_quality, timed with hyperfine (Debian's `hyperfine`), which runs each
# command RUNS times after a warm-up and prints the ratio of the means.
# Usage: benchmarks/whole_run_presets.sh [BUILD_DIR [WIDTH HEIGHT [RUNS]]]
# Rows where the preset misses its target at 320x240 (bench_quality) are left
# out: the comparison is with a fixed preset that meets it.
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."
build=${1:-build}
width=${2:-320}
height=${3:-240}
runs=${4:-9}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$build/bin/whitted-field" 300 --seed 7 --half-width 5 --length 12 -o "$work/generated.json"

declare -A preset=([draft]="--spp 1 --depth 2" [preview]="--spp 16 --depth 5"
                   [final]="--spp 128 --depth 8")
# scene:target pairs where the preset misses (docs/quality.md, "Measured").
misses=" field:preview field:final generated:final "

printf '| scene | target | ours, mean of %d (s) | preset (s) | ours / preset, ± one sigma |\n' "$runs"
printf '|---|---|---|---|---|\n'
for scene in seed glass mirrors coloured-shadows whitted-1980 field generated; do
  file=scenes/$scene.json
  [[ $scene == generated ]] && file=$work/generated.json
  for target in draft preview final; do
    [[ $misses == *" $scene:$target "* ]] && continue
    common="$build/bin/whitted-render $file --width $width --height $height --quiet"
    hyperfine -N --style none --warmup 1 --runs "$runs" --export-json "$work/t.json" \
      "$common -o $work/ours.png --quality $target" \
      "$common -o $work/preset.png ${preset[$target]}" >/dev/null 2>"$work/warnings" ||
      { cat "$work/warnings" >&2; exit 1; }
    python3 - "$work/t.json" "$scene" "$target" <<'PY'
import json, sys
ours, preset = json.load(open(sys.argv[1]))["results"]
ratio = ours["mean"] / preset["mean"]
# The spread of a ratio of two means, from each one's run-to-run spread.
spread = ratio * ((ours["stddev"] / ours["mean"]) ** 2 + (preset["stddev"] / preset["mean"]) ** 2) ** 0.5
print(f"| {sys.argv[2]} | {sys.argv[3]} | {ours['mean']:.3f} | {preset['mean']:.3f} | "
      f"{ratio:.2f} ± {spread:.2f} |")
PY
  done
done
