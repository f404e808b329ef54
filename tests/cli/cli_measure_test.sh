#!/usr/bin/env bash
# The measuring commands as a user meets them (bench, score, tune, an interrupted sweep, the maps'
# memory): exit codes, messages and what they write. Usage: cli_measure_test.sh GNOMON_BINARY
# CASE WORKDIR (exit codes as in cli_test.sh).
source "$(dirname "$0")/cli_common.sh"

case $case in
interrupt)
    # Ctrl-C in a sweep: exit 130 with the finished values saved and the progress line ended.
    vals=$(printf '256,%.0s' {1..19})256
    "$gnomon" bench --scene tutorial-room --size 128x128 --frames 50 --warmup 0 --sweep map-size \
        --values "$vals" --out-dir "$work/s" >"$work/stdout" 2>"$work/stderr" &
    pid=$!
    for _ in $(seq 600); do grep -q "\[1/20\]" "$work/stderr" 2>/dev/null && break; sleep 0.1; done
    skip_without_gl
    kill -INT $pid; wait $pid; echo $? >"$work/code"
    expect 130 "gnomon: interrupted while measuring ["
    expect 130 "values finished"
    rows=$(($(wc -l <"$work/s/sweep.csv") - 1))
    ((rows >= 1 && rows < 20)) || fail "sweep.csv should hold the finished values only, has $rows"
    ! grep -q $'\r' "$work/stderr" || fail "progress lines written to a file that is not a terminal"
    # On a terminal (script(1) gives one), long work shows an activity line.
    if command -v script >/dev/null; then
        script -qec "'$gnomon' bench --scene tutorial-room --size 128x128 --frames 400 --warmup 0 \
            --out-dir '$work/t'" /dev/null >"$work/stdout" 2>"$work/stderr"
        echo $? >"$work/code"
        expect 0 "gnomon: measuring tutorial-room ..."
    fi
    ;;
map_memory)
    # 24 maps of 8192^2 depth32f (14 lights' maps and the two point lights' faces: 6 GiB in one
    # array): one sentence with the size and what to lower, exit 2, and no image left behind.
    # llvmpipe refuses any texture over its size limit (well below 6 GiB); a driver that stored
    # it would fail here with exit 0.
    run render --scene mixed-lights --map-size 8192 --size 32x32 --out "$work/m.png"
    skip_without_gl
    expect 2 "need 6.00 GiB in one texture"
    expect 2 "lower --map-size or the number of shadowed lights"
    [[ ! -e "$work/m.png" ]] || fail "a refused render left m.png behind"
    ;;
bench)
    run bench --scene tutorial-room --size 64x64 --frames 2 --warmup 1 --out-dir "$work/b"
    skip_without_gl
    expect 0 "shadow light 0"
    expect 0 "reference: shadows off"
    python3 - "$work/b/bench.json" <<'PY' || fail "bench.json incomplete"
import json, sys
j = json.load(open(sys.argv[1]))
r = j["runs"][0]
for k in ["frame_ms", "shadow_ms", "main_ms", "shadows_off_ms", "bare_depth_ms"]:
    assert set(r[k]) == {"median", "p10", "p90"}, k
for k in ["map_size", "maps", "shadow_map_bytes", "shadow_triangles", "main_triangles"]:
    assert k in r, k
names = [p["name"] for p in r["passes"]]
assert names == ["view depth", "shadow light 0", "main", "read-back"], names
for p in r["passes"]:
    assert set(p) == {"name", "ms", "triangles", "fragments"}, p
