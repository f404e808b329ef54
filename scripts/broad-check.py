#!/usr/bin/env python3
"""Scores the default settings on every glTF model in ../shared/scenes from many views none
of them was tuned for, and lists the views over the bounds gnomon holds itself to (all
misclassified < 1 %, false shadow away from edges < 0.05 %, leak away from edges < 0.1 %).
Run from anywhere after `make build`:

    scripts/broad-check.py [--scenes DIR | --models A.obj,B.3ds] [--size WxH]
                           [--lights sun,point,spot] [--only A,B]
                           [--random N [--seed S]] [--flags "--bias-slope 0"]
                           [--out FILE]

Views per model, each with and without `--ground`:
- sun: the model's own camera under four suns (`--sun` at the default, 30,60, 200,20, 120,8);
- point, spot: a point light and a 35° spot placed from the model's bounds (above and to
  one side, about 1.5 radii out), each seen from the model's own camera and from a low
  close camera. Bounds come from the glTF's position accessors through its node
  transforms, so they are the file's, not gnomon's (other formats, given by --models: the box
  gnomon loads them into, from `gnomon --verbose render`);
- random (with --random N): N more views per model, each a camera 1.2 to 3 radii out at a
  random bearing and height (5 degrees below the centre to 60 above), aimed within 0.3 radii
  of the centre, under one random light of the kinds --lights names, in turn: a sun (6 to
  85 degrees high), a point light or a spot (20 to 45 degree cone, aimed within 0.3 radii of
  the centre), both 1.2 to 2.5 radii out and 15 to 75 degrees above; --seed picks another set.
Scene files and score outputs go to a temporary folder; only --out writes a file.
"""
import argparse
import glob
import json
import math
import os
import random
import shlex
import struct
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# $GNOMON picks another build: a whole build tree's binary (a git worktree's, say), not a copy of
# this tree's: the binary loads libgnomon from the tree it was built in, so a copy run while this
# tree rebuilds mixes the two builds.
GNOMON = os.environ.get("GNOMON") or os.path.join(ROOT, "build", "release", "apps", "gnomon", "gnomon")
SCENES = os.path.join(os.path.dirname(ROOT), "shared", "scenes")
BOUNDS = (1.0, 0.05, 0.1)  # misclassified, false shadow away, leak away (percent)
SUNS = [[], ["--sun", "30,60"], ["--sun", "200,20"], ["--sun", "120,8"]]


def gltf_json(path):
    if path.endswith(".glb"):
        data = open(path, "rb").read()
        length = struct.unpack_from("<I", data, 12)[0]
        return json.loads(data[20:20 + length])
    return json.load(open(path))


def node_matrix(node):
    if "matrix" in node:
        m = node["matrix"]
        return [[m[c * 4 + r] for c in range(4)] for r in range(4)]
    t = node.get("translation", [0, 0, 0])
    x, y, z, w = node.get("rotation", [0, 0, 0, 1])
    s = node.get("scale", [1, 1, 1])
    r = [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
         [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
         [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]
    return [[r[i][0] * s[0], r[i][1] * s[1], r[i][2] * s[2], t[i]] for i in range(3)] + [[0, 0, 0, 1]]


def multiply(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(4)) for j in range(4)] for i in range(4)]


def bounds(path):
    """Centre and radius of the default scene's position accessors' boxes, transformed."""
    g = gltf_json(path)
    lo, hi = [math.inf] * 3, [-math.inf] * 3

    def visit(index, parent):
        node = g["nodes"][index]
        m = multiply(parent, node_matrix(node))
        for prim in g["meshes"][node["mesh"]]["primitives"] if "mesh" in node else []:
            a = g["accessors"][prim["attributes"]["POSITION"]]
            for corner in range(8):
                p = [a["max" if corner >> k & 1 else "min"][k] for k in range(3)] + [1]
                w = [sum(m[i][k] * p[k] for k in range(4)) for i in range(3)]
                for k in range(3):
                    lo[k], hi[k] = min(lo[k], w[k]), max(hi[k], w[k])
        for child in node.get("children", []):
            visit(child, m)

    identity = [[float(i == j) for j in range(4)] for i in range(4)]
    for index in g["scenes"][g.get("scene", 0)]["nodes"]:
        visit(index, identity)
    return [(lo[k] + hi[k]) / 2 for k in range(3)], math.dist(lo, hi) / 2


