#!/usr/bin/env python3
"""Two (or more) builds' first `check` run, interleaved (docs/benchmarks.md, section 8).

usage: bench/first_run_ab.py [--ignore-output] RUNS MASSPROPS_A MASSPROPS_B [...] -- CHECK-ARGS...

Runs `MASSPROPS check CHECK-ARGS FILE...` RUNS times for each build, one build after the other in
every round (A B A B ...), each run with an empty cache ($XDG_CACHE_HOME a fresh temporary
folder), and prints per build the CPU time (user + system of the process and its threads) as the
10th percentile, quartile, median and mean, and the median of the minor page faults. On a shared
virtual machine the same command varies by 10-20% from minute to minute; interleaving gives each
build the same minutes, so that a difference of a few percent shows in the medians. The outputs
of the builds are compared once first: the script stops if they differ (unless --ignore-output:
builds meant to word a finding differently).
"""
import os
import resource
import shutil
import statistics
import sys
import tempfile

from mesh_speed import cpu_of


def run(command, cache):
    """CPU seconds (mesh_speed.py's cpu_of), minor page faults and stdout of one run of command."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_minflt
    cpu, out = cpu_of(command, dict(os.environ, XDG_CACHE_HOME=cache))
    return cpu, resource.getrusage(resource.RUSAGE_CHILDREN).ru_minflt - before, out


def main():
    argv = sys.argv[1:]
    ignore_output = bool(argv) and argv[0] == "--ignore-output"
    if ignore_output:
        argv = argv[1:]
    if "--" not in argv or argv.index("--") < 3:
        sys.exit(__doc__)
    split = argv.index("--")
    runs, tools, args = int(argv[0]), argv[1:split], argv[split + 1:]
    outputs = set()
    for tool in tools:
        cache = tempfile.mkdtemp()
        outputs.add(run([tool, "check"] + args, cache)[2])
        shutil.rmtree(cache)
    if len(outputs) != 1 and not ignore_output:
        sys.exit("first_run_ab.py: the builds' outputs differ")
    cpu = {tool: [] for tool in tools}
    faults = {tool: [] for tool in tools}
    for _ in range(runs):
        for tool in tools:
            cache = tempfile.mkdtemp()
            seconds, minflt, _ = run([tool, "check"] + args, cache)
            shutil.rmtree(cache)
            cpu[tool].append(seconds)
            faults[tool].append(minflt)
    print(f"first run, {runs} runs each, interleaved; CPU s")
    print("| build | p10 | p25 | median | mean | page faults (median) |")
    print("|---|---:|---:|---:|---:|---:|")
    for tool in tools:
        v = sorted(cpu[tool])
        print(f"| {tool} | {v[len(v) // 10]:.3f} | {v[len(v) // 4]:.3f} | "
              f"{statistics.median(v):.3f} | {statistics.mean(v):.3f} | "
              f"{statistics.median(faults[tool]):.0f} |")


if __name__ == "__main__":
    main()
