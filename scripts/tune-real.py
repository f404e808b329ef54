#!/usr/bin/env python3
"""gnomon tune on every hard view of the real scenes (scripts/quality-real.py's views), with
the default settings as the start and their frame time as the budget. Prints a markdown table:
the defaults' error and frame time, the best setting found within that time and its error,
whether the defaults are on the error-versus-time front, whether the best's gain holds with the
view moved half a pixel four ways (tune's check: errors, best / defaults, per shift), and how
long each search took.

Usage: scripts/tune-real.py [--size 512x512] [--only a,b] [--scenes DIR] [--flags "..."]"""
import argparse
import json
import os
import subprocess
import shlex
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# $GNOMON picks another build: a whole build tree's binary (a git worktree's, say), not a copy of
# this tree's: the binary loads libgnomon from the tree it was built in, so a copy run while this
# tree rebuilds mixes the two builds.
GNOMON = os.environ.get("GNOMON") or os.path.join(ROOT, "build", "release", "apps", "gnomon", "gnomon")
QUALITY_REAL = os.path.join(ROOT, "scripts", "quality-real.py")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--size", default="512x512")
    ap.add_argument("--only", help="comma-separated view names")
    ap.add_argument("--scenes", default=os.path.join(ROOT, "..", "shared", "scenes"))
    ap.add_argument("--flags", default="", help="gnomon tune flags added to every view "
                                                "(its start: \"--shadow-rays off\", the maps alone)")
    args = ap.parse_args()
    if not os.access(GNOMON, os.X_OK):
        sys.exit(f"tune-real: {GNOMON} is missing: run 'make build' first")
    views = subprocess.run([sys.executable, QUALITY_REAL, "--list"], capture_output=True,
                           text=True, check=True).stdout.split()
    if args.only:
        views = [v for v in views if v in args.only.split(",")]
    work = tempfile.mkdtemp(prefix="gnomon-tune-real-")
    print(f"gnomon tune at {args.size}, budget: the defaults' frame time\n")
    print("| view | defaults: misclassified %, away %, ms | best within budget | its misclassified % (x defaults) | defaults on the front | half a pixel away: best / defaults, % | trials | search s |")
    print("|---|---|---|---|---|---|---|---|")
    for view in views:
        scene = os.path.join(work, view + ".json")
        if subprocess.run([sys.executable, QUALITY_REAL, "--scenes", args.scenes,
                           "--write-scene", view, scene]).returncode != 0:
            print(f"| {view} | skipped: model absent | | | | | | |", flush=True)
            continue
        out = os.path.join(work, view)
        start = time.monotonic()
        r = subprocess.run([GNOMON, "tune", "--scene", scene, "--size", args.size,
                            "--out-dir", out] + shlex.split(args.flags),
                           capture_output=True, text=True)
        seconds = time.monotonic() - start
        if r.returncode != 0:
            print(f"| {view} | failed: {r.stderr.strip()} | | | | | | |", flush=True)
            continue
        j = json.load(open(os.path.join(out, "tune.json")))
        d = j["trials"][0]
        b = j["trials"][j["best"]] if j["best"] >= 0 else d
        ratio = b["misclassified"] / d["misclassified"] if d["misclassified"] > 0 else 1.0
        best = "the defaults" if j["best"] <= 0 else f"`{b['flags']}`"
        front = "yes" if j["start_on_front"] else f"no (trial {j['beats_start']})"
        # tune's check of the best on the view moved half a pixel four ways (docs/tune.md).
        shifted = "–"
        if "shifted" in j:
            pairs = " ".join(f"{100 * b_:.3f}/{100 * s_:.3f}" for b_, s_ in
                             zip(j["shifted"]["best_errors"], j["shifted"]["start_errors"]))
            shifted = ("holds: " if j["shifted"]["holds"] else "does not hold: ") + pairs
        print(f"| {view} | {100 * d['misclassified']:.3f}, {100 * d['away_from_edges']:.3f}, "
              f"{d['frame_ms']:.0f} | {best} | {100 * b['misclassified']:.3f} ({ratio:.2f}x) | "
              f"{front} | {shifted} | {len(j['trials'])} | {seconds:.0f} |", flush=True)


if __name__ == "__main__":
    main()