# The view's depth is drawn each frame (its sun is fitted to it): every triangle of the room.
assert r["passes"][0]["triangles"] == r["main_triangles"] > 0, r["passes"][0]
assert r["moment_passes"] == 0, r["moment_passes"]
# The floor, as two medians and as each frame's own ratio. Its value is a timing and this
# machine is noisy (a 64x64 frame can take either pass first), so only its presence and
# sanity are asserted, never a bound.
import math
assert set(r["main_floor_ms"]) == {"median", "p10", "p90"}, r["main_floor_ms"]
assert math.isfinite(r["main_over_floor"]) and r["main_over_floor"] > 0, r["main_over_floor"]
PY
    # The moment filters' pass is timed and counted beside the shadow pass.
    run bench --scene tutorial-room --size 64x64 --frames 1 --warmup 0 --filter msm \
        --out-dir "$work/bm"
    expect 0 "moments light 0"
    expect 0 "1 moment pass(es) a frame"
    run bench --scene tutorial-room --size 64x64 --frames 1 --warmup 0 --sweep map-size \
        --values 256,512 --out-dir "$work/s"
    expect 0 "sweep.svg"
    [[ $(wc -l <"$work/s/sweep.csv") == 3 ]] || fail "sweep.csv should have a header and 2 rows"
    head -1 "$work/s/sweep.csv" | grep -q "^value,frame_ms,frame_p10,frame_p90,shadow_ms" ||
        fail "sweep.csv header"
    grep -q "<polyline" "$work/s/sweep.svg" || fail "sweep.svg has no lines"
    run bench --scene tutorial-room --sweep colour
    expect 2 "--sweep: expected lights, local-lights, map-size, triangles, cascades, filter or"
    # Local lights: a sweep's table and CSV, and one value's scene written as a file that
    # renders (and measures nothing).
    run bench --scene tutorial-room --size 64x64 --frames 1 --warmup 0 --sweep local-lights \
        --values 1,4 --out-dir "$work/l"
    expect 0 "local-lights"
    [[ $(wc -l <"$work/l/sweep.csv") == 3 ]] || fail "local-lights sweep.csv should have 2 rows"
    (cd "$work" && run bench --scene tutorial-room --sweep local-lights --values 6 \
        --write-scene six.json)
    expect 0 "6 lights"
    [[ ! -e "$work/bench" ]] || fail "--write-scene made the bench folder"
    run render --scene "$work/six.json" --size 64x64 --out "$work/six.png"
    [[ $(cat "$work/code") == 0 && -s "$work/six.png" ]] ||
        fail "six.json does not render: $(cat "$work/stderr")"
    [[ $(grep -c '"type": "spot"' "$work/six.json") == 3 ]] || fail "six.json: 3 spot lights"
    # Moving lights under a redraw budget: at most the budget's maps drawn a frame, the
    # others wait (the first frame draws them all: nothing is held yet).
    run bench --scene mixed-lights --size 64x64 --frames 3 --warmup 1 --moving-lights \
        --map-redraws 2 --out-dir "$work/mv"
    expect 0 "drawn and"
    python3 - "$work/mv/bench.json" <<'PY' || fail "moving lights under --map-redraws 2"
import json, sys
j = json.load(open(sys.argv[1]))
r = j["runs"][0]
assert j["moving_lights"] is True
assert r["maps_drawn"] <= 2 and r["maps_waiting"] > 0, (r["maps_drawn"], r["maps_waiting"])
PY
    run bench --scene tutorial-room --sweep local-lights --write-scene "$work/all.json"
    expect 2 "--write-scene needs --sweep and one value in --values, got 9 values"
    run bench --scene tutorial-room --sweep local-lights --values 300 --frames 1 --warmup 0 \
        --out-dir "$work/l"
    expect 2 "--values: local-lights 300 is outside 1..256"
    # A value refused after others were measured: one error line, and theirs are kept.
    run bench --scene tutorial-room --size 64x64 --sweep map-size --values 256,big --frames 1 \
        --warmup 0 --out-dir "$work/big"
    expect 2 "map-size big: --values: 'big' is not a number (kept the 1 of 2 values finished)"
    [[ $(grep -c "^gnomon: error" "$work/stderr") == 1 ]] || fail "more than one error line"
    [[ $(wc -l <"$work/big/sweep.csv") == 2 ]] || fail "the value measured was not kept"
    ;;
