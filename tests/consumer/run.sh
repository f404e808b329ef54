#!/usr/bin/env bash
# consumer.find_package: installs the already-built gnomon into a fresh prefix, then
# configures, builds and runs tests/consumer/project against that prefix only (find_package
# and gnomon::gnomon). Settings come from the environment (see CMakeLists.txt); arguments are
# passed on to the consumer's configure step. Exit 0: pass, 77: no usable OpenGL (skipped).
set -euo pipefail

for var in GNOMON_CMAKE GNOMON_BUILD_DIR GNOMON_CONFIG GNOMON_LIBDIR GNOMON_LIBRARY \
    GNOMON_CLI CONSUMER_SOURCE CONSUMER_WORK; do
    if [[ -z "${!var:-}" ]]; then
        echo "run.sh: $var is not set (run this through ctest)" >&2
        exit 1
    fi
done

cmake=$GNOMON_CMAKE
config=$GNOMON_CONFIG
work=$CONSUMER_WORK
prefix=$work/prefix
build=$work/build
libdir=$prefix/$GNOMON_LIBDIR

# Runs a step quietly; on failure shows its output and stops.
step() {
    local name=$1
    shift
    if ! "$@" >"$work/$name.log" 2>&1; then
        echo "consumer: step '$name' failed: $*" >&2
        cat "$work/$name.log" >&2
        exit 1
    fi
}
fail() {
    echo "consumer: $*" >&2
    exit 1
}

rm -rf "$work"
mkdir -p "$work"

for built in "$GNOMON_LIBRARY" "$GNOMON_CLI"; do
    [[ -f "$built" ]] || fail "$built does not exist: build the project before running the tests"
done

# 1. Install the build tree into the fresh prefix (library, headers, package config, CLI).
unset DESTDIR
step install "$cmake" --install "$GNOMON_BUILD_DIR" --config "$config" --prefix "$prefix"
for file in include/gnomon/gnomon.h "$GNOMON_LIBDIR/cmake/gnomon/gnomonConfig.cmake" \
    "$GNOMON_LIBDIR/cmake/gnomon/gnomonConfigVersion.cmake"; do
    [[ -f "$prefix/$file" ]] || fail "the install did not create $file under $prefix"
done
compgen -G "$libdir/libgnomon.so*" >/dev/null || fail "the install put no libgnomon.so in $libdir"

# 2. Configure and build the consumer against the prefix, and nothing else.
step configure "$cmake" -S "$CONSUMER_SOURCE" -B "$build" -DCMAKE_BUILD_TYPE="$config" \
    -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF "$@"
found=$(sed -n 's/^gnomon_DIR:PATH=//p' "$build/CMakeCache.txt")
[[ "$found" == "$prefix"/* ]] || fail "find_package(gnomon) found '$found', not the install in $prefix"
step build "$cmake" --build "$build" --config "$config"

exe=$build/gnomon_consumer
[[ -x "$exe" ]] || exe=$build/$config/gnomon_consumer
[[ -x "$exe" ]] || fail "the consumer build produced no gnomon_consumer in $build"

# 3. The installed CLI finds its library through its RPATH alone.
cli_version=$(env -u LD_LIBRARY_PATH "$prefix/bin/gnomon" --version) ||
    fail "the installed gnomon CLI does not run (RPATH to $libdir?)"
# The consumer has no RPATH to the prefix: give it the installed library.
export LD_LIBRARY_PATH="$libdir${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
if command -v ldd >/dev/null; then
    loaded=$(ldd "$exe" | sed -n 's/^[[:space:]]*libgnomon\.so[^ ]* => \([^ ]*\).*/\1/p')
    [[ "$loaded" == "$prefix"/* ]] || fail "the consumer loads libgnomon from '$loaded', not $prefix"
fi

status=0
"$exe" "$work/book-triangle.png" || status=$?
if [[ $status -eq 77 ]]; then
    exit 77
elif [[ $status -ne 0 ]]; then
    fail "gnomon_consumer exited with status $status"
fi
[[ -s "$work/book-triangle.png" ]] || fail "gnomon_consumer wrote no $work/book-triangle.png"
echo "consumer: installed CLI reports version $cli_version"
