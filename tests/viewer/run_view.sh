# Sourced by the viewer's shell tests: run_view ARGS... runs `gnomon view ARGS...` (with
# $gnomon and $work set), prints its log, and ends the test as skipped (77) when no window
# can be opened, or failed (1) when the viewer exits with an error.
run_view() {
    "$gnomon" view "$@" >"$work/view.log" 2>&1
    local status=$?
    cat "$work/view.log"
    [[ $status -eq 0 ]] && return 0
    if grep -q "cannot open" "$work/view.log"; then
        echo "skipped: no window"
        exit 77
    fi
    echo "gnomon view exited $status"
    exit 1
}