def gnomon_bounds(path):
    """Centre and radius of the box gnomon loads `path` into (`gnomon --verbose render`), for
    formats other than glTF (OBJ, 3DS, FBX... through assimp), whose node transforms this script
    does not read."""
    with tempfile.TemporaryDirectory() as work:
        run = subprocess.run([GNOMON, "--verbose", "render", "--scene", path, "--size", "16x16",
                              "--out", os.path.join(work, "bounds.png")],
                             capture_output=True, text=True)
    line = next((l for l in run.stderr.splitlines() if "scene bounds" in l), None)
    if run.returncode or not line:
        sys.exit(f"broad-check: cannot load {path}: {run.stderr.strip()}")
    lo, hi = ([float(v) for v in part.split(",")] for part in line.split("bounds ")[1].split(" to "))
    return [(lo[k] + hi[k]) / 2 for k in range(3)], math.dist(lo, hi) / 2


def model_bounds(path):
    """glTF 2.0 read here; anything else (glTF 1.0 too, whose dictionaries this reader does
    not walk and which gnomon reads through assimp) as gnomon loads it."""
    if path.endswith((".gltf", ".glb")):
        try:
            c, r = bounds(path)
            if all(math.isfinite(v) for v in c) and math.isfinite(r):
                return c, r
        except (KeyError, TypeError, IndexError, ValueError):
            pass
    return gnomon_bounds(path)


def random_views(model, name, count, rng, kinds, work):
    """`count` random cameras around `model`, each under one random light, as (label, scene,
    flags). The lights take turns through `kinds`: a sun given by flags, or a point or spot
    light placed 1.2 to 2.5 radii out, 15 to 75 degrees above the centre, written with the
    model into a scene file."""
    c, r = model_bounds(model)
    for i in range(count):
        bearing, height = rng.uniform(0, 2 * math.pi), math.radians(rng.uniform(-5, 60))
        d = rng.uniform(1.2, 3.0) * r
        eye = [c[0] + d * math.cos(height) * math.sin(bearing), c[1] + d * math.sin(height),
               c[2] + d * math.cos(height) * math.cos(bearing)]
        target = [c[k] + rng.uniform(-0.3, 0.3) * r for k in range(3)]
        flags = ["--camera-eye", ",".join(f"{v:.5g}" for v in eye),
                 "--camera-target", ",".join(f"{v:.5g}" for v in target)]
        kind = kinds[i % len(kinds)]
        if kind == "sun":
            sun = f"{rng.uniform(0, 360):.1f},{rng.uniform(6, 85):.1f}"
            yield f"{name} random {i} sun {sun}", model, flags + ["--sun", sun]
            continue
        bearing, height = rng.uniform(0, 2 * math.pi), math.radians(rng.uniform(15, 75))
        d = rng.uniform(1.2, 2.5) * r
        position = [c[0] + d * math.cos(height) * math.sin(bearing), c[1] + d * math.sin(height),
                    c[2] + d * math.cos(height) * math.cos(bearing)]
        light = {"type": kind, "position": [round(v, 5) for v in position]}
        label = f"{name} random {i} {kind} at {','.join(f'{v:.3g}' for v in position)}"
        if kind == "spot":
            aim = [c[k] + rng.uniform(-0.3, 0.3) * r for k in range(3)]
            outer = rng.uniform(20, 45)
            light.update({"direction": [round(aim[k] - position[k], 5) for k in range(3)],
                          "outer-cone": round(outer, 1), "inner-cone": round(0.8 * outer, 1)})
            label += f" cone {outer:.0f}"
        path = os.path.join(work, f"{name}-random-{i}.json")
        with open(path, "w") as f:
            json.dump({"gnomon-scene": 1, "include": [{"scene": model}], "lights": [light]}, f)
        yield label, path, flags


