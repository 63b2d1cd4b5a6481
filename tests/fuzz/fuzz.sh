#!/bin/sh
# Fuzz driver for `porelab run` (issue 13, "Fuzzing in CI"). POSIX sh + awk, no python.
#
#   tests/fuzz/fuzz.sh PORELAB SRCDIR WORKDIR [--seed N] [--mutations N] [--set default|long]
#                      [--jobs J] [--budget S] [--cpu S] [--mem KB] [--deadline S]
#
# Cases: the hand-written scenes in tests/fuzz/cases/ (huge/NaN/inf numbers, wrong types,
# missing fields, deep recursion, giant tables, unknown flags, bad render tables, ...) and
# N mutations of the shipped scenes (scenes/**, tests/fuzz/mutate.awk: numbers and strings
# made nasty, lines dropped, duplicated or truncated, field names misspelt, statements
# inserted), all from a fixed seed, so a case name (m0042_demo.lua) is the same case on every
# machine. Each case runs as
#     cd WORKDIR/cases/NAME/cwd && porelab run ../scene/NAME.lua --steps 50 --out out -q \
#         --max-cpu HALF_THE_CPU_BUDGET
# (so that a scene's own endless loop is stopped by porelab, with its line, before the limits
# below) under `timeout` (wall budget) and ulimit -t/-v (CPU seconds, virtual memory), with cwd,
# HOME and TMPDIR empty folders of its own. A case fails when
#   SIGNAL   the exit code is >= 128 (a crash, or killed by the CPU limit)
#   HANG     it ran past its wall budget
#   NOLINE   it exited non-zero without a "NAME.lua:<line>:" message on stderr
#   OUTSIDE  a file appeared outside the output folder (cwd, the scene's folder, HOME/TMPDIR)
# A hand-written case whose header says `-- fuzz-expect: fail (reason)` is expected to fail
# (XFAIL; a pass is reported as XPASS, not an error); `-- fuzz-set: long` keeps a case out of
# the default set (it costs its whole budget, e.g. an endless loop). tests/fuzz/known.txt lists
# mutation cases expected to fail, with the reason. Exit 1 on any unexpected failure. Failing
# cases are kept in WORKDIR/failures/ (scene, stdout, stderr); WORKDIR/results.txt has one
# line per case.
set -u
# has_line CASEDIR NAME: stderr has "FILE.lua:<line>:" for the scene or a module of its folder.
has_line() {
  re=$(ls "$1/scene" | sed "s/[.]/[.]/g" | tr "\n" "|" | sed "s/|\$//")
  grep -Eq "(^|[/ ])($re):[0-9]+:" "$1/stderr"
}
if [ "${1:-}" = "--one" ]; then
  # One case: --one CASEDIR PORELAB BUDGET CPU MEM DEADLINE_EPOCH
  d=$2 exe=$3 budget=$4 cpu=$5 mem=$6 deadline=$7
  name=$(cat "$d/name")
  if [ "$(date +%s)" -gt "$deadline" ]; then echo "$name SKIP - total deadline reached" >"$d/result"; exit 0; fi
  mkdir -p "$d/cwd" "$d/home"
  ls -A "$d/scene" | LC_ALL=C sort >"$d/scene.before"
  t0=$(date +%s)
  ( cd "$d/cwd" && ulimit -t "$cpu" && ulimit -v "$mem" &&
    HOME="$d/home" TMPDIR="$d/home" exec timeout -k 2 "$budget" "$exe" run "../scene/$name" \
      --steps 50 --out out -q --max-cpu "$(( (cpu + 1) / 2 ))" ) >"$d/stdout" 2>"$d/stderr" </dev/null
  rc=$?
  t1=$(date +%s)
  status=ok detail=""
  if [ $rc -eq 124 ] || { [ $rc -eq 137 ] && [ $((t1 - t0)) -ge "$budget" ]; }; then
    status=HANG detail="no exit after ${budget} s"
  elif [ $rc -ge 128 ]; then
    status=SIGNAL detail="signal $((rc - 128))"
  elif [ $rc -ne 0 ] && ! has_line "$d" "$name"; then
    status=NOLINE detail="$(head -c 300 "$d/stderr" | tr '\n' ' ')"
  fi
  extra=$(cd "$d/cwd" && ls -A | grep -vx out)
  [ -n "$(ls -A "$d/home")" ] && extra="$extra HOME/TMPDIR:$(ls -A "$d/home" | tr '\n' ' ')"
  ls -A "$d/scene" | LC_ALL=C sort | comm -13 "$d/scene.before" - >"$d/scene.new"
  [ -s "$d/scene.new" ] && extra="$extra scene-folder:$(tr '\n' ' ' <"$d/scene.new")"
  if [ -n "$extra" ]; then status=OUTSIDE detail="files outside the output folder: $(echo $extra)"; fi
  echo "$name $status $rc $((t1 - t0))s $detail" >"$d/result"
  rm -rf "$d/cwd/out"
  exit 0
fi

