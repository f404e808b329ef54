# Shared by the CLI tests (cli_test.sh, cli_measure_test.sh): the binary, the case and its
# work directory from the arguments, and the checks they use.
set -uo pipefail
gnomon=$1; case=$2; work=$3
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL ($case): $*"; exit 1; }
run() { "$gnomon" "$@" >"$work/stdout" 2>"$work/stderr"; echo $? >"$work/code"; }
expect() {  # expect CODE TEXT: exit code and a substring of stdout+stderr
    local code; code=$(cat "$work/code")
    [[ "$code" == "$1" ]] || fail "exit code $code, expected $1; output: $(cat "$work/stdout" "$work/stderr")"
    grep -qF -- "$2" "$work/stdout" "$work/stderr" || fail "output lacks '$2': $(cat "$work/stdout" "$work/stderr")"
}
skip_without_gl() {
    if grep -q "no usable OpenGL" "$work/stderr"; then echo "skipped: $(cat "$work/stderr")"; exit 77; fi
}
