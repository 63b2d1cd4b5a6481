#!/usr/bin/env bash
# README command 2: install what is missing, build from nothing, run the whole test suite.
# Everything runs (about two minutes on 2 cores). The whole-scene soil validations carry the
# ctest label "long": `ctest --test-dir build -LE long` skips them, `-L long` runs only them.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)"
ctest --test-dir build --output-on-failure -j"$(nproc)"
