#!/usr/bin/env python3
"""Writes docs/quality.md: every built-in scene x the main technique options, scored by
`gnomon score` against the ray-traced reference and timed by `gnomon bench`, at the
scenes' own size (512x512). Run from anywhere after `make build`:

    scripts/quality.py [--frames N] [--out docs/quality.md]
"""
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

# (label, flags): the techniques compared on every scene.
VARIANTS = [
    ("textbook preset", ["--preset", "textbook"]),
    ("defaults (pcf 3)", []),
    ("pcf 1", ["--pcf-size", "1"]),
    ("pcf 5", ["--pcf-size", "5"]),
    ("filter none", ["--filter", "none"]),
    ("poisson 5", ["--filter", "poisson", "--pcf-size", "5"]),
    ("pcss", ["--filter", "pcss"]),
    ("evsm4", ["--filter", "evsm4"]),
    ("msm", ["--filter", "msm"]),
    ("4 cascades", ["--cascades", "4"]),
]

# Scenes beyond the built-in ones, each with its own variants: (name, scene file, variants).
# examples/stained-glass.json is what coloured shadows (the default for blended casters) are
# for; dithered blend shadows are the rule they replaced.
EXTRA = [
    ("stained-glass", os.path.join(ROOT, "examples", "stained-glass.json"),
     [("defaults (coloured)", []), ("blend dithered", ["--blend-shadows", "dithered"]),
      ("pcss", ["--filter", "pcss"]), ("msm", ["--filter", "msm"])]),
]


def run(args):
    result = subprocess.run([GNOMON] + args, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True)
    if result.returncode != 0:
        sys.exit(f"gnomon {' '.join(args)} failed ({result.returncode}):\n{result.stderr}")
    return result.stdout


FLICKER_MARK = "<!-- flicker: made by scripts/quality-flicker.py -->"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--frames", type=int, default=5, help="frames timed per cell")
    parser.add_argument("--out", default=os.path.join(ROOT, "docs", "quality.md"))
    args = parser.parse_args()
    if not os.access(GNOMON, os.X_OK):
        sys.exit(f"{GNOMON} not found: run `make build` first")
    cases = [(scene, scene, VARIANTS) for scene in run(["scenes", "--names"]).split()] + EXTRA
    gl = ""
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for scene, source, variants in cases:
            for label, flags in variants:
                print(f"quality: {scene}: {label}", file=sys.stderr)
                run(["score", "--scene", source, "--out-dir", work] + flags)
                with open(os.path.join(work, "score.json")) as f:
                    result = json.load(f)
                score = result["overall"]
                score["tint"] = result.get("tint")
                run(["bench", "--scene", source, "--frames", str(args.frames), "--warmup", "1",
                     "--static", "--out-dir", work] + flags)
                with open(os.path.join(work, "bench.json")) as f:
                    bench = json.load(f)
                gl = bench["gl"]
                frame = bench["runs"][0]["frame_ms"]["median"]
                rows.append((scene, label, score, frame))

    def pct(v):
        return f"{100.0 * v:.3f}"

    def tint(s):
        t = s.get("tint")
        return f"{255.0 * t['mean_error']:.2f}" if t and t["cells"] > 0 else "–"

    lines = [
        "# Shadow quality of every built-in scene",
        "",
        "Produced by `scripts/quality.py` (do not edit by hand). Every cell is one",
        "`gnomon score` run against the Embree reference at 512×512, and its frame time is",
        f"the median of {args.frames} frames of `gnomon bench --static` (maps kept, as for a",
        f"static scene; the driver: {gl}). Compare frame times within this table only: they",
        "are one run's, and this shared machine's speed moves by up to twice between hours",
        "(docs/results/performance.md measures builds and peers side by side). The flags of each row are",
        "added to the scene's own options:",
        "",
    ]
    for label, flags in VARIANTS:
        lines.append(f"- **{label}**: `{' '.join(flags) if flags else '(none)'}`")
    for scene, source, variants in EXTRA:
        lines.append(f"- and `{os.path.relpath(source, ROOT)}` (**{scene}**): " + ", ".join(
            f"**{label}** `{' '.join(flags) if flags else '(none)'}`" for label, flags in variants))
    lines += [
        "",
        "Percentages are of the pixels where a light's shadow can show (the light reaches a",
        "receiving surface that faces it, by more than 0.06 degrees: a surface edge-on to the light",
        "gets under 0.1 % of it, which no picture shows, and the rounding of its vertices would",
        "decide which side it is on) and the",
        "render drew that same surface (where rasterisation drew another one or none, the visibility",
        "read is not that surface's: `gnomon score` leaves such pixels out and counts them), summed",
        "over lights:",
        "- **misclassified**: false shadow plus leak;",
        "- **false shadow**: the reference is lit and gnomon drew shadow (acne, over-wide",
        "  filters);",
        "- **leak**: the reference is in shadow and gnomon drew light (peter-panning, missed",
        "  casters, surfaces outside a light's map);",
        "- **… away from edges**: the same counts, leaving out pixels within 2 map texels of",
        "  a reference shadow edge, where aliasing is expected (measured along the surface: on",
        "  a surface tilted by θ to the light a texel covers 1/cos θ of it, counted up to 4).",
        "  The terminator, where a surface turns away from the light into its own attached",
        "  shadow, is such an edge too: the map sees it as the outline of the shadow it casts.",
        "  The band is found on screen, where an edge the camera does not see (under the caster",
        "  that makes it, behind a fold) leaves none; so every pixel rendered wrong outside it is",
        "  probed with 16 more shadow rays on its surface within the band's reach, and joins the",
        "  band where the reference's shadow changes there.",
        "  (Figures in other pages measured before this rule counted terminators as away from",
        "  edges.)",
        "",
        "- **tinted light error**: where blended casters tint the light (coloured shadows),",
        "  the mean difference of the light arriving from the reference's, in 8-bit steps",
        "  (– where nothing is tinted).",
        "",
        "`pcss` is compared with the soft reference (64 rays to the light's disc or cone per",
        "pixel), the others with the hard one.",
        "",
        "| scene | technique | misclassified % | false shadow % | leak % "
        "| false shadow away from edges % | leak away from edges % | tinted light error /255 "
        "| frame ms |",
        "|---|---|---|---|---|---|---|---|---|",
    ]
    for scene, label, s, frame in rows:
        lines.append(
            f"| {scene} | {label} | {pct(s['misclassified'])} | {pct(s['false_shadow'])} | "
            f"{pct(s['leak'])} | {pct(s['false_shadow_outside_band'])} | "
            f"{pct(s['leak_outside_band'])} | {tint(s)} | {frame:.1f} |")
    # The temporal-stability section (scripts/quality-flicker.py) is kept as it was.
    kept = ""
    if os.path.exists(args.out):
        with open(args.out) as f:
            old = f.read()
        if FLICKER_MARK in old:
            kept = "\n" + old[old.index(FLICKER_MARK):]
    with open(args.out + ".tmp", "w") as f:
        f.write("\n".join(lines) + "\n" + kept)
    os.replace(args.out + ".tmp", args.out)
    print(f"wrote {args.out}", file=sys.stderr)


if __name__ == "__main__":
    main()
