#!/usr/bin/env python3
"""Prints the table of docs/xacro.md: for each package of ../shared/xacro/, how many inertial
numbers of its expansion `massprops trace` traced to one place (by how), to several places, as
computed, or not at all.

usage: tools/xacro_trace_table.py [--tool build/massprops] [--xacro ../shared/xacro]
"""
import argparse
import collections
import json
import pathlib
import subprocess
import sys


def main():
    here = pathlib.Path(__file__).resolve().parent.parent
    parser = argparse.ArgumentParser()
    parser.add_argument("--tool", default=str(here / "build" / "massprops"))
    parser.add_argument("--xacro", default=str(here.parent / "shared" / "xacro"))
    args = parser.parse_args()
    root = pathlib.Path(args.xacro)
    rows = []
    total = collections.Counter()
    for package in sorted(p for p in root.iterdir() if (p / "expanded.urdf").is_file()):
        out = subprocess.run(
            [args.tool, "trace", "--format", "json", "--expanded", str(package / "expanded.urdf"),
             "--source-root", str(package)], check=True, capture_output=True, text=True).stdout
        counts = collections.Counter()
        for n in json.loads(out)["numbers"]:
            places = n["places"]
            if not places:
                counts["none"] += 1
            elif len(places) > 1:
                counts["several"] += 1
            else:
                counts[places[0]["how"]] += 1
            counts["all"] += 1
        total.update(counts)
        rows.append((package.name, counts))
    rows.append(("all seven", total))
    cols = ["literal", "yaml", "parameter", "computed", "several", "none"]
    print("| package | numbers | " + " | ".join(cols) + " |")
    print("| --- | ---: | " + " | ".join("---:" for _ in cols) + " |")
    for name, c in rows:
        cells = [f"{c[k]} ({100 * c[k] / c['all']:.0f}%)" if c[k] else "0" for k in cols]
        print(f"| {name} | {c['all']} | " + " | ".join(cells) + " |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
