#!/usr/bin/env bash
# CLI behaviour: exit codes and messages. Usage: cli_test.sh GNOMON_BINARY CASE WORKDIR
# Exit codes of gnomon: 0 success, 1 failure (writing output, GL), 2 bad usage or input (a
# missing input file too), 3 score above --max-error, 130 interrupted (Ctrl-C).
# The measuring commands' cases (bench, score) are in cli_measure_test.sh.
source "$(dirname "$0")/cli_common.sh"

case $case in
unknown_scene)
    run render --scene no-such-scene --out "$work/a.png"
    expect 2 "unknown scene 'no-such-scene'"
    expect 2 "book-triangle"  # the message lists the known scenes
    ! grep -q "did you mean" "$work/stderr" || fail "a name far from every scene got a guess"
    # A slip of the keyboard: the scene meant is named before the list.
    run render --scene tutorial-rom --out "$work/a.png"
    expect 2 "unknown scene 'tutorial-rom'; did you mean tutorial-room? (built-in scenes:"
    ;;
gltf)
    corpus=$(dirname "$0")/../data/gltf
    run render --scene "$corpus/triangle.gltf" --size 32x32 --out "$work/t.png"
    skip_without_gl
    expect 0 "warning: meshes[0].primitives[0] has no normals: flat ones generated"
    [[ -s "$work/t.png" ]] || fail "no t.png"
    run render --scene "$corpus/index_out_of_range.gltf" --out "$work/b.png"
    expect 2 "index_out_of_range.gltf: accessors[1] holds index 7"
    [[ -e "$work/b.png" ]] && fail "an image was written for a broken scene"
    printf 'not a model\n' >"$work/model.xyzzy"
    run render --scene "$work/model.xyzzy" --out "$work/o.png"
    expect 2 "'.xyzzy' files are not supported; gnomon reads glTF 2.0"
    ;;
assimp)
    models=$(dirname "$0")/../data/models
    run render --scene "$models/two_parts.obj" --size 64x64 --out "$work/o.png"
    skip_without_gl
    expect 0 "warning: no lights: a default sun was added"
    [[ -s "$work/o.png" ]] || fail "no o.png"
    run render --scene "$models/two_parts.obj" --size 64x64 --out "$work/o.png" --sun 30,60
    expect 0 ""
    grep -q "default sun" "$work/stderr" && fail "--sun replaced the added sun, yet its warning stayed"
    run render --scene "$models/textured.obj" --size 64x64 --out "$work/t.png"
    expect 0 "no camera"
    [[ -s "$work/t.png" ]] || fail "no t.png"
    run render --scene "$models/broken.dae" --out "$work/b.png"
    expect 2 "broken.dae: assimp cannot read it"
    [[ -e "$work/b.png" ]] && fail "an image was written for a broken model"
    ;;
view_input)
    # gnomon view reports bad input before it opens a window (no display needed here).
    run view --window 10x10
    expect 2 "--window: 10x10 is outside"
    run view --script "$work/missing.txt"
    expect 2 "--script: no such file"
    printf 'wait 1\nexplode now\n' >"$work/bad.txt"
    run view --script "$work/bad.txt"
    expect 2 "bad.txt:2: unknown command 'explode'"
    run view --scene no-such-scene
    expect 2 "no-such-scene"
    run view --screenshot-dir "$work/nope"
    expect 2 "--screenshot-dir: '$work/nope' is not a folder"
    run view --filter blurry
    expect 2 "--filter: expected one of"
    printf 'quit\n' >"$work/quit.txt"
    DISPLAY= WAYLAND_DISPLAY= run view --script "$work/quit.txt"
    expect 1 "cannot open a window"
    ;;
