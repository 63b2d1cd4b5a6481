#!/usr/bin/env bash
# Prints the state hash of every scene in scenes/ after a few steps, one line per scene:
#   tools/scene_hashes.sh [PORELAB] [STEPS]
# Run it before and after a change that must not change any result (a refactoring) and diff
# the two outputs. Imperative scenes that step themselves print the hash of their own run.
set -uo pipefail
cd "$(dirname "$0")/.."
EXE=${1:-build/app/porelab}
STEPS=${2:-300}
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
for s in $(find scenes -name '*.lua' | sort); do
  h=$(timeout 300 "$EXE" run "$s" --steps "$STEPS" --every 100000000 --quiet --hash --out "$OUT/$(echo "$s" | tr / _)" 2>&1 |
      sed -n 's/^state-hash: //p' | tail -1)
  printf '%s %s\n' "${h:-none}" "$s"
done
