#!/usr/bin/env bash
# What a user of whitted-render waits for: the whole run (start, plan, render,
# write the PNG) of a render to each quality target against the fixed preset
# of the same name (core/analysis/render_presets.h), timed with hyperfine
# (Debian's `hyperfine`), which runs each command RUNS times after a warm-up
# and prints the ratio of the means.
# Usage: benchmarks/whole_run_presets.sh [BUILD_DIR [WIDTH HEIGHT [RUNS [fields]]]]
# Without `fields`: the scenes of bench_quality, at 640x480. With it: the twenty
# untuned fields of `bench_quality_fields presets 1 20` (untunedField() there),
# at 160x120. Rows where the preset misses its target are left out: the
# comparison is with a fixed preset that meets it. Which presets miss depends
# on the size, and the lists below were measured at those two sizes only, so
# the script refuses any other. With WHOLE_RUN_CSV=FILE each row is also
# added to FILE (benchmarks/whole_run_presets.csv keeps them, a build's rows
# after another's), with the commit it measured.
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."
build=${1:-build}
which=${5:-scenes}
measured=640x480
[[ $which == fields ]] && measured=160x120
width=${2:-${measured%x*}}
height=${3:-${measured#*x}}
runs=${4:-9}
if [[ ${width}x$height != "$measured" ]]; then
  echo "whole_run_presets.sh: which presets miss their targets is known at $measured only;" \
    "measure it at ${width}x$height (bench_quality, bench_quality_fields) and add it here" >&2
  exit 2
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

declare -A preset=([draft]="--spp 1 --depth 2" [preview]="--spp 16 --depth 5"
                   [final]="--spp 128 --depth 8")

# One row: ours and the preset on scene file $1, named $2, for target $3.
time_row() {
  local common="$build/bin/whitted-render $1 --width $width --height $height --quiet"
  hyperfine -N --style none --warmup 1 --runs "$runs" --export-json "$work/t.json" \
    "$common -o $work/ours.png --quality $3" \
    "$common -o $work/preset.png ${preset[$3]}" >/dev/null 2>"$work/warnings" ||
    { cat "$work/warnings" >&2; exit 1; }
  python3 - "$work/t.json" "$2" "$3" "$width" "$height" "$runs" "${WHOLE_RUN_CSV:-}" \
    "$(git rev-parse --short HEAD 2>/dev/null || echo unknown)" <<'PY'
import json, sys
ours, preset = json.load(open(sys.argv[1]))["results"]
ratio = ours["mean"] / preset["mean"]
# The spread of a ratio of two means, from each one's run-to-run spread.
spread = ratio * ((ours["stddev"] / ours["mean"]) ** 2 + (preset["stddev"] / preset["mean"]) ** 2) ** 0.5
print(f"| {sys.argv[2]} | {sys.argv[3]} | {ours['mean']:.3f} | {preset['mean']:.3f} | "
      f"{ratio:.2f} ± {spread:.2f} |")
scene, target, width, height, runs, csv, build = sys.argv[2:9]
if csv:
    with open(csv, "a") as out:
        out.write(f"{scene},{target.capitalize()},{width},{height},{runs},{build},"
                  f"{ratio:.2f},{spread:.2f}\n")
PY
}

printf '| scene | target | ours, mean of %d (s) | preset (s) | ours / preset, ± one sigma |\n' "$runs"
printf '|---|---|---|---|---|\n'
if [[ $which == fields ]]; then
  # Where the preset misses at 160x120 (bench_quality_fields 160 120).
  missed=(8:draft 9:draft 18:draft 2:preview 4:preview 5:preview 6:preview 7:preview
          8:preview 12:preview 13:preview 17:preview 19:preview 2:final 3:final 4:final
          5:final 6:final 7:final 8:final 10:final 12:final 14:final 15:final 16:final
          17:final 18:final 19:final)
  misses=" ${missed[*]} "
  for n in $(seq 1 20); do
    count=$((40 + 37 * (n % 9)))
    length=$(python3 -c "print(5 + 1.5 * ($n % 5))")
    "$build/bin/whitted-field" "$count" --seed $((500 + n)) --half-width $((2 + n % 4)) \
      --length "$length" -o "$work/field.json"
    for target in draft preview final; do
      [[ $misses == *" $n:$target "* ]] && continue
      time_row "$work/field.json" "seed $n, $count balls" "$target"
    done
  done
  exit 0
fi

"$build/bin/whitted-field" 300 --seed 7 --half-width 5 --length 12 -o "$work/generated.json"
# scene:target pairs where the preset misses at 640x480 (bench_quality 640 480,
# docs/tradeoff.md).
misses=" field:preview field:final generated:final seed:preview generated:preview "
for scene in seed glass mirrors coloured-shadows whitted-1980 field generated; do
  file=scenes/$scene.json
  [[ $scene == generated ]] && file=$work/generated.json
  for target in draft preview final; do
    [[ $misses == *" $scene:$target "* ]] && continue
    time_row "$file" "$scene" "$target"
  done
done
