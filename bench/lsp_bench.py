#!/usr/bin/env python3
"""The language server over a long session (docs/benchmarks.md, "Language server"; issue 45).

1. Memory: a 100-link chain (tools/gen_chain.py) is opened, then CHANGES didChange notifications
   are sent one at a time, each waiting for its publishDiagnostics (so every one is checked, none
   coalesced), the text alternating between two masses of one link. The server's resident set
   (VmRSS of /proc/PID/status) is read after the first check and after the last; the growth is
   printed (the bar: under 10 MB for 10 000 changes).
2. Latency: on the README's example (examples/two_link_arm.urdf), EDITS didChange notifications,
   each timed from the moment it is written to the arrival of the publishDiagnostics of its
   version (the client's reader thread stamps each message as it is parsed); the median and the
   95th percentile are printed (the bar: median at most 20 ms).

Usage: lsp_bench.py MASSPROPS [--changes N] [--edits N] [--check]
--check exits 1 when a bar is not met (the smoke run in ctest uses small counts and checks only
the memory bar, never the time).
"""
import argparse
import pathlib
import statistics
import subprocess
import sys
import tempfile
import time

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "tests"))
from lsp_client import Client, frame  # noqa: E402


def rss_kib(pid):
    for line in pathlib.Path("/proc/%d/status" % pid).read_text().splitlines():
        if line.startswith("VmRSS:"):
            return int(line.split()[1])
    raise RuntimeError("no VmRSS")


def two_variants(text, link_mass):
    """The text, and the text with the first `<mass value="M"/>` changed to M + 0.1."""
    at = text.index('<mass value="%s"/>' % link_mass)
    other = '<mass value="%s"/>' % (float(link_mass) + 0.1)
    return text, text[:at] + other + text[at + len('<mass value="%s"/>' % link_mass):]


def timed_change(client, uri, text, version):
    message = frame({"jsonrpc": "2.0", "method": "textDocument/didChange",
                     "params": {"textDocument": {"uri": uri, "version": version},
                                "contentChanges": [{"text": text}]}})
    start = time.monotonic()
    client.send_raw(message)
    client.wait_for(lambda m: m.get("method") == "textDocument/publishDiagnostics"
                    and m["params"]["uri"] == uri and m["params"].get("version") == version)
    return client.last_arrival - start


def memory(tool, changes):
    with tempfile.TemporaryDirectory() as folder:
        chain = pathlib.Path(folder) / "chain100.urdf"
        subprocess.run([sys.executable, str(HERE.parent / "tools" / "gen_chain.py"), "100",
                        str(chain)], check=True)
        text = chain.read_text()
        client = Client(tool)
        try:
            client.initialize()
            uri = client.open(chain, text)
            client.diagnostics(uri)
            before = rss_kib(client.proc.pid)
            variants = two_variants(text, "1.5")
            start = time.monotonic()
            for version in range(2, changes + 2):
                timed_change(client, uri, variants[version % 2], version)
            seconds = time.monotonic() - start
            after = rss_kib(client.proc.pid)
            client.shutdown_and_exit()
        finally:
            client.kill()
    return before, after, seconds


def latency(tool, edits):
    example = HERE.parent / "examples" / "two_link_arm.urdf"
    text = example.read_text()
    client = Client(tool)
    try:
        client.initialize()
        uri = client.open(example, text)
        client.diagnostics(uri)
        variants = two_variants(text, "0.8")
        times = [timed_change(client, uri, variants[v % 2], v) for v in range(2, edits + 2)]
        client.shutdown_and_exit()
    finally:
        client.kill()
    times.sort()
    return statistics.median(times), times[int(0.95 * (len(times) - 1))], times[0]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("tool")
    parser.add_argument("--changes", type=int, default=10000)
    parser.add_argument("--edits", type=int, default=1000)
    parser.add_argument("--check", action="store_true")
    args = parser.parse_args()
    print(subprocess.run(["uptime"], capture_output=True, text=True).stdout.strip())
    before, after, seconds = memory(args.tool, args.changes)
    growth_mib = (after - before) / 1024
    print("100-link chain, %d didChange each checked: RSS %.1f MiB after the first check, "
          "%.1f MiB after the last: growth %.2f MiB (%.2f ms per change)"
          % (args.changes, before / 1024, after / 1024, growth_mib,
             1000 * seconds / args.changes))
    median, p95, fastest = latency(args.tool, args.edits)
    print("two_link_arm.urdf, %d didChange -> publishDiagnostics: median %.2f ms, 95th "
          "percentile %.2f ms, fastest %.2f ms" % (args.edits, 1000 * median, 1000 * p95,
                                                    1000 * fastest))
    print(subprocess.run(["uptime"], capture_output=True, text=True).stdout.strip())
    if args.check and growth_mib >= 10:
        print("FAIL: resident memory grew by %.2f MiB (the bar: under 10)" % growth_mib)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
