#!/usr/bin/env bash
# The pictures of docs/viewer.md: runs the walkthrough script (examples/viewer/walkthrough.txt,
# also the test viewer.walkthrough) in a 1280x720 window under xvfb-run, in
# docs/images/viewer/, where its window shots land.
set -euo pipefail
cd "$(dirname "$0")/.."
make build >/dev/null
gnomon=$PWD/build/release/apps/gnomon/gnomon
mkdir -p docs/images/viewer
cd docs/images/viewer
xvfb-run -a -s "-screen 0 1280x1024x24" "$gnomon" view --window 1280x720 \
    --script ../../../examples/viewer/walkthrough.txt
