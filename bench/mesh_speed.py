#!/usr/bin/env python3
"""`massprops check` on robots with meshes, side by side in one run (docs/benchmarks.md, section 8).

usage: bench/mesh_speed.py MASSPROPS BARE_READ [--repeat N] [--label NAME] -- CHECK-ARGS... FILE...

For the files and arguments given (the same for every row), prints the CPU time (user + system
of the process and its threads, the median of N runs, default 5) of:

  bare read     reading the mesh files `check` resolves (files[].mesh_uris of its JSON output)
                into memory and summing them as 64-bit words: BARE_READ (build/bench/bare_read,
                bench/bare_read.cc), timed inside the process;
  --no-geometry check reading no mesh;
  first -j 1    check with an empty cache ($XDG_CACHE_HOME a fresh temporary folder), one thread;
  first -j 2    the same on two threads;
  cached        check again with the cache the first run left (no mesh is read);
  --no-cache    check neither using nor writing the cache (every mesh read, as before issue 33);

with each row's ratio to the bare read and the mesh bytes per CPU second, then the first run's
ratio net of --no-geometry (the issue's measure). Each repeat runs every row once, in turn, so
that the machine's slower minutes weigh on all rows alike. The tool's output is
compared across the rows that read meshes: the script stops if any differs. MASSPROPS may be an
older build without --no-cache (then only the rows it supports are run).
"""
import argparse
import json
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile



def cpu_of(command, env):
    """Runs command; returns (CPU seconds of it and its threads, stdout)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    out = subprocess.run(command, env=env, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                         check=False).stdout
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return cpu, out


def mesh_paths(tool, args, env):
    out = subprocess.run([tool, "check", "--format", "json", *args], env=env,
                         stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, check=False).stdout
    paths = set()
    for f in json.loads(out)["files"]:
        for mesh in f.get("mesh_uris", []):
            if mesh.get("path"):
                paths.add(mesh["path"])
    return sorted(paths)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("tool")
    parser.add_argument("bare_read")
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--label", default="")
    argv = sys.argv[1:]
    split = argv.index("--") if "--" in argv else len(argv)
    a = parser.parse_args(argv[:split])
    args = argv[split + 1:]
    tool = os.path.abspath(a.tool)
    help_text = subprocess.run([tool, "check", "--help"], stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT, check=False).stdout.decode()
    has_cache = "--no-cache" in help_text
    base_env = dict(os.environ)
    scratch = tempfile.mkdtemp(prefix="mesh-speed-")
    try:
        base_env["XDG_CACHE_HOME"] = os.path.join(scratch, "unused")
        paths = mesh_paths(tool, args + (["--no-cache"] if has_cache else []), base_env)
        size = sum(os.path.getsize(p) for p in paths)
        check = [tool, "check", "-q", *args]

        def bare():
            out = subprocess.run([os.path.abspath(a.bare_read), *paths],
                                 stdout=subprocess.PIPE, check=True).stdout.split()
            return float(out[0])

        # Round-robin: each repeat runs every row once, so that a slower minute of the machine
        # weighs on every row alike (the rows' ratios are what the benchmark is for).
        names = ["bare read", "--no-geometry"]
        names += ["first -j 1", "cached", "first -j 2", "--no-cache"] if has_cache else ["check -j 1"]
        rows = {name: [] for name in names}
        outputs = {}
        for r in range(a.repeat):
            rows["bare read"].append(bare())
            rows["--no-geometry"].append(cpu_of(check + ["--no-geometry"], base_env)[0])
            if not has_cache:
                cpu, outputs["check -j 1"] = cpu_of(check + ["-j", "1"], base_env)
                rows["check -j 1"].append(cpu)
                continue
            for jobs in ("1", "2"):
                env = dict(base_env)
                env["XDG_CACHE_HOME"] = os.path.join(scratch, f"cache-{jobs}-{r}")
                cpu, outputs[f"first -j {jobs}"] = cpu_of(check + ["-j", jobs], env)
                rows[f"first -j {jobs}"].append(cpu)
                if jobs == "1":
                    cpu, outputs["cached"] = cpu_of(check + ["-j", jobs], env)
                    rows["cached"].append(cpu)
            rows["--no-cache"].append(cpu_of(check + ["--no-cache", "-j", "1"], base_env)[0])
        if len(set(outputs.values())) > 1:
            sys.exit("the outputs differ between rows: " + ", ".join(outputs))
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
    bare_cpu = statistics.median(rows["bare read"])
    title = a.label or " ".join(args[-1:])
    print(f"## {title}: {len(paths)} mesh files, {size / 1e6:.1f} MB; median of {a.repeat}")
    print("| run | CPU s | / bare read | MB per CPU s |")
    print("|---|---:|---:|---:|")
    for name, values in rows.items():
        cpu = statistics.median(values)
        print(f"| {name} | {cpu:.3f} | {cpu / bare_cpu:.1f}x | {size / 1e6 / cpu:.0f} |")
    first = "first -j 1" if has_cache else "check -j 1"
    net = statistics.median(rows[first]) - statistics.median(rows["--no-geometry"])
    print(f"\n{first}, net of --no-geometry: {net / bare_cpu:.1f}x the bare read")


if __name__ == "__main__":
    main()
