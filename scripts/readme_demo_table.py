#!/usr/bin/env python3
"""Writes the README's demo table from a demo run's demo.json.

    bash scripts/demo.sh && python3 scripts/readme_demo_table.py out/demo/demo.json

The ctest DemoBar.ReadmeTableIsTheDemos fails while the README's table
differs from what the demo prints."""
import json
import sys


def mm(v):
    return f"{1e3 * v:.1f}"


def main():
    if len(sys.argv) != 2 or sys.argv[1] in ("-h", "--help"):
        print(__doc__.strip())
        return 0 if len(sys.argv) == 2 else 2
    runs = json.load(open(sys.argv[1]))["runs"]
    rows = []
    for r in runs:
        rb = r["robot"]
        tags = f"{mm(r['tags']['mean_dist'])} / {mm(r['tags']['max_dist'])}" if "tags" in r else "-"
        rows.append(f"| {r['label']} | {mm(rb['mean_dist'])} / {mm(rb['max_dist'])} | "
                    f"{mm(rb['rmse_dist'])} | {mm(rb['aligned']['rmse_dist'])} | {tags} |")
    path = "README.md"
    lines = open(path).read().split("\n")
    head = next(i for i, l in enumerate(lines) if l.startswith("| method | robot mean / max [mm]"))
    end = head + 2
    while end < len(lines) and lines[end].startswith("|"):
        end += 1
    lines[head + 2:end] = rows
    tmp = path + ".tmp"
    open(tmp, "w").write("\n".join(lines))
    import os
    os.replace(tmp, path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
