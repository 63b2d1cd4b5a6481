#!/bin/sh
# porelab still/run --renderer gl: the GL still of a scene agrees with the cairo still
# (PSNR >= 28 dB, the threshold of test_gl_render), run --renderer gl writes the frames
# the plan asks for, SVG is refused with a clear message, unknown renderers are usage errors.
#   test_gl_cli.sh PORELAB GL_PSNR SOURCE_DIR OUT_DIR
set -u
unset PORELAB_GL_SAMPLES PORELAB_WINDOW_SAMPLES # the goldens and thresholds are for the defaults
P=$1; PSNR=$2; SRC=$3; OUT=$4
rm -rf "$OUT"; mkdir -p "$OUT"
fail() { echo "FAIL: $*"; exit 1; }
cd "$SRC" || fail "no source dir"

"$P" still scenes/two_disc_impact.lua --at 0.01 -o "$OUT/gl.png" --renderer gl --out "$OUT/s" -q \
  || fail "still --renderer gl"
"$P" still scenes/two_disc_impact.lua --at 0.01 -o "$OUT/cairo.png" --out "$OUT/s" -q || fail "still cairo"
p=$("$PSNR" "$OUT/gl.png" "$OUT/cairo.png" 28) || fail "GL vs cairo still: PSNR $p dB < 28"
echo "still two_disc_impact: GL vs cairo PSNR $p dB"

"$P" still scenes/fluid_quicksand.lua --at 0.6 -o "$OUT/qs_gl.png" --renderer gl --out "$OUT/q" -q \
  || fail "still quicksand --renderer gl"
"$P" still scenes/fluid_quicksand.lua --at 0.6 -o "$OUT/qs_cairo.png" --out "$OUT/q" -q || fail "still quicksand"
p=$("$PSNR" "$OUT/qs_gl.png" "$OUT/qs_cairo.png" 28) || fail "quicksand GL vs cairo: PSNR $p dB < 28"
echo "still fluid_quicksand (pressure, velocity, colour bar): GL vs cairo PSNR $p dB"

# a different time must not pass as the same picture
"$P" still scenes/two_disc_impact.lua --at 0.2 -o "$OUT/gl_late.png" --renderer gl --out "$OUT/s" -q \
  || fail "still late"
if p=$("$PSNR" "$OUT/gl_late.png" "$OUT/cairo.png" 28); then fail "a later state passed as equal ($p dB)"; fi
echo "later state vs cairo: $p dB (rejected, as it should be)"

"$P" run scenes/two_disc_impact.lua --renderer gl --steps 40 --every 10 --out "$OUT/run" -q \
  || fail "run --renderer gl"
n=$(ls "$OUT/run"/frame_*.png 2>/dev/null | wc -l)
[ "$n" -eq 5 ] || fail "run --renderer gl wrote $n frames, expected 5"
"$P" run scenes/two_disc_impact.lua --steps 40 --every 10 --out "$OUT/run_cairo" -q || fail "run cairo"
p=$("$PSNR" "$OUT/run/frame_000004.png" "$OUT/run_cairo/frame_000004.png" 28) || fail "frame 4 PSNR $p"
echo "run: 5 GL frames; last frame vs cairo PSNR $p dB"

if "$P" still scenes/two_disc_impact.lua -o "$OUT/x.svg" --renderer gl --out "$OUT/s" 2>"$OUT/err.txt"; then
  fail "--renderer gl accepted an SVG"
fi
grep -q "PNG only" "$OUT/err.txt" || fail "SVG refusal message: $(cat "$OUT/err.txt")"
"$P" still scenes/two_disc_impact.lua -o "$OUT/x.png" --renderer vulkan 2>"$OUT/err2.txt"
[ $? -eq 2 ] || fail "--renderer vulkan is not a usage error"
grep -q "cairo or gl" "$OUT/err2.txt" || fail "unknown renderer message"
echo "ok"