score)
    run score --scene tutorial-room --size 96x96 --out-dir "$work/s"
    skip_without_gl
    expect 0 "misclassified"
    expect 0 "directional"
    for f in render.png errors.png score.json errors.csv; do
        [[ -s "$work/s/$f" ]] || fail "no $f"
    done
    grep -q '"false_shadow"' "$work/s/score.json" || fail "score.json lacks false_shadow"
    # Nothing in the room is translucent: no coloured-shadow line, map or numbers.
    [[ ! -e "$work/s/tint-errors.png" ]] || fail "tint-errors.png for an opaque scene"
    ! grep -q "coloured shadows" "$work/stdout" || fail "coloured-shadow line for an opaque scene"
    ! grep -q '"tint"' "$work/s/score.json" || fail "score.json has tint for an opaque scene"
    # The table fits 80 columns (so do the notes: the acne below has them all).
    wide=$(awk 'length > 80' "$work/stdout")
    [[ -z $wide ]] || fail "score lines over 80 columns: $wide"
    # Panes of coloured glass: the tinted light is scored, mapped and listed.
    glass=$(dirname "$0")/../../examples/stained-glass.json
    run score --scene "$glass" --size 96x96 --out-dir "$work/g"
    expect 0 "coloured shadows: transmitted light off by"
    expect 0 "tint-errors.png"
    [[ -s "$work/g/tint-errors.png" ]] || fail "no tint-errors.png for coloured glass"
    grep -q '"tint"' "$work/g/score.json" || fail "score.json lacks tint for coloured glass"
    wide=$(awk 'length > 80' "$work/stdout")
    [[ -z $wide ]] || fail "score lines over 80 columns: $wide"
    # The same glass with dithered shadows tints nothing.
    run score --scene "$glass" --size 96x96 --blend-shadows dithered --out-dir "$work/d"
    expect 0 "misclassified"
    [[ ! -e "$work/d/tint-errors.png" ]] || fail "tint-errors.png with --blend-shadows dithered"
    # A score that fails leaves no folder behind; one that cannot write leaves no files.
    run score --scene tutorial-room --size 96x96 --light-only 9 --out-dir "$work/none"
    expect 2 "light-only 9"
    [[ ! -e "$work/none" ]] || fail "a failed score left its --out-dir"
    mkdir -p "$work/ro/errors.png"  # a folder where a file must go: the second write fails
    run score --scene tutorial-room --size 96x96 --out-dir "$work/ro"
    expect 1 "errors.png"
    [[ ! -e "$work/ro/render.png" ]] || fail "a failed score left render.png"
    # No tolerance at all and maps alone: acne everywhere, above any sensible bound: exit 3.
    run score --scene tutorial-room --size 96x96 --out-dir "$work/s" --bias-constant 0 \
        --bias-depth-aware 0 --bias-slope 0 --bias-units 0 --normal-offset 0 --cull none --receiver-plane off \
        --shadow-rays off --max-error 0.05 --contact-range 0.1
    expect 3 "exceeds --max-error"
    expect 3 "away from edges (pixel x light pairs)"
    expect 3 "at contacts (occluder within 0.1)"
    wide=$(awk 'length > 80' "$work/stdout")
    [[ -z $wide ]] || fail "score lines over 80 columns: $wide"
    run score --scene tutorial-room --size 96x96 --out-dir "$work/s" --max-error 2
    expect 2 "--max-error must be a fraction"
    # Over a path: a line per frame, path.json and each frame's error map.
    run score --scene tutorial-room --size 64x64 --path still --frames 3 --error-maps \
        --out-dir "$work/p"
    expect 0 "mean over 3 frames"
    for f in path.json errors-000.png errors-002.png; do [[ -s "$work/p/$f" ]] || fail "no $f"; done
    grep -q '"mean_flicker": 0.0' "$work/p/path.json" || fail "a still path flickered"
    run score --scene tutorial-room --size 64x64 --path loop --out-dir "$work/q"
    expect 2 "unknown path 'loop': expected orbit, dolly, sun, still or a path file"
    [[ ! -e "$work/q" ]] || fail "a failed path score left its --out-dir"
    run score --scene tutorial-room --size 64x64 --path orbit --frames 1 --out-dir "$work/q"
    expect 2 "2..10000 frames"
    run score --scene tutorial-room --size 64x64 --error-maps --out-dir "$work/q"
    expect 2 "--error-maps needs --path"
    # tune: a line per trial, the front, and a scene file render takes as is.
    run tune --scene tutorial-room --size 48x48 --sweeps 1 --out-dir "$work/t"
    expect 0 "front (nothing tried is both faster and better; <- marks the start)"
    expect 0 "<- start"
    for f in tuned.json tune.json front.svg; do [[ -s "$work/t/$f" ]] || fail "no $f"; done
    run render --scene "$work/t/tuned.json" --out "$work/t/r.png"
    [[ $(cat "$work/code") == 0 && -s "$work/t/r.png" ]] || fail "tuned.json does not render"
    # At its time limit a search keeps what it found: a success, the files written.
    run tune --scene tutorial-room --size 48x48 --time-limit 0.001 --out-dir "$work/l"
    expect 0 "stopped at the time limit"
    [[ -s "$work/l/tuned.json" ]] || fail "a timed-out tune wrote no tuned.json"
    run tune --scene tutorial-room --size 48x48 --time-limit -1 --out-dir "$work/u"
    expect 2 "--time-limit must be in [0, 1e7) seconds"
    run tune --scene tutorial-room --size 48x48 --sweeps 11 --out-dir "$work/u"
    expect 2 "--sweeps must be in 1..10"
    [[ ! -e "$work/u" ]] || fail "a rejected tune left its --out-dir"
    ;;
*) fail "unknown case" ;;
esac
echo "ok ($case)"
