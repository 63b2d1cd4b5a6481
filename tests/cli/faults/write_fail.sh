#!/bin/sh
# A write that fails (file size limit: `ulimit -f`, so writes fail with EFBIG like on a
# full disk) must end the run with a message naming the file and a non-zero exit, leave
# every CSV ending in a whole line and no truncated PNG under its final name.
#   write_fail.sh PORELAB SRCDIR OUT
set -u
exe=$1 src=$2 out=$3
faults=$src/tests/cli/faults
fail=0
bad() { echo "FAIL: $*"; fail=1; }
# run NAME EXPECT_RC REGEX [IGNORE_XFSZ]: runs the scene under an 8-16 KB file size limit
run() {
  name=$1 want=$2 re=$3
  dir=$out/$name
  rm -rf "$dir"
  mkdir -p "$dir"
  (
    [ "${4:-}" = ignore ] && trap '' XFSZ
    ulimit -f 16
    exec "$exe" run "$faults/$name.lua" --quiet --out "$dir"
  ) > "$dir.log" 2>&1
  rc=$?
  echo "--- $name: exit $rc"
  cat "$dir.log"
  [ "$rc" = "$want" ] || bad "$name: expected exit $want, got $rc"
  grep -Eq "$re" "$dir.log" || bad "$name: the output does not match: $re"
  for f in "$dir"/*.csv; do
    [ -s "$f" ] || continue
    last=$(tail -c 1 "$f" | od -An -tx1 | tr -d ' \n')
    [ "$last" = "0a" ] || bad "$name: $f ends mid-line"
  done
}
# rows flushed after each frame: the flush fails during the run (porelab itself must not
# die of SIGXFSZ, so the signal is left at its default here)
run csv_per_frame 1 "writing the CSV file '.*log.csv' failed: File too large"
grep -q "run stopped at t = .*a CSV file could not be written" "$out/csv_per_frame.log" ||
  bad "csv_per_frame: no 'run stopped' line"
# rows only in on_finish, file never closed: the failure shows when porelab closes it
run csv_at_end 1 "writing the CSV file '.*log.csv' failed: File too large" ignore
grep -q "finished" "$out/csv_at_end.log" && bad "csv_at_end: reported as finished"
# an imperative script that never closes its CSV
run csv_imperative 1 "log.csv' failed: File too large.*|output is incomplete" ignore
grep -q "ran to completion" "$out/csv_imperative.log" && bad "csv_imperative: reported as completed"
# a frame larger than the limit: no frame under its final name, none counted
run big_frame 1 "cannot write .*frame_000000.png.*File too large" ignore
[ -e "$out/big_frame/frame_000000.png" ] && bad "big_frame: a truncated frame_000000.png was left"
grep -q "no frames were written" "$out/big_frame.log" || bad "big_frame: the truncated frame was counted"
# a VTK collection that outgrows the limit (--vtk): the .pvd files are rewritten at every frame;
# what stays under its final name must be a whole file
dir=$out/long_pvd
rm -rf "$dir"
mkdir -p "$dir"
( trap '' XFSZ; ulimit -f 16; exec "$exe" run "$faults/long_pvd.lua" --quiet --vtk --out "$dir" ) > "$dir.log" 2>&1
rc=$?
echo "--- long_pvd: exit $rc"
cat "$dir.log"
[ "$rc" = 1 ] || bad "long_pvd: expected exit 1, got $rc"
grep -Eq "cannot write .*run.pvd: File too large" "$dir.log" || bad "long_pvd: the message does not name the .pvd file and the reason"
for f in "$dir"/*.pvd; do
  [ -e "$f" ] || { bad "long_pvd: no .pvd left"; continue; }
  tail -c 12 "$f" | grep -q "</VTKFile>" || bad "long_pvd: a truncated $f was left ($(wc -c < "$f") bytes)"
done
exit $fail