[ $# -ge 3 ] || { echo "usage: $0 PORELAB SRCDIR WORKDIR [options]" >&2; exit 2; }
exe=$1 src=$2 work=$3; shift 3
seed=13 mutations=300 set=default jobs=2 budget=15 cpu=15 mem=2000000 total=600
while [ $# -gt 0 ]; do
  case $1 in
    --seed) seed=$2 ;; --mutations) mutations=$2 ;; --set) set=$2 ;; --jobs) jobs=$2 ;;
    --budget) budget=$2 ;; --cpu) cpu=$2 ;; --mem) mem=$2 ;; --deadline) total=$2 ;;
    *) echo "$0: unknown option '$1'" >&2; exit 2 ;;
  esac
  shift 2
done
case $exe in /*) ;; *) exe=$(pwd)/$exe ;; esac
here=$src/tests/fuzz
rm -rf "$work"; mkdir -p "$work/cases" "$work/failures" || exit 2
work=$(cd "$work" && pwd)
rm -f /tmp/porelab-fuzz-escape

# Hand-written cases.
for f in "$here"/cases/*.lua; do
  [ -f "$f" ] || continue
  if [ "$set" = default ] && grep -q '^-- fuzz-set: long' "$f"; then continue; fi
  n=$(basename "$f"); d=$work/cases/${n%.lua}
  mkdir -p "$d/scene"; cp "$f" "$d/scene/$n"; echo "$n" >"$d/name"
  grep -q '^-- fuzz-expect: fail' "$f" && grep '^-- fuzz-expect: fail' "$f" | head -1 >"$d/expect"
done
# Mutations of the shipped scenes: case i mutates scene i mod (number of scenes), with
# 1 + i mod 3 mutations from seed (seed * 100003 + i); its siblings come along unmutated
# (scenes require their folder's modules).
(cd "$src" && find scenes -name '*.lua' | LC_ALL=C sort) >"$work/scenes.txt"
nscenes=$(wc -l <"$work/scenes.txt")
i=0
while [ $i -lt "$mutations" ]; do
  s=$(sed -n "$((i % nscenes + 1))p" "$work/scenes.txt")
  base=$(basename "$s" .lua)
  n=$(printf 'm%04d_%s.lua' $i "$base"); d=$work/cases/${n%.lua}
  mkdir -p "$d/scene"
  for sib in "$src/$(dirname "$s")"/*.lua; do cp "$sib" "$d/scene/"; done
  rm -f "$d/scene/$base.lua"
  awk -v seed=$((seed * 100003 + i)) -v n=$((1 + i % 3)) -f "$here/mutate.awk" "$src/$s" >"$d/scene/$n"
  echo "$n" >"$d/name"
  i=$((i + 1))
done

deadline=$(( $(date +%s) + total ))
ls "$work/cases" | LC_ALL=C sort | sed "s|^|$work/cases/|" |
  xargs -P "$jobs" -I{} sh "$0" --one {} "$exe" "$budget" "$cpu" "$mem" "$deadline"

# known_reason CASEDIR STATUS: a case named in known.txt, or a NOLINE/OUTSIDE case whose stderr
# matches a known pattern, gets an expect file (unless it has one).
known_reason() {
  [ -f "$1/expect" ] && return
  kc=$(basename "$1")
  kr=$(awk -F "\t" -v c="$kc" '$1 == "case " c { print $2; exit }' "$here/known.txt")
  if [ -z "$kr" ] && { [ "$2" = NOLINE ] || [ "$2" = OUTSIDE ]; }; then
    kr=$(awk -F "\t" '$1 == "match" { print $2 "\t" $3 }' "$here/known.txt" |
      while IFS="$(printf "\t")" read -r re why; do
        if tr "\n" " " <"$1/stderr" | grep -Eq -- "$re"; then echo "$why"; break; fi
      done)
  fi
  [ -n "$kr" ] && echo "-- fuzz-expect: fail ($kr)" >"$1/expect"
}
: >"$work/results.txt"
fail=0 xfail=0 xpass=0 pass=0 skip=0
for d in "$work"/cases/*/; do
  d=${d%/}
  r=$(cat "$d/result" 2>/dev/null || echo "$(cat "$d/name") SKIP - not run")
  st=$(echo "$r" | awk '{print $2}')
  [ "$st" = SKIP ] || known_reason "$d" "$st"
  if [ "$st" = SKIP ]; then skip=$((skip + 1))
  elif [ -f "$d/expect" ]; then
    if [ "$st" = ok ]; then xpass=$((xpass + 1)); r="$r XPASS $(cat "$d/expect")"
    else xfail=$((xfail + 1)); r="$r XFAIL $(cat "$d/expect")"; fi
  elif [ "$st" = ok ]; then pass=$((pass + 1))
  else
    fail=$((fail + 1))
    f=$work/failures/$(basename "$d"); mkdir -p "$f"
    cp "$d/scene/$(cat "$d/name")" "$d/stdout" "$d/stderr" "$f/"
    echo "FAIL $r"
  fi
  echo "$r" >>"$work/results.txt"
done
if [ -e /tmp/porelab-fuzz-escape ]; then
  echo "FAIL a case wrote /tmp/porelab-fuzz-escape"; fail=$((fail + 1)); rm -f /tmp/porelab-fuzz-escape
fi
grep ' XFAIL \| XPASS ' "$work/results.txt" | sed 's/^/note: /'
echo "fuzz: seed $seed, set $set: $pass passed, $fail failed, $xfail expected failures, $xpass unexpected passes, $skip not run (results: $work/results.txt)"
[ $fail -eq 0 ]
