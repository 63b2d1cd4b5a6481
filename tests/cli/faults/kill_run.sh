#!/bin/sh
# Kills a running `porelab run` with SIGKILL at a few seeded pseudo-random moments and
# checks what it leaves: every PNG under its final name is whole (PNG signature, IEND as
# the last chunk, and libpng decodes it through imgdiff) and every CSV ends in a whole line
# with the header's number of fields on every line. Hidden temporaries (.NAME.tmp-PID.png)
# may remain. Bounded: ITER kills, each 0.15..0.75 s after the second frame.
#   kill_run.sh PORELAB IMGDIFF SCENE OUT [ITER] [SEED]
set -u
exe=$1 imgdiff=$2 scene=$3 out=$4 iter=${5:-5} seed=${6:-13}
fail=0
bad() { echo "FAIL: $*"; fail=1; }
i=0
while [ "$i" -lt "$iter" ]; do
  i=$((i + 1))
  dir="$out/kill_$i"
  rm -rf "$dir"
  seed=$(( (seed * 1103515245 + 12345) % 2147483648 ))
  ms=$(( 150 + (seed / 65536) % 600 ))
  "$exe" run "$scene" --quiet --out "$dir" &
  pid=$!
  # the random moment counts from the second frame (a loaded machine may take a while to
  # start); give up waiting after 20 s
  waited=0
  while [ ! -e "$dir/frame_000001.png" ] && [ "$waited" -lt 400 ] && kill -0 "$pid" 2>/dev/null; do
    sleep 0.05
    waited=$((waited + 1))
  done
  sleep "$(printf '%d.%03d' $((ms / 1000)) $((ms % 1000)))"
  kill -9 "$pid" 2>/dev/null
  wait "$pid" 2>/dev/null
  pngs=0
  for f in "$dir"/*.png; do
    [ -e "$f" ] || continue
    pngs=$((pngs + 1))
    sig=$(head -c 8 "$f" | od -An -tx1 | tr -d ' \n')
    [ "$sig" = "89504e470d0a1a0a" ] || { bad "kill $i at ${ms} ms: $f has no PNG signature"; continue; }
    iend=$(tail -c 12 "$f" | od -An -tx1 | tr -d ' \n')
    [ "$iend" = "0000000049454e44ae426082" ] || { bad "kill $i at ${ms} ms: $f does not end in IEND ($(wc -c < "$f") bytes)"; continue; }
    "$imgdiff" "$f" "$f" > /dev/null 2>&1 || bad "kill $i at ${ms} ms: libpng cannot decode $f"
  done
  csvs=0
  for f in "$dir"/*.csv; do
    [ -e "$f" ] || continue
    csvs=$((csvs + 1))
    if [ ! -s "$f" ]; then bad "kill $i at ${ms} ms: $f is empty"; continue; fi
    last=$(tail -c 1 "$f" | od -An -tx1 | tr -d ' \n')
    [ "$last" = "0a" ] || bad "kill $i at ${ms} ms: $f ends mid-line ($(wc -c < "$f") bytes)"
    awk -F, '/^#/ { next } !n { n = NF } NF != n { bad = 1 } END { exit bad }' "$f" ||
      bad "kill $i at ${ms} ms: $f has a line with a wrong number of fields"
  done
  echo "kill $i at ${ms} ms: $pngs PNG, $csvs CSV checked"
  [ "$pngs" -gt 0 ] || bad "kill $i at ${ms} ms: no frame was written (the run did not start?)"
  [ "$csvs" -eq 2 ] || bad "kill $i at ${ms} ms: expected 2 CSV files, found $csvs"
  rm -rf "$dir"
done
exit $fail