scene_file)
    examples=$(dirname "$0")/../../examples/scenes
    run --verbose render --scene "$examples/tutorial-room.json" --size 64x64 --out "$work/room.png"
    skip_without_gl
    expect 0 "loaded 'tutorial-room'"
    expect 0 "7 objects, 1 lights"
    # Where the scene lies, for placing lights and cameras: the room's floor, walls and beams.
    expect 0 "scene bounds -10.5,-0.5,-10.5 to 10.5,6,10.5"
    [[ -s "$work/room.png" ]] || fail "no room.png"
    grep -q "warning" "$work/stderr" && fail "warnings for an example: $(cat "$work/stderr")"
    printf '{"gnomon-scene": 1, "include": [{"scene": "tutorial-room"}], "options": {"filtre": "pcf"}}' \
        >"$work/typo.json"
    run render --scene "$work/typo.json" --out "$work/typo.png"
    expect 2 "typo.json: options: unknown key \"filtre\""
    [[ -e "$work/typo.png" ]] && fail "an image was written for a broken scene file"
    ;;
missing_file)
    run render --scene "$work/nothing.gltf" --out "$work/a.png"
    expect 2 "gnomon: error: cannot load scene '$work/nothing.gltf': no such file"
    # A folder: which of its files to give, not a list of every extension.
    mkdir -p "$work/model"
    run render --scene "$work/model" --out "$work/a.png"
    expect 2 "cannot load scene '$work/model': it is a folder; it holds no file gnomon reads"
    printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >"$work/model/tri.obj"
    run render --scene "$work/model" --out "$work/a.png"
    expect 2 "it is a folder; give one of the files in it, such as $work/model/tri.obj"
    [[ ! -e "$work/a.png" ]] || fail "a refused render left a.png behind"
    ;;
unwritable_output)
    run render --scene book-triangle --size 32x32 --out "$work/no/such/folder/a.png"
    skip_without_gl
    expect 1 "cannot write '$work/no/such/folder/a.png'"
    [[ -z "$(ls -A "$work" | grep -v -e stdout -e stderr -e code)" ]] || fail "left files behind"
    ;;
malformed_size)
    run render --scene book-triangle --size 12by12 --out "$work/a.png"
    expect 2 "--size: expected WIDTHxHEIGHT"
    run render --scene book-triangle --size 0x12 --out "$work/a.png"
    expect 2 "outside 1x1..16384x16384"
    run render --scene book-triangle --size 100000x100000 --out "$work/a.png"
    expect 2 "size 100000x100000 is outside 1x1..16384x16384"
    ;;
bad_enum)
    run render --scene book-triangle --filter blurry --out "$work/a.png"
    expect 2 "--filter: expected one of none, hw2x2, pcf, poisson, pcss, evsm2, evsm4, msm, got 'blurry'"
    ;;
cascades)
    # Auto and explicit counts, the share of each map the view uses, and bad values.
    run --verbose render --scene tutorial-room --cascades 4 --size 64x64 --out "$work/c.png"
    skip_without_gl
    expect 0 "light 0 cascade 3: 2048² map, the view uses"
    run render --scene tutorial-room --cascades 5 --size 64x64 --out "$work/c5.png"
    expect 2 "cascades must be auto (0) or in 1..4, got 5"
    [[ ! -e "$work/c5.png" ]] || fail "a refused render left c5.png behind"
    run render --scene tutorial-room --fit-to nowhere --size 64x64 --out "$work/c.png"
    expect 2 "--fit-to: expected one of view-depth, boxes, got 'nowhere'"
    run render --scene tutorial-room --cascades auto --fit-to boxes --size 64x64 --out "$work/c.png"
    [[ $(cat "$work/code") == 0 && -s "$work/c.png" ]] || fail "auto cascades with boxes: $(cat "$work/stderr")"
    ;;
map_sizes)
    # A light without a map size takes its default: 2048 for a sun, a spot and a point light
    # drawn as one map, 1024 per face for a point light drawn as a cube or as maps per face.
    cat >"$work/lights.json" <<'JSON'
{"gnomon-scene": 1, "include": [{"scene": "book-triangle"}],
 "lights": [{"type": "directional", "direction": [0, -1, 0.2]},
            {"type": "spot", "position": [0, 7, 2], "direction": [0, -1, -0.2]},
            {"type": "directional", "direction": [0.1, -1, 0], "shadow-map-size": 512},
            {"type": "point", "position": [0, 1, 0]},
            {"type": "point", "position": [0, 7, 2],
             "shadow-camera": {"policy": "manual", "target": [0, 0, 0], "fovy": 90}}]}
