#!/usr/bin/env python3
"""`massprops check FILE` end to end against urdf::parseURDF alone on the same file, one process
per run, on chains of 1 000, 10 000 and 100 000 links (tools/gen_chain.py): CPU time (user +
system, best of RUNS; on a shared machine it is much steadier than wall time) and peak resident
set of each process. Prints the Markdown table of docs/urdf.md.

Usage: tools/read_bench.py [BUILD_DIR] [RUNS]   (BUILD_DIR defaults to build/, RUNS to 3)
Needs BUILD_DIR/massprops and BUILD_DIR/bench/read_bench (`read_bench --once urdfdom FILE` runs
urdf::parseURDF once on FILE)."""
import os
import subprocess
import sys
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
build = os.path.abspath(sys.argv[1]) if len(sys.argv) > 1 else os.path.join(here, "..", "build")
runs = int(sys.argv[2]) if len(sys.argv) > 2 else 3
tool = os.path.join(build, "massprops")
bench = os.path.join(build, "bench", "read_bench")


def measure(cmd):
    """Best CPU time (s) and the largest peak resident set (KiB) over `runs` runs."""
    best, peak = float("inf"), 0
    for _ in range(runs):
        proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        _, status, usage = os.wait4(proc.pid, 0)
        elapsed = usage.ru_utime + usage.ru_stime
        code = os.waitstatus_to_exitcode(status)
        if code not in (0, 1):
            sys.exit(f"{' '.join(cmd)} exited with {code}")
        best, peak = min(best, elapsed), max(peak, usage.ru_maxrss)
    return best, peak


print("| links | MB | urdfdom `parseURDF` (CPU) | `massprops check` (CPU) | time ratio | urdfdom peak | "
      "`massprops check` peak | memory ratio |")
print("|---:|---:|---:|---:|---:|---:|---:|---:|")
with tempfile.TemporaryDirectory() as tmp:
    for n in (1000, 10000, 100000):
        path = os.path.join(tmp, f"chain{n}.urdf")
        subprocess.run([sys.executable, os.path.join(here, "gen_chain.py"), str(n), path], check=True)
        mb = os.path.getsize(path) / 1e6
        t_ref, m_ref = measure([bench, "--once", "urdfdom", path])
        t_chk, m_chk = measure([tool, "check", "--quiet", path])
        print(f"| {n:,} | {mb:.1f} | {t_ref * 1000:.0f} ms | {t_chk * 1000:.0f} ms | "
              f"{t_chk / t_ref:.2f} | {m_ref / 1024:.0f} MiB | {m_chk / 1024:.0f} MiB | "
              f"{m_chk / m_ref:.2f} |".replace(",", " "))
