#!/usr/bin/python3
"""docs/outputs.md against what rfir-slam and rfir-localize write, both ways.

    /usr/bin/python3 scripts/check_outputs_doc.py [--bin build/bin]

Runs (a few seconds, fixed seeds, in a scratch folder):
- rfir-slam PS-SLAM --smooth on datasets/rfid_kidnap (ground truth beside
  it: errors and the smoother's files and keys);
- rfir-slam PS-SLAM on bench_floor_30x20.ini's first 320 s, seed 3 (rfir-sim):
  the drifted return that PS-SLAM closes by smoothing (loop_closure_times_s;
  tests/test_loop_closure.cpp holds the same run);
- rfir-localize on datasets/ir_loop_spots (ground truth and spots).
Then, per program, the page's sections "### <program>: files" and
"### <program>: stats.json" (first column of their tables) must list every
file the runs wrote and every key of their stats.json, and nothing the runs
did not write. A key of a nested object is written with dots
(`smoother.solver`); a listed object (`path_errors`) covers its keys, which
are documented elsewhere, and an object whose keys are listed needs no row
of its own; lists are not entered. Exit codes: 0 the page
agrees, 1 it differs (each difference named) or a run failed, 2 bad command
line."""
import argparse
import json
import os
import re
import sys
import tempfile

from docs_numbers import Sources

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PAGE = "docs/outputs.md"


def listed(page, heading):
    """The code spans opening the table rows of the section `heading`."""
    m = re.search(rf"^### {re.escape(heading)}\n(.*?)(?=^#|\Z)", page, re.M | re.S)
    if not m:
        raise RuntimeError(f"{PAGE}: no section '### {heading}'")
    names = re.findall(r"^\| `([^`]+)` \|", m.group(1), re.M)
    if not names:
        raise RuntimeError(f"{PAGE}: section '### {heading}' lists nothing")
    return set(names)


def keys(obj, prefix=""):
    """Every key of a JSON object, nested objects' keys with dots."""
    out = set()
    for k, v in obj.items():
        out.add(prefix + k)
        if isinstance(v, dict):
            out |= keys(v, prefix + k + ".")
    return out


def compare(what, written, page):
    """Problems: written but not on the page (nor covered by a listed
    object), or on the page but written by no run."""
    def covered(k):  # k, an object holding it, or (k an object) one of its keys
        parts = k.split(".")
        return (any(".".join(parts[:i]) in page for i in range(1, len(parts) + 1)) or
                any(p.startswith(k + ".") for p in page))
    missing = sorted(k for k in written if not covered(k))
    stale = sorted(k for k in page if k not in written)
    return ([f"{what}: '{k}' is written but not in {PAGE}" for k in missing] +
            [f"{what}: '{k}' is in {PAGE} but no run wrote it" for k in stale])


class Runner(Sources):
    """docs_numbers' command runner: a program of --bin, quiet, in ROOT."""

    def __call__(self, prog, *args):
        self.run([self.prog(prog), *args, "-q"])

    def out(self, name):
        return os.path.join(self.tmp, name)


def written(dirs):
    """The files of the output folders, and the keys of their stats.json."""
    files, stats = set(), set()
    for d in dirs:
        files |= set(os.listdir(d))
        with open(os.path.join(d, "stats.json"), encoding="utf-8") as f:
            stats |= keys(json.load(f))
    return files, stats


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bin", default=os.path.join(ROOT, "build", "bin"),
                    help="folder of the rfir programs (default: build/bin)")
    a = ap.parse_args()
    bindir = os.path.abspath(a.bin)
    for p in ("rfir-slam", "rfir-localize", "rfir-sim"):
        if not os.access(os.path.join(bindir, p), os.X_OK):
            ap.error(f"--bin {a.bin}: no program {p} (build it first)")
    page = open(os.path.join(ROOT, PAGE), encoding="utf-8").read()
    problems = []
    with tempfile.TemporaryDirectory(prefix="rfir_outputs_doc_") as tmp:
        run = Runner(bindir, tmp)
        try:
            run("rfir-slam", "--rawlog", "datasets/rfid_kidnap.rawlog", "--method", "ps",
                "--smooth", "--out-dir", run.out("kidnap"))
            run("rfir-sim", "--config", "bench_floor_30x20", "--seed", "3",
                "--set", "simulation.max_duration=320", "--out-dir", run.out("floor"))
            run("rfir-slam", "--rawlog", run.out("floor/bench_floor_30x20.rawlog"),
                "--method", "ps", "--seed", "3", "--out-dir", run.out("floor_ps"))
            run("rfir-localize", "--rawlog", "datasets/ir_loop_spots.rawlog", "--emitters",
                "datasets/ir_loop_spots.gt_map.txt", "--out-dir", run.out("ir"))
            for prog, dirs in (("rfir-slam", ["kidnap", "floor_ps"]), ("rfir-localize", ["ir"])):
                files, stats = written([run.out(d) for d in dirs])
                problems += compare(f"{prog} files", files, listed(page, f"{prog}: files"))
                problems += compare(f"{prog} stats.json", stats,
                                    listed(page, f"{prog}: stats.json"))
        except RuntimeError as e:
            print(f"check_outputs_doc: {e}", file=sys.stderr)
            return 1
    for p in problems:
        print(f"check_outputs_doc: {p}", file=sys.stderr)
    if problems:
        return 1
    print(f"check_outputs_doc: {PAGE} lists every file and stats.json key of rfir-slam "
          "and rfir-localize, and no other")
    return 0


if __name__ == "__main__":
    sys.exit(main())
