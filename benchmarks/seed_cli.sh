#!/usr/bin/env bash
# The issue's speed check: whitted-render on the seed scene at 1280x720 with
# --stats, run N times (default 21) in float and in double; prints the median,
# fastest and slowest render time and the median Mrays/s as whitted-render
# reports them ("seconds" in --stats: the render, not process start-up or PNG
# writing). Usage: benchmarks/seed_cli.sh [N]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
runs=${1:-21}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for precision in float double; do
  for _ in $(seq "$runs"); do
    build/bin/whitted-render scenes/seed.json -o "$out/seed.png" --width 1280 --height 720 \
      --precision "$precision" --quiet --stats "$out/stats.json"
    field() { sed -n "s/^ *\"$1\": \([0-9.e+-]*\),\?$/\1/p" "$out/stats.json"; }
    echo "$(field seconds) $(field mrays_per_second) $(field threads)"
  done | sort -n | awk -v p="$precision" '{t[NR]=$1; r[NR]=$2; th=$3}
    END {m=int((NR+1)/2); printf "%-6s median %.1f ms (fastest %.1f, slowest %.1f; %d runs, %d threads), %.0f Mrays/s\n", p, t[m]*1000, t[1]*1000, t[NR]*1000, NR, th, r[m]}'
done
