#!/bin/sh
# Regenerates the renderer's golden images ON PURPOSE, after a deliberate change of the
# drawing (never to make a failing test pass without looking). It rebuilds, rewrites
#   tests/golden/<case>.png   (test_render_golden --update: the cases of tests/render/render_scenes.c)
#   tests/golden/chart.png    (test_render_output --update-chart)
#   tests/golden/gl/<case>.png (test_gl_render --update: the same cases through OpenGL/OSMesa)
# and copies them to docs/figures/render-<case>.png for docs/rendering.md.
# Look at every rewritten image before committing (the diff shows which changed).
#   usage: tools/update-goldens.sh [BUILD_DIR]     (default: build-goldens in the source tree)
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build-goldens}
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j2 --target test_render_golden test_render_output test_gl_render
mkdir -p "$root/tests/golden" "$root/docs/figures"
"$build/tests/test_render_golden" --update "$root/tests/golden"
"$build/tests/test_render_output" --update-chart "$root/tests/golden/chart.png"
"$build/tests/test_gl_render" --update
for f in "$root"/tests/golden/*.png; do
  cp "$f" "$root/docs/figures/render-$(basename "$f")"
done
echo "goldens rewritten in $root/tests/golden; look at each one before committing"
