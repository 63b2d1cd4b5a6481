#!/usr/bin/env bash
# README command 2: install what is missing, build from nothing, run the whole test suite:
# the plain ctest set (under ten minutes on 2 cores), then the long validations (whole scenes
# and mesh sequences, configuration and label "long", not in a plain `ctest`).
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)"
ctest --test-dir build --output-on-failure -j"$(nproc)"
ctest --test-dir build --output-on-failure -j"$(nproc)" -C long -L long