def views(model, kinds, work, random_count=0, rng=None):
    """(label, scene file or model, extra flags) for every view of `model`."""
    name = os.path.basename(model).split(".")[0]
    if "sun" in kinds:
        for sun in SUNS:
            yield f"{name} sun {sun[1] if sun else 'default'}", model, sun
    if random_count:
        yield from random_views(model, name, random_count, rng,
                                [k for k in ("sun", "point", "spot") if k in kinds], work)
    if not {"point", "spot"} & set(kinds):
        return
    c, r = model_bounds(model)
    at = lambda k: [c[i] + r * k[i] for i in range(3)]
    lights = {"point": {"type": "point", "position": at([0.6, 1.2, 0.8])},
              "spot": {"type": "spot", "position": at([-1.0, 1.5, 1.0]), "direction": [1.0, -1.5, -1.0],
                       "outer-cone": 35, "inner-cone": 25}}
    cameras = {"own": None, "low": {"eye": at([1.3, 0.25, 1.3]), "centre": c, "near": 0.02 * r, "far": 20 * r}}
    for kind in (k for k in ("point", "spot") if k in kinds):
        for camera_name, camera in cameras.items():
            scene = {"gnomon-scene": 1, "include": [{"scene": model}], "lights": [lights[kind]]}
            if camera:
                scene["camera"] = camera
            path = os.path.join(work, f"{name}-{kind}-{camera_name}.json")
            with open(path, "w") as f:
                json.dump(scene, f)
            yield f"{name} {kind} {camera_name} camera", path, []


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--scenes", default=SCENES)
    parser.add_argument("--size", default="384x384")
    parser.add_argument("--lights", default="sun,point,spot")
    parser.add_argument("--only", default="", help="comma-separated parts of model names")
    parser.add_argument("--models", default="",
                        help="comma-separated model files of any format gnomon reads, checked "
                             "instead of --scenes' glTF models (models none of gnomon's work "
                             "was tried on: Debian's glmark2-data, say)")
    parser.add_argument("--out", help="also write the table as a markdown page")
    parser.add_argument("--flags", default="",
                        help="gnomon score flags added to every view (a candidate default)")
    parser.add_argument("--random", type=int, default=0,
                        help="also this many random cameras and lights per model")
    parser.add_argument("--seed", type=int, default=1, help="which random views")
    args = parser.parse_args()
    rng = random.Random(args.seed)
    extra = shlex.split(args.flags)
    if args.models:
        models = args.models.split(",")
    else:
        models = sorted(glob.glob(os.path.join(args.scenes, "*", "*.gltf")) +
                        glob.glob(os.path.join(args.scenes, "*", "*.glb")))
    if args.only:
        models = [m for m in models if any(o in os.path.basename(m) for o in args.only.split(","))]
    if not models:
        sys.exit(f"broad-check: no model under {args.scenes} (or given by --models)")
    over, total, lines = [], 0, []

    def emit(line):
        print(line, flush=True)
        lines.append(line)

    emit("| view | ground | misclassified % | false shadow away % | leak away % |")
    emit("|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as work:
        for model in models:
            for label, scene, flags in views(model, args.lights.split(","), work, args.random, rng):
                for ground in ([], ["--ground"]):
                    run = subprocess.run([GNOMON, "score", "--scene", scene, "--size", args.size,
                                          "--out-dir", os.path.join(work, "out")] + flags + ground + extra,
                                         capture_output=True, text=True)
                    total += 1
                    if run.returncode:
                        emit(f"| {label} | {'yes' if ground else 'no'} | failed: {run.stderr.strip()} | | |")
                        over.append(label)
                        continue
                    with open(os.path.join(work, "out", "score.json")) as f:
                        s = json.load(f)["overall"]
                    row = (100 * s["misclassified"], 100 * s["false_shadow_outside_band"],
                           100 * s["leak_outside_band"])
                    mark = " **over**" if any(v >= b for v, b in zip(row, BOUNDS)) else ""
                    if mark:
                        over.append(f"{label}{' ground' if ground else ''}")
                    emit(f"| {label} | {'yes' if ground else 'no'} | {row[0]:.3f}{mark} | "
                         f"{row[1]:.3f} | {row[2]:.3f} |")
    summary = f"{total - len(over)} of {total} views within bounds"
    summary += ": over: " + "; ".join(over) if over else ""
    print("\n" + summary)
    if args.out:
        head = __doc__.split("Run from")[0].strip().replace("\n", " ")
        if args.models:
            names = ", ".join(os.path.basename(m) for m in models)
            head = head.replace("every glTF model in ../shared/scenes",
                                f"the models given ({names})")
        commit = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"],
                                capture_output=True, text=True).stdout.strip()
        page = ["# Broad check: every model, many views, default settings", "",
                head, "", f"`scripts/broad-check.py --size {args.size}{' --flags ' + shlex.quote(args.flags) if args.flags else ''}"
                f"{f' --lights {args.lights}' if args.lights != 'sun,point,spot' else ''}"
                f"{f' --random {args.random} --seed {args.seed}' if args.random else ''}"
                f"{f' --models {args.models}' if args.models else ''} --out FILE`, at commit {commit}. "
                + summary + ".", ""] + lines
        tmp = args.out + ".tmp"
        with open(tmp, "w") as f:
            f.write("\n".join(page) + "\n")
        os.replace(tmp, args.out)


if __name__ == "__main__":
    main()
