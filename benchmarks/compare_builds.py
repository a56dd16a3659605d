#!/usr/bin/env python3
"""Two bench_render binaries in turn (A B A B ...), each benchmark's median
time per binary and the median of the pairwise ratios A/B.

The machines are shared and their speed drifts; pairs taken back to back see
the same drift, so their ratio holds where absolute times do not. Times are
CPU time (the benchmarks named .../1 run on one thread), in milliseconds.

    benchmarks/compare_builds.py build-portable/bin/bench_render build/bin/bench_render \\
        --rounds 7 --filter 'BM_Seed(Float|Double)/1/'
"""
import argparse
import json
import statistics
import subprocess


def run_once(binary, pattern, min_time):
    out = subprocess.run(
        [binary, f"--benchmark_filter={pattern}", f"--benchmark_min_time={min_time}",
         "--benchmark_format=json"],
        check=True, capture_output=True, text=True).stdout
    report = json.loads(out)
    return {b["name"]: b["cpu_time"] for b in report["benchmarks"]}, report["context"]


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("a")
    parser.add_argument("b")
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--filter", default="BM_Seed(Float|Double)/1/")
    parser.add_argument("--min-time", default="0.5")
    args = parser.parse_args()

    times = {"a": {}, "b": {}}
    kernels = {}
    for _ in range(args.rounds):
        for side in ("a", "b"):
            figures, context = run_once(getattr(args, side), args.filter, args.min_time)
            kernels[side] = context.get("kernel", "?")
            for name, ms in figures.items():
                times[side].setdefault(name, []).append(ms)

    print(f"A: {args.a}  (kernel {kernels['a']})")
    print(f"B: {args.b}  (kernel {kernels['b']})")
    print(f"{args.rounds} rounds, CPU ms, median over rounds")
    print(f"{'benchmark':44} {'A':>8} {'B':>8} {'A/B':>6} {'min':>6} {'max':>6}")
    for name in times["a"]:
        if name not in times["b"]:
            continue
        a, b = times["a"][name], times["b"][name]
        ratios = [x / y for x, y in zip(a, b)]
        print(f"{name:44} {statistics.median(a):8.1f} {statistics.median(b):8.1f} "
              f"{statistics.median(ratios):6.3f} {min(ratios):6.3f} {max(ratios):6.3f}")


if __name__ == "__main__":
    main()
