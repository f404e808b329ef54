# Sourced by the real-scene tests: write_views SCENES WORK VIEW... writes each view of
# scripts/quality-real.py as WORK/VIEW.json, every one before anything is scored, and exits the
# test with 77 (skipped) when a model is missing, 1 when a scene cannot be written.
write_views() {
    local scenes=$1 work=$2 view code
    shift 2
    local quality_real
    quality_real=$(dirname "${BASH_SOURCE[0]}")/../../scripts/quality-real.py
    for view in "$@"; do
        python3 "$quality_real" --scenes "$scenes" --write-scene "$view" "$work/$view.json"
        code=$?
        [[ $code == 77 ]] && exit 77
        [[ $code == 0 ]] || { echo "FAIL: could not write the scene of $view"; exit 1; }
    done
}
