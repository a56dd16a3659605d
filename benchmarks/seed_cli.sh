#!/usr/bin/env bash
# The issue's speed check: whitted-render on the seed scene at 1280x720 with
# --stats, run N times (default 21) in float and in double; prints the median,
# fastest and slowest render time and the median Mrays/s as whitted-render
# reports them ("seconds" in --stats: the render, not process start-up or PNG
# writing), and the median time each thread spent on the CPU ("cpu_seconds"
# over the threads): where other programs take a core, the seconds grow and
# this does not. Usage: benchmarks/seed_cli.sh [N]
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
    echo "$(field seconds) $(field mrays_per_second) $(field threads) $(field cpu_seconds)"
  done | sort -n | awk -v p="$precision" '{t[NR]=$1; r[NR]=$2; th=$3; c[NR]=$4/$3}
    END {m=int((NR+1)/2)
      for (i = 2; i <= NR; i++) { v = c[i]; for (j = i - 1; j > 0 && c[j] > v; j--) c[j+1] = c[j]; c[j+1] = v }
      printf "%-6s median %.1f ms (fastest %.1f, slowest %.1f; %d runs, %d threads), %.0f Mrays/s; on the CPU %.1f ms a thread (median)\n", p, t[m]*1000, t[1]*1000, t[NR]*1000, NR, th, r[m], c[m]*1000}'
done