JSON
    run --verbose render --scene "$work/lights.json" --cascades 1 --size 64x64 --out "$work/m.png"
    skip_without_gl
    expect 0 "light 3 face 3 (-Y): 1024² map"
    run --verbose render --scene "$work/lights.json" --cascades 1 --point-maps cube --size 64x64 \
        --out "$work/m.png"
    expect 0 "light 0: 2048² map"
    expect 0 "light 1: 2048² map"
    expect 0 "light 2: 512² map"
    expect 0 "light 3: 1024² cube"
    expect 0 "light 4: 2048² map"
    # The same point light far above the triangle, whose view then fits one frustum.
    sed 's/"position": \[0, 1, 0\]/"position": [0, 40, 0.1]/' "$work/lights.json" >"$work/far.json"
    run --verbose render --scene "$work/far.json" --cascades 1 --size 64x64 --out "$work/m.png"
    expect 0 "light 3: 2048² map"
    run --verbose render --scene "$work/lights.json" --cascades 1 --map-size 256 --size 64x64 \
        --out "$work/m.png"
    expect 0 "light 0: 256² map"
    ;;
bad_light)
    run render --scene book-triangle --light-only 3 --out "$work/a.png"
    expect 2 "has 1 light(s)"
    ;;
help)
    run render --help
    expect 0 "--shadows"
    for flag in --size --time --light-only --shadow-maps --outside --map-size --bias-constant \
                --bias-depth-aware --preset \
                --bias-slope --bias-units --normal-offset --cull --filter --pcf-size \
                --light-radius --light-angle --cascades --fit-to --cascade-lambda --cascade-blend \
                --debug-view --shadowed --shadow-factor --depth-format --map-filter; do
        grep -qF -- "$flag" "$work/stdout" || fail "help lacks $flag"
    done
    grep -qF -- "default" "$work/stdout" || fail "help shows no defaults"
    for cmd in "" render score bench view scenes options; do
        wide=$("$gnomon" $cmd --help | awk 'length > 100')
        [[ -z $wide ]] || fail "gnomon $cmd --help has lines over 100 columns: $wide"
    done
    grep -q "^Tolerances:" "$work/stdout" || fail "help is not grouped"
    ;;
outputs)
    # The format follows the extension; a failed render leaves nothing it wrote behind.
    run render --scene book-triangle --size 32x32 --out "$work/a.jpg"
    skip_without_gl
    [[ $(cat "$work/code") == 0 ]] || fail "a.jpg: $(cat "$work/stderr")"
    [[ $(od -An -tx1 -N2 "$work/a.jpg" | tr -d ' ') == ffd8 ]] || fail "a.jpg is not JPEG"
    run render --scene book-triangle --size 32x32 --out "$work/a.bmp"
    expect 2 "the format follows the extension: .png, .jpg or .jpeg"
    [[ ! -e "$work/a.bmp" ]] || fail "a refused format was written"
    touch "$work/file"
    run render --scene book-triangle --size 32x32 --out "$work/b.png" --shadow-maps "$work/file/maps"
    expect 1 "--shadow-maps: cannot create folder"
    [[ ! -e "$work/b.png" ]] || fail "b.png left behind by a failed render"
    ;;
