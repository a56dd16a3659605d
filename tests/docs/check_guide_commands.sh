#!/usr/bin/env bash
# Runs every shell command the guides show, so that the docs cannot drift from
# the programs.
#
# Usage: tests/docs/check_guide_commands.sh BUILD_DIR [PAGE.md...]
#   (default pages: docs/guide/*.md and docs/reference/*.md)
#
# Each fenced block whose info string is `sh`, `bash` or `console` is one test.
# It runs with bash -e -o pipefail in a fresh temporary folder holding links to
# the repository's scenes/ and to BUILD_DIR (as build/), with BUILD_DIR/bin first
# on PATH and PYTHONPATH=BUILD_DIR/python, so a guide may write
# `whitted-render scenes/seed.json ...` or `build/bin/whitted-render ...`.
# `python3` is the one the module was built for: $WHITTED_PYTHON, else
# Debian's /usr/bin/python3 (another python3 found first on PATH may lack NumPy).
# A `console` block's lines that start with "$ " are the commands; its other
# lines are output and are not checked.
#
# A block that must not run here (a package install, a cluster submission,
# opening the editor, a build, a benchmark that takes minutes) is fenced with
# the word no-test after the language:
#
#     ```sh no-test
#     sudo apt install ./whitted_0.1.0_amd64.deb
#     ```
#
# Keep the blocks that run small (`--width 64 --height 48`): the whole script
# should take seconds. A failing block is reported with its page, its first
# line number and its output, and the script exits 1.
set -uo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
build=${1:?usage: check_guide_commands.sh BUILD_DIR [PAGE.md...]}
build=$(cd "$build" && pwd) || exit 2
shift
[[ -x "$build/bin/whitted-render" ]] || { echo "no $build/bin/whitted-render: build first" >&2; exit 2; }
if [[ $# -eq 0 ]]; then
  set -- "$root"/docs/guide/*.md "$root"/docs/reference/*.md
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir "$work/python-bin"
ln -s "${WHITTED_PYTHON:-/usr/bin/python3}" "$work/python-bin/python3"

# Splits the pages into one file a block: NNN.sh, and NNN.where ("page:line").
python3 - "$work" "$root" "$@" <<'PY'
import os, re, sys
work, root, pages = sys.argv[1], sys.argv[2], sys.argv[3:]
n = 0
fence = re.compile(r"^(\s*)(`{3,}|~{3,})\s*([A-Za-z0-9_-]*)\s*(.*)$")
for page in pages:
    lines = open(page, encoding="utf-8").read().split("\n")
    i = 0
    while i < len(lines):
        m = fence.match(lines[i])
        if not m:
            i += 1
            continue
        marker, lang, rest = m.group(2), m.group(3), m.group(4)
        start = i + 1
        j = start
        while j < len(lines) and not lines[j].strip().startswith(marker):
            j += 1
        body = lines[start:j]
        i = j + 1
        if lang not in ("sh", "bash", "console") or "no-test" in rest.split():
            continue
        if lang == "console":
            body = [l[2:] for l in body if l.startswith("$ ")]
        n += 1
        rel = os.path.relpath(page, root)
        with open(os.path.join(work, f"{n:03d}.sh"), "w") as f:
            f.write("\n".join(body) + "\n")
        with open(os.path.join(work, f"{n:03d}.where"), "w") as f:
            f.write(f"{rel}:{start}")
PY

failed=0
count=0
start=$SECONDS
for block in "$work"/*.sh; do
  [[ -e "$block" ]] || break
  count=$((count + 1))
  where=$(cat "${block%.sh}.where")
  dir=$(mktemp -d "$work/run.XXXXXX")
  ln -s "$root/scenes" "$dir/scenes"
  ln -s "$build" "$dir/build"
  if ! output=$(cd "$dir" && PATH="$build/bin:$work/python-bin:$PATH" PYTHONPATH="$build/python" \
                QT_QPA_PLATFORM=offscreen timeout 60 bash -e -o pipefail "$block" 2>&1); then
    failed=$((failed + 1))
    echo "FAILED: the block at $where"
    sed 's/^/  | /' "$block"
    echo "  its output:"
    printf '%s\n' "$output" | tail -n 30 | sed 's/^/  > /'
  fi
  rm -rf "$dir"
done

echo "$count blocks run, $failed failed, in $((SECONDS - start)) s"
[[ $count -gt 0 && $failed -eq 0 ]]
