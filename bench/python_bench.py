#!/usr/bin/env python3
"""Benchmarks of the Python module, side by side with the peers in one run:

1. massprops.principal_moments on an (N, 3, 3) array (default N = 100 000) against
   numpy.linalg.eigvalsh on the same array: time (best of --repeat runs) and the largest error
   |λ − λ_ref| / trace, where λ_ref is computed in long double (numpy.longdouble, cyclic Jacobi
   rotations).
2. The per-call cost of massprops.check(path) on a small file against running the command-line
   tool (`massprops check --format json FILE`) on it, and of reading the JSON back.

Usage (from the build tree; the module and the tool must be built):
    PYTHONPATH=build/python /usr/bin/python3 bench/python_bench.py --tool build/massprops
"""
import argparse
import json
import os
import pathlib
import platform
import subprocess
import time

import numpy as np

import massprops

HERE = pathlib.Path(__file__).resolve().parent


def random_inertias(n, seed):
    """Valid inertias: random principal moments (Σ's diagonal uniform in [0, 1), so the triangle
    inequality holds), a quarter of them thin rods or near-spheres, scales 1e-6 .. 1e3, rotated
    by random rotations."""
    rng = np.random.default_rng(seed)
    a = rng.uniform(0.0, 1.0, size=(n, 3))
    q = n // 8
    a[:q, 0] = 0.0
    a[:q, 1] = a[:q, 2]  # thin rods: moments (m, m, 0)
    a[q:2 * q] = 1.0 + 1e-9 * rng.uniform(size=(q, 3))  # near-spheres
    moments = np.stack([a[:, 1] + a[:, 2], a[:, 0] + a[:, 2], a[:, 0] + a[:, 1]], axis=1)
    moments *= 10.0 ** rng.uniform(-6, 3, size=(n, 1))
    qm, r = np.linalg.qr(rng.normal(size=(n, 3, 3)))
    qm *= np.sign(np.diagonal(r, axis1=1, axis2=2))[:, None, :]
    I = qm @ (moments[:, :, None] * np.swapaxes(qm, 1, 2))
    return 0.5 * (I + np.swapaxes(I, 1, 2))


def long_double_eigenvalues(I, sweeps=6):
    """Ascending eigenvalues of the symmetric float64 matrices I, computed in long double (x86:
    64-bit mantissa, eps 1.1e-19, about 2000 times finer than double) by cyclic Jacobi rotations
    (backward stable: errors of a few long-double eps of the norm, also for repeated roots)."""
    A = I.astype(np.longdouble)
    n = len(A)
    with np.errstate(over="ignore"):  # theta overflows to inf where A_pq is tiny: t = 0
        A = _jacobi_sweeps(A, n, sweeps)
    return np.sort(np.diagonal(A, axis1=1, axis2=2), axis=1)


def _jacobi_sweeps(A, n, sweeps):
    for _ in range(sweeps):
        for p, q in ((0, 1), (0, 2), (1, 2)):
            apq = A[:, p, q]
            nonzero = apq != 0
            theta = np.where(nonzero, (A[:, q, q] - A[:, p, p]) / (2 * np.where(nonzero, apq, 1)),
                             0)
            t = np.where(nonzero,
                         np.sign(theta) / (np.abs(theta) + np.sqrt(theta * theta + 1)), 0)
            t = np.where(nonzero & (theta == 0), 1, t)
            c = 1 / np.sqrt(t * t + 1)
            sn = t * c
            J = np.broadcast_to(np.eye(3, dtype=np.longdouble), (n, 3, 3)).copy()
            J[:, p, p] = c
            J[:, q, q] = c
            J[:, p, q] = sn
            J[:, q, p] = -sn
            A = np.swapaxes(J, 1, 2) @ A @ J
    return A


def best_time(function, repeat):
    best = float("inf")
    for _ in range(repeat):
        start = time.perf_counter()
        function()
        best = min(best, time.perf_counter() - start)
    return best


def bench_principal_moments(n, repeat):
    I = random_inertias(n, seed=2024)
    reference = long_double_eigenvalues(I)
    trace = np.trace(I, axis1=1, axis2=2).astype(np.longdouble)
    rows = []
    candidates = [
        ("massprops.principal_moments(I, 'accurate')",
         lambda: massprops.principal_moments(I, "accurate")),
        ("massprops.principal_moments(I, 'fast')",
         lambda: massprops.principal_moments(I, "fast")),
        ("numpy.linalg.eigvalsh(I)", lambda: np.linalg.eigvalsh(I)),
    ]
    for name, function in candidates:
        seconds = best_time(function, repeat)
        values = function().astype(np.longdouble)
        error = np.max(np.abs(values - reference) / trace[:, None])
        rows.append((name, seconds, float(error) / np.finfo(float).eps))
    return rows


def bench_check(tool, path, calls):
    massprops.check(path)  # warm up (first import of the rules, file cache)
    start = time.perf_counter()
    for _ in range(calls):
        massprops.check(path)
    python_seconds = (time.perf_counter() - start) / calls
    tool_calls = max(calls // 10, 5)
    start = time.perf_counter()
    for _ in range(tool_calls):
        run = subprocess.run([tool, "check", "--format", "json", path], capture_output=True,
                             text=True)
        json.loads(run.stdout)
    tool_seconds = (time.perf_counter() - start) / tool_calls
    return python_seconds, tool_seconds


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--tool", default="build/massprops", help="the massprops executable")
    parser.add_argument("--n", type=int, default=100_000, help="matrices (default 100000)")
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--calls", type=int, default=200, help="check() calls to time")
    parser.add_argument("--file", default=str(HERE.parent / "examples" / "two_link_arm.urdf"))
    args = parser.parse_args()

    print(f"massprops {massprops.__version__}, numpy {np.__version__}, "
          f"Python {platform.python_version()}, {platform.machine()}, "
          f"{os.cpu_count()} CPUs (load average {os.getloadavg()[0]:.1f})\n")
    print(f"principal moments of {args.n} symmetric 3x3 matrices (best of {args.repeat}):\n")
    print("| method | time (ms) | ns per matrix | max error / trace (eps) |")
    print("| --- | ---: | ---: | ---: |")
    for name, seconds, error in bench_principal_moments(args.n, args.repeat):
        print(f"| `{name}` | {seconds * 1e3:.1f} | {seconds / args.n * 1e9:.0f} | {error:.2f} |")

    python_seconds, tool_seconds = bench_check(args.tool, args.file, args.calls)
    print(f"\ncheck on {os.path.basename(args.file)} "
          f"({os.path.getsize(args.file)} bytes), per call:\n")
    print("| how | time per call (ms) |")
    print("| --- | ---: |")
    print(f"| `massprops.check(path)` | {python_seconds * 1e3:.3f} |")
    print(f"| `massprops check --format json FILE` (subprocess + json.loads) | "
          f"{tool_seconds * 1e3:.3f} |")


if __name__ == "__main__":
    main()