scene_flags)
    # The camera and a sun from the command line move the picture; bad values say where.
    run render --scene tutorial-room --size 32x32 --out "$work/a.png"
    skip_without_gl
    run render --scene tutorial-room --size 32x32 --out "$work/b.png" --camera-eye 6,4,8 \
        --camera-target 0,1,0 --camera-fov 50
    [[ $(cat "$work/code") == 0 ]] || fail "camera flags: $(cat "$work/stderr")"
    run render --scene tutorial-room --size 32x32 --out "$work/c.png" --sun 30,60
    [[ $(cat "$work/code") == 0 ]] || fail "--sun: $(cat "$work/stderr")"
    cmp -s "$work/a.png" "$work/b.png" && fail "--camera-* changed nothing"
    cmp -s "$work/a.png" "$work/c.png" && fail "--sun changed nothing"
    run render --scene tutorial-room --out "$work/d.png" --camera-eye 1,2
    expect 2 "--camera-eye: expected X,Y,Z"
    run render --scene tutorial-room --out "$work/d.png" --camera-fov 0
    expect 2 "--camera-fov: must be in 1..179 degrees, got 0"
    grep -q "got 0\.0" "$work/stderr" && fail "--camera-fov: the number is not shown as given"
    run render --scene tutorial-room --out "$work/d.png" --sun 10,-5
    expect 2 "--sun: expected AZIMUTH,ELEVATION"
    [[ ! -e "$work/d.png" ]] || fail "a refused render left d.png"
    # A camera turned away from the scene renders, and says that it shows none of it.
    run render --scene tutorial-room --size 32x32 --out "$work/e.png" --camera-eye 0,5,30 \
        --camera-target 0,5,60
    expect 0 "sees none of the scene, or all of it within a pixel: the image holds the background"
    [[ -e "$work/e.png" ]] || fail "the turned-away render wrote nothing"
    # So does one so far away that the whole scene falls within a pixel.
    run render --scene tutorial-room --size 32x32 --out "$work/e.png" --camera-eye 1e30,0,0
    expect 0 "sees none of the scene, or all of it within a pixel"
    run render --scene tutorial-room --size 32x32 --out "$work/f.png" --camera-eye 6,4,8
    grep -q "sees none" "$work/stderr" && fail "warned of a camera that sees the room"
    # A model without a camera gets a framing one, unless the flags place the camera.
    post="$(dirname "$0")/../data/models/post_z_up.stl"
    run render --scene "$post" --size 32x32 --out "$work/g.png"
    expect 0 "no camera: one framing the scene was added"
    run render --scene "$post" --size 32x32 --out "$work/g.png" --camera-eye 3,2,3 \
        --camera-target 0,0.5,0 --camera-fov 40
    grep -q "no camera" "$work/stderr" && fail "warned of a framing camera the flags replaced"
    ;;
install)
    # README's way to a bare `gnomon`: `make install` into a prefix that needs no root.
    src="$(dirname "$0")/../.."
    build="$(cd "$(dirname "$gnomon")/../.." && pwd)"
    make -n -C "$src" install PREFIX="$work/prefix" >"$work/stdout" 2>&1 ||
        fail "make install: $(cat "$work/stdout")"
    grep -qE -- "--install build/(release|asan) --prefix $work/prefix" "$work/stdout" ||
        fail "make install does not install into PREFIX: $(cat "$work/stdout")"
    grep -q "make install" "$src/README.md" || fail "README does not say how to install"
    cmake --install "$build" --prefix "$work/prefix" >/dev/null || fail "cmake --install failed"
    PATH="$work/prefix/bin:$PATH" gnomon --version >"$work/stdout" 2>&1 ||
        fail "the installed gnomon does not run: $(cat "$work/stdout")"
    ;;
up_axis)
    # A Z-up model (CAD's STL) stands up with --up z; --up names model files' axes only.
    post="$(dirname "$0")/../data/models/post_z_up.stl"
    run render --scene "$post" --size 32x32 --out "$work/lying.png"
    skip_without_gl
    run render --scene "$post" --size 32x32 --out "$work/standing.png" --up z
    [[ $(cat "$work/code") == 0 ]] || fail "--up z: $(cat "$work/stderr")"
    cmp -s "$work/lying.png" "$work/standing.png" && fail "--up z changed nothing"
    run render --scene "$post" --out "$work/bad.png" --up w
    expect 2 "--up: expected one of x, y, z, got 'w'"
    run render --scene tutorial-room --out "$work/bad.png" --up z
    expect 2 "--up applies to model files; 'tutorial-room' is a built-in scene"
    [[ ! -e "$work/bad.png" ]] || fail "a refused render left bad.png"
    ;;
pointless_flags)
    # A flag the other options make pointless is said once, and the render still runs.
    run render --scene book-triangle --size 32x32 --out "$work/p.png" --filter pcss --pcf-size 5
    skip_without_gl
    expect 0 "gnomon: warning: --pcf-size does nothing here: it applies only with --filter pcf or poisson"
    [[ $(grep -c "pcf-size" "$work/stderr") == 1 ]] || fail "warned more than once"
    run render --scene book-triangle --size 32x32 --out "$work/q.png" --filter pcss --light-radius 0.5
    [[ ! -s "$work/stderr" ]] || fail "a flag that matters was warned about: $(cat "$work/stderr")"
    run render --scene tutorial-directional --size 32x32 --out "$work/r.png" --cascades 1 \
        --debug-view cascades
    expect 0 "gnomon: warning: --debug-view does nothing here: it applies only with --cascades"
    run render --scene book-triangle --size 32x32 --out "$work/s.png" --debug-view cascades
    expect 0 "--debug-view cascades does nothing here: the scene has no shadowed directional light"
    ;;
