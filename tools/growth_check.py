#!/usr/bin/env python3
"""How `massprops check` and `massprops report` grow with the number of links (issue 50).

CPU time (user + system of the process, best of RUNS: a loaded machine stretches wall time, much
less the CPU time a process itself uses) and peak resident set of each process, on the synthetic
chains of tools/gen_chain.py: a URDF chain, an SDF world of 8-link robots (--world), and
`check` on two URDF chains that ask per-group and per-subtree questions of every link: one welded
group of every link (--welded) and massless links carrying the last (--massless).

  tools/growth_check.py TOOL
      The CI growth check (ctest -L speed): 2 000 and 32 000 links, best of 3 runs each; fails
      (exit 1) when 16 times the links cost more than 24 times the CPU time (a linear tool costs
      16 times, a quadratic one 256), for check and report on the URDF chain and the SDF world,
      and check on the welded and the massless chain.
  tools/growth_check.py TOOL --curve 1000,10000,100000,1000000 [--runs R] [--check-urdf PATH]
      The table of docs/benchmarks.md (section 11): links against CPU time and peak memory, with
      urdfdom's check_urdf on the same URDF files when it is installed (liburdfdom-tools).

The tool runs with an empty XDG_CACHE_HOME and from a temporary folder holding the files."""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
SMALL, LARGE = 2000, 32000
LIMIT = 24  # times the CPU time allowed for 16 times the links


def generate(n, kind, folder):
    """The file of n links of `kind` ('urdf' or 'world'), written once into `folder`."""
    path = os.path.join(folder, f"world{n}.sdf" if kind == "world" else f"{kind}{n}.urdf")
    if not os.path.exists(path):
        flags = [] if kind == "urdf" else [f"--{kind}"]
        subprocess.run([sys.executable, os.path.join(HERE, "gen_chain.py"), str(n), path] + flags,
                       check=True)
    return path


class Failed(Exception):
    """A measured command that exited with neither 0 nor 1 (a crash: a negative signal number)."""


def run_once(cmd, env):
    """(CPU seconds, peak resident KiB) of one run of `cmd`."""
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env)
    _, status, usage = os.wait4(proc.pid, 0)
    code = os.waitstatus_to_exitcode(status)
    if code not in (0, 1):
        raise Failed(f"{' '.join(cmd)} exited with {code}")
    return usage.ru_utime + usage.ru_stime, usage.ru_maxrss


def measure(cmd, env, runs, good_enough=None):
    """Best CPU time and largest peak over `runs` runs; stops early once a run's time is at most
    `good_enough` (the best can then only confirm the verdict). Raises Failed."""
    best, peak = float("inf"), 0
    for _ in range(runs):
        cpu, rss = run_once(cmd, env)
        best, peak = min(best, cpu), max(peak, rss)
        if good_enough is not None and best <= good_enough:
            break
    return best, peak


# The files of the growth check: report only where its composites are the question.
KINDS = ("urdf", "world", "welded", "massless")


def commands(tool, kind, path):
    """(label, command) of each measured command on `path`. A file above the readers' default
    limit of 256 MiB (10^6 links) is read with --max-input-size raised to hold it."""
    limit = []
    if os.path.getsize(path) > 256 << 20:
        limit = ["--max-input-size", str(2 * os.path.getsize(path))]
    measured = [(f"check {kind}", [tool, "check", "--quiet"] + limit + [path])]
    if kind in ("urdf", "world"):
        measured.append((f"report {kind}", [tool, "report"] + limit + [path]))
    return measured


def environment(folder):
    env = dict(os.environ)
    env["XDG_CACHE_HOME"] = os.path.join(folder, "cache")
    return env


def growth_check(tool, runs):
    failed = []
    with tempfile.TemporaryDirectory() as folder:
        env = environment(folder)
        print(f"| command | {SMALL} links | {LARGE} links | CPU ratio | peak {SMALL} | "
              f"peak {LARGE} | memory ratio |")
        print("|---|---:|---:|---:|---:|---:|---:|")
        for kind in KINDS:
            small, large = generate(SMALL, kind, folder), generate(LARGE, kind, folder)
            for (label, cmd_small), (_, cmd_large) in zip(commands(tool, kind, small),
                                                          commands(tool, kind, large)):
                t_small, m_small = measure(cmd_small, env, runs)
                t_large, m_large = measure(cmd_large, env, runs, LIMIT * t_small)
                ratio = t_large / max(t_small, 1e-6)
                print(f"| {label} | {t_small:.3f} s | {t_large:.3f} s | {ratio:.1f} | "
                      f"{m_small / 1024:.0f} MiB | {m_large / 1024:.0f} MiB | "
                      f"{m_large / m_small:.1f} |", flush=True)
                if ratio > LIMIT or m_large > LIMIT * m_small:
                    failed.append(label)
    if failed:
        print(f"FAILED: {', '.join(failed)}: {LARGE // SMALL} times the links cost more than "
              f"{LIMIT} times the CPU time or memory (not linear)", file=sys.stderr)
        return 1
    print(f"ok: {LARGE // SMALL} times the links cost at most {LIMIT} times the CPU time and memory")
    return 0


def curve(tool, sizes, runs, check_urdf):
    with tempfile.TemporaryDirectory() as folder:
        env = environment(folder)
        print("| links | file | command | CPU time | peak memory | check_urdf CPU | check_urdf "
              "peak | CPU ratio |")
        print("|---:|---|---|---:|---:|---:|---:|---:|")
        for n in sizes:
            for kind in ("urdf", "world"):
                path = generate(n, kind, folder)
                size = f"{os.path.getsize(path) / 1e6:.1f} MB"
                reference = None
                if kind == "urdf" and check_urdf:
                    try:
                        reference = measure([check_urdf, path], env, runs)
                    except Failed as e:  # Debian 12's check_urdf crashes at 10^5 links
                        reference = str(e).rsplit(" ", 1)[-1]
                for label, cmd in commands(tool, kind, path):
                    t, m = measure(cmd, env, runs)
                    if reference is None or not label.startswith("check"):
                        ref = "| | |"
                    elif isinstance(reference, str):
                        ref = f"| exit {reference} | | |"
                    else:
                        ref = (f"| {reference[0]:.3f} s | {reference[1] / 1024:.0f} MiB | "
                               f"{t / reference[0]:.2f} |")
                    print(f"| {n:,} | {kind} {size} | {label.split()[0]} | {t:.3f} s | "
                          f"{m / 1024:.0f} MiB {ref}".replace(",", " "), flush=True)
                os.remove(path)
    return 0


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("tool", help="the massprops executable")
    parser.add_argument("--curve", help="comma-separated link counts: print the table")
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--check-urdf", default=shutil.which("check_urdf"))
    args = parser.parse_args()
    tool = os.path.abspath(args.tool)
    if args.curve:
        return curve(tool, [int(n) for n in args.curve.split(",")], args.runs, args.check_urdf)
    try:
        return growth_check(tool, args.runs)
    except Failed as e:
        print(f"FAILED: {e}", file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main())
