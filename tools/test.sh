#!/usr/bin/env bash
# README command 2: install what is missing, build from nothing, run the whole test suite.
# Long validations carry the ctest label "long" and are excluded here; run them with
#   ctest --test-dir build -L long
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)"
ctest --test-dir build --output-on-failure -LE long -j"$(nproc)"