option_tables)
    # The docs' option tables are the schema's: README.md and docs/scene-file.md hold
    # exactly what `gnomon options --markdown` prints between their markers.
    root=$(cd "$(dirname "$0")/../.." && pwd)
    for pair in "flags:README.md" "scene-file:docs/scene-file.md"; do
        kind=${pair%%:*}; doc=$root/${pair#*:}
        "$gnomon" options --markdown "$kind" >"$work/$kind.md" || fail "gnomon options --markdown $kind"
        sed -n "/<!-- options:$kind -->/,/<!-- options:end -->/p" "$doc" | sed '1d;$d' >"$work/$kind.doc"
        [[ -s $work/$kind.doc ]] || fail "$doc has no <!-- options:$kind --> table"
        diff -u "$work/$kind.doc" "$work/$kind.md" >"$work/$kind.diff" ||
            fail "$doc's option table differs from the schema (update it with gnomon options --markdown $kind): $(cat "$work/$kind.diff")"
    done
    # And the text listing names every option.
    run options
    expect 0 "bias-constant"
    expect 0 "cascades"
    ;;
usage)
    # A mistyped command: the nearest one named, exit 2.
    run rendr --scene book-triangle
    expect 2 "gnomon: error: unknown command 'rendr'; did you mean 'render'?"
    # A word no command is near: the list alone.
    run xyzzy --scene book-triangle
    expect 2 "gnomon: error: unknown command 'xyzzy' (commands: scenes, options, render"
    # Global flags after the command, as before it.
    run render --verbose --scene book-triangle --size 32x32 --out "$work/v.png"
    skip_without_gl
    expect 0 "OpenGL"
    # CLI11's own complaints carry gnomon's prefix and say where help is.
    run render --bogus
    expect 2 "gnomon: error: "
    expect 2 "--help"
    # Words nobody took are named as given.
    run render --scene book-triangle --out "$work/w.png" --bogus 1
    expect 2 "gnomon: error: unknown flag or stray value: --bogus 1 (see gnomon render --help)"
    # A mistyped flag: the nearest one named.
    run render --scene book-triangle --out "$work/w.png" --map-sise 512
    expect 2 "unknown flag or stray value: --map-sise 512; did you mean --map-size? (see"
    run
    expect 2 "gnomon: error: "
    ;;
scenes)
    run scenes
    expect 0 "course-two-lights"
    [[ $("$gnomon" scenes --names | wc -l) -ge 6 ]] || fail "fewer than 6 built-in scenes"
    ;;
render_and_maps)
    run --verbose render --scene course-two-lights --size 64x64 --out "$work/a.png" --shadow-maps "$work/maps"
    skip_without_gl
    expect 0 "OpenGL"
    [[ -s "$work/a.png" ]] || fail "no image"
    [[ -s "$work/maps/light-0.png" && -s "$work/maps/light-1.png" ]] || fail "maps missing"
    # 16-bit greyscale: IHDR bit depth byte (offset 24) is 16, colour type (25) is 0.
    [[ $(od -An -tu1 -j24 -N2 "$work/maps/light-0.png" | tr -s ' ') == " 16 0" ]] || fail "map is not 16-bit grey"
    ls -A "$work" | grep -q '^\.' && fail "temporary files left behind"
    ;;
no_gl)
    # glvnd with no vendor library: the machine has libEGL but no driver behind it.
    __EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json run render --scene book-triangle --out "$work/a.png"
    expect 1 "no usable OpenGL: libEGL found no EGL driver"
    [[ $(wc -l <"$work/stderr") -eq 1 ]] || fail "expected one sentence, got: $(cat "$work/stderr")"
    ;;
*) fail "unknown case" ;;
esac
echo "ok ($case)"
