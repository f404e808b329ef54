#!/usr/bin/env python3
"""Temporal stability of gnomon's shadows: `gnomon score --path` over camera and light paths,
for each filter and for fitted maps with and without stabilisation. Prints a markdown table
of the mean flicker per frame (the share of pixel x light pairs whose rendered shadow changed
while the ray-traced one did not) and the mean misclassified share.

Usage: scripts/quality-flicker.py [--size 256x256] [--frames 16] [--scenes DIR] [--out FILE]
With --out (docs/quality.md), the section after the flicker marker is replaced (or added);
scripts/quality.py keeps it when it rewrites the rest. Real views come from
scripts/quality-real.py (skipped when their model is absent)."""
import argparse
import json
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# $GNOMON picks another build: a whole build tree's binary (a git worktree's, say), not a copy of
# this tree's: the binary loads libgnomon from the tree it was built in, so a copy run while this
# tree rebuilds mixes the two builds.
GNOMON = os.environ.get("GNOMON") or os.path.join(ROOT, "build", "release", "apps", "gnomon", "gnomon")

MARK = "<!-- flicker: made by scripts/quality-flicker.py -->"
INTRO = """## Temporal stability: flicker over camera and light paths

Does a shadow hold still while the view moves? `gnomon score --path dolly|orbit|sun|FILE`
scores every frame of a path and, between each frame and the one before it, draws the
previous frame's view again with this frame's shadow maps and lights, and counts the pixel x
light pairs whose rendered shadow changed while the ray-traced one did not: **flicker**, as
a share of the pairs where the light's shadow can show. The camera's own motion changes no
pixel of that comparison, and an edge that is steadily in the wrong place is an error of
each frame (the misclassified column), not flicker. Paths take small steps, as from one
frame to the next: `dolly` moves the eye 0.5 % of its distance towards the target per frame,
`orbit` turns it 0.5 degree about the target, `sun` turns directional lights 0.25 degree
about the vertical (there the true shadow moves too, and the map's texel grid turns with
the light, so no stabilisation can hold it). `--stabilise off` refits the maps exactly every
frame. A path's frames follow one another as a viewer's do, so stabilised maps also hold
their extent while it covers the view; what stabilisation does is in docs/techniques.md
(Cascades). The point light of `toycar-lamp` gets one frustum over what the view sees and
the spot of `sponza-capitals-spot` the part of its cone the view sees, each held between
frames the same way; `--fit-to boxes` gives them the fixed cube and the whole cone."""

# (settings name, flags) for every view and path
SETTINGS = [
    ("defaults (pcf 3, cascades auto, stabilised)", []),
    ("--stabilise off", ["--stabilise", "off"]),
    ("--cascades 3 --fit-to boxes", ["--cascades", "3", "--fit-to", "boxes"]),
    ("--cascades 3 --fit-to boxes --stabilise off",
     ["--cascades", "3", "--fit-to", "boxes", "--stabilise", "off"]),
    ("--filter none", ["--filter", "none"]),
    ("--filter poisson", ["--filter", "poisson"]),
    ("--filter pcss", ["--filter", "pcss"]),
]
RUNS = [("tutorial-room", "dolly"), ("tutorial-room", "orbit"), ("sponza-atrium", "dolly"),
        ("sponza-atrium", "orbit"), ("lantern-low-sun", "dolly"), ("lantern-low-sun", "sun"),
        ("toycar-lamp", "dolly"), ("toycar-lamp", "orbit"), ("sponza-capitals-spot", "dolly"),
        ("sponza-capitals-spot", "orbit")]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--size", default="256x256")
    ap.add_argument("--frames", default="16")
    ap.add_argument("--scenes", default=os.path.join(ROOT, "..", "shared", "scenes"))
    ap.add_argument("--out", help="markdown page whose flicker section to replace")
    args = ap.parse_args()
    if not os.access(GNOMON, os.X_OK):
        sys.exit(f"quality-flicker: {GNOMON} is missing: run 'make build' first")
    work = tempfile.mkdtemp(prefix="gnomon-flicker-")
    rows = ["| view | path | settings | flicker % per frame (mean) | max % | misclassified % |",
            "|---|---|---|---|---|---|"]

    def row(text):
        rows.append(text)
        print(text, flush=True)

    print(rows[0])
    print(rows[1])
    for view, path in RUNS:
        scene = view
        if not view.startswith("tutorial-"):
            scene = os.path.join(work, view + ".json")
            written = subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "quality-real.py"),
                                      "--scenes", args.scenes, "--write-scene", view, scene])
            if written.returncode != 0:
                row(f"| {view} | {path} | skipped: model absent | | | |")
                continue
        for name, flags in SETTINGS:
            out = os.path.join(work, "out")
            cmd = [GNOMON, "score", "--scene", scene, "--size", args.size, "--path", path,
                   "--frames", args.frames, "--out-dir", out] + flags
            r = subprocess.run(cmd, capture_output=True, text=True)
            if r.returncode != 0:
                row(f"| {view} | {path} | {name} | failed: {r.stderr.strip()} | | |")
                continue
            j = json.load(open(os.path.join(out, "path.json")))
            row(f"| {view} | {path} | {name} | {100 * j['mean_flicker']:.4f} | "
                f"{100 * j['max_flicker']:.4f} | {100 * j['mean_misclassified']:.3f} |")
    if args.out:
        write_section(args.out, rows, args)


def write_section(out, rows, args):
    text = open(out).read() if os.path.exists(out) else ""
    section = "\n".join([MARK, "", INTRO, "",
                         f"Measured at {args.size}, {args.frames} frames per path "
                         f"(`scripts/quality-flicker.py --size {args.size} --frames {args.frames} "
                         f"--out docs/quality.md`):", ""] + rows) + "\n"
    text = (text[:text.index(MARK)] if MARK in text else text.rstrip("\n") + "\n\n") + section
    with open(out + ".tmp", "w") as f:
        f.write(text)
    os.replace(out + ".tmp", out)
    print(f"wrote {out}", file=sys.stderr)


if __name__ == "__main__":
    main()
