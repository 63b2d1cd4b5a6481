#!/usr/bin/env bash
# README's first demo: install what is missing, build, and run the default demo scene,
# liquefaction on a shaking table (scenes/soil/liquefaction.lua: grains and pore water, excess
# pore pressure with its colour bar). Frames go to out/demo/ (and out/demo.mp4 when ffmpeg is
# installed), the chart of r_u to out/demo/ru.png.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)"
video=()
if command -v ffmpeg >/dev/null 2>&1; then video=(--video out/demo.mp4); else echo "note: ffmpeg is not installed, so no video; the PNG frames are in out/demo/"; fi
build/app/porelab run scenes/soil/liquefaction.lua --out out/demo "${video[@]}"
