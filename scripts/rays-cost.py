#!/usr/bin/env python3
"""What --shadow-rays uncertain costs against the maps alone, written to
docs/results/shadow-rays.md.

One gnomon binary, the two modes alternating round by round (`gnomon bench --frames 20`, maps
alone then uncertain), so the machine's drift hits both alike; per scene the median over rounds
of each run's median frame and of the main pass's fastest tenth, and their ratios. The scenes:
glmark2's shadow scene as the peer benchmark draws it (800x600), the same at 512x512,
tutorial-room and Sponza's atrium at 512x512 (the atrium when ../shared/scenes holds Sponza).
The share of pixel-light pairs traced comes from one `gnomon score` of each view. Takes about
ten minutes on an otherwise idle machine. Usage:
    scripts/rays-cost.py [--rounds N] [--gnomon PATH] [--out FILE] [--print]
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PEER = os.path.join(ROOT, "bench", "peers", "glmark2", "shadow.json")


def views(work):
    """(name, scene, flags) of each measured view; the atrium only when its model is here."""
    out = [("glmark2's scene, 800×600", PEER, []),
           ("glmark2's scene, 512×512", PEER, ["--size", "512x512"]),
           ("tutorial-room, 512×512", "tutorial-room", ["--size", "512x512"])]
    atrium = os.path.join(work, "atrium.json")
    made = subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "quality-real.py"),
                           "--write-scene", "sponza-atrium", atrium], capture_output=True)
    if made.returncode == 0:
        out.append(("Sponza's atrium, 512×512", atrium, ["--size", "512x512"]))
    else:
        print("Sponza is not in ../shared/scenes: its atrium is left out", file=sys.stderr)
    return out


def bench(gnomon, scene, flags, mode, work):
    """(median frame, main pass p10) of one `gnomon bench` run, in ms."""
    out = os.path.join(work, "bench")
    subprocess.run([gnomon, "bench", "--scene", scene, "--frames", "20", "--out-dir", out,
                    "--shadow-rays", mode] + flags, check=True, capture_output=True)
    run = json.load(open(os.path.join(out, "bench.json")))["runs"][0]
    main = next(p for p in run["passes"] if p["name"] == "main")
    return run["frame_ms"]["median"], main["ms"]["p10"]


def traced(gnomon, scene, flags, work):
    """The share of pixel-light pairs a ray decided under uncertain, from `gnomon score`."""
    out = os.path.join(work, "score")
    subprocess.run([gnomon, "score", "--scene", scene, "--shadow-rays", "uncertain",
                    "--out-dir", out] + flags, check=True, capture_output=True)
    return json.load(open(os.path.join(out, "score.json")))["overall"]["traced"]


def measure(gnomon, rounds, work):
    rows = []
    for name, scene, flags in views(work):
        ms = {"off": [], "uncertain": []}
        for _ in range(rounds):
            for mode in ms:
                ms[mode].append(bench(gnomon, scene, flags, mode, work))
        med = {m: [statistics.median(r[k] for r in ms[m]) for k in (0, 1)] for m in ms}
        rows.append((name, med["off"], med["uncertain"], traced(gnomon, scene, flags, work)))
        print(f"{name}: {med['off'][0]:.1f} -> {med['uncertain'][0]:.1f} ms", file=sys.stderr)
    return rows


def page(rows, rounds, gl):
    lines = [
        "# Results: what `--shadow-rays uncertain` costs",
        "",
        "**Regenerate.** `scripts/rays-cost.py` (about ten minutes, on an otherwise idle "
        "machine). It runs `gnomon bench --frames 20` with the maps alone (`--shadow-rays off`) "
        f"and with `--shadow-rays uncertain` in turn, {rounds} rounds, and gives per view the "
        "median over rounds of each run's median frame and of the main pass's fastest tenth "
        "of frames; *traced* is the share of pixel-light pairs a ray decided, from "
        "`gnomon score` of the same view. The machine is shared and noisy (15–35 % between "
        "runs): the ratios, measured side by side, move less than the times.",
        "",
        f"Driver: {gl}.",
        "",
        "| view | frame, maps alone | frame, uncertain | ratio | main pass p10, maps alone "
        "| main pass p10, uncertain | traced |",
        "|---|---|---|---|---|---|---|",
    ]
    for name, off, unc, share in rows:
        lines.append(f"| {name} | {off[0]:.1f} ms | {unc[0]:.1f} ms | {unc[0] / off[0]:.2f}× "
                     f"| {off[1]:.1f} ms | {unc[1]:.1f} ms | {100 * share:.2f} % |")
    lines += [
        "",
        "glmark2's scene is `bench/peers/glmark2/shadow.json`, the view the peer benchmark "
        "draws (a 1386² map, `--filter none`); the atrium is `scripts/quality-real.py "
        "--write-scene sponza-atrium`. Why the ratio is what it is, and where the frame goes: "
        "[the technique's page](../techniques/shadow-maps.md#shadow-rays).",
        "",
    ]
    return "\n".join(lines)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--rounds", type=int, default=7)
    ap.add_argument("--gnomon", default=os.path.join(ROOT, "build", "release", "apps",
                                                     "gnomon", "gnomon"))
    ap.add_argument("--out", default=os.path.join(ROOT, "docs", "results", "shadow-rays.md"))
    ap.add_argument("--print", action="store_true", help="print the page instead of writing it")
    a = ap.parse_args()
    with tempfile.TemporaryDirectory() as work:
        rows = measure(a.gnomon, a.rounds, work)
        gl = json.load(open(os.path.join(work, "bench", "bench.json"))).get("gl", "?")
    text = page(rows, a.rounds, gl)
    if a.print:
        print(text)
        return
    tmp = a.out + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, a.out)
    print(f"wrote {a.out}", file=sys.stderr)


if __name__ == "__main__":
    main()
