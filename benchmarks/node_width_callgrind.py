#!/usr/bin/env python3
"""Per-ray figures from a callgrind run of bench_node_width (docs/design/acceleration.md).

bench_node_width dumps callgrind's counters after each pass, named
"set/mode/tree"; this divides each dump's totals by the pass's rays (from the
benchmark's own table) and prints instructions, D1 misses, LL misses and
mispredicted branches (callgrind's simple predictor) per ray.

  valgrind --tool=callgrind --instr-atstart=no --collect-atstart=no \\
      --cache-sim=yes --branch-sim=yes --LL=8388608,16,64 --callgrind-out-file=cg.out \\
      build/bin/bench_node_width --sizes N ... > bench.txt     # one size a run
  benchmarks/node_width_callgrind.py bench.txt cg.out
"""
import glob
import re
import sys


def rays_per_set(bench_txt):
    """(N, set) -> rays, from the rows of the benchmark's table."""
    rays = {}
    for line in open(bench_txt):
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) >= 5 and cells[0].isdigit():
            rays[(int(cells[0]), cells[1])] = int(cells[4])
    return rays


def dumps(out_base):
    """(name, {event: count}) for each dump of one run, in the order taken."""
    files = glob.glob(out_base + ".*")
    files.sort(key=lambda f: int(f.rsplit(".", 1)[1]))
    for f in files:
        name, events, totals = None, None, None
        for line in open(f):
            if line.startswith("desc: Trigger: Client Request: "):
                name = line[len("desc: Trigger: Client Request: "):].strip()
            elif line.startswith("events: "):
                events = line.split()[1:]
            elif line.startswith("totals: "):
                totals = [int(x) for x in line.split()[1:]]
        if name and events and totals:
            totals += [0] * (len(events) - len(totals))  # trailing zeros are left out
            yield name, dict(zip(events, totals))


def main():
    bench_txt, out_base = sys.argv[1], sys.argv[2]
    rays = rays_per_set(bench_txt)
    # The dumps are named by set, mode and tree, not size: a run of one size only.
    command = open(out_base + ".1").read()
    sizes = re.findall(r"\d+", re.search(r"--sizes ([\d, ]+)", command).group(1))
    if len(sizes) != 1:
        sys.exit(f"node_width_callgrind.py: the run has --sizes {','.join(sizes)}; "
                 "its dumps do not say which size each is of, so give bench_node_width one size")
    n = int(sizes[0])
    print("| N | set | mode | tree | instructions/ray | D1 misses/ray | LL misses/ray |"
          " mispredicted branches/ray |")
    print("|---|---|---|---|---|---|---|---|")
    for name, e in dumps(out_base):
        ray_set, mode, tree = name.split("/")
        r = rays[(n, ray_set)]
        d1 = e["D1mr"] + e["D1mw"]
        ll = e["DLmr"] + e["DLmw"] + e["ILmr"]
        mispredicted = e.get("Bcm", 0) + e.get("Bim", 0)  # with --branch-sim=yes
        print(f"| {n} | {ray_set} | {mode} | {tree} | {e['Ir'] / r:.0f} | {d1 / r:.2f} |"
              f" {ll / r:.3f} | {mispredicted / r:.2f} |")


if __name__ == "__main__":
    main()
