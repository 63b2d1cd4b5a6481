#!/usr/bin/env bash
# docs_commands: every command in the fenced blocks marked `sh quick` of README.md and
# docs/*.md runs as written. Convention (README.md, "Install"): ```sh quick marks a block of
# quick commands (seconds each), run here one by one from a scratch copy of the tree's
# layout (scenes/, tools/ linked; out/ and docs/figures/ fresh, so nothing in the source tree
# is overwritten), with the built porelab first on PATH. A line ending in \ continues on the
# next; a '#' after the command is a comment. Plain ```sh blocks are longer runs, not run.
#   usage: docs_commands.sh SOURCE_DIR PORELAB_BINARY_DIR SCRATCH_DIR
set -u
src=$1; bindir=$2; work=$3
rm -rf "$work"; mkdir -p "$work/docs/figures" "$work/out"
ln -s "$src/scenes" "$work/scenes"
ln -s "$src/tools" "$work/tools"
export PATH="$bindir:$PATH"
fail=0; count=0
for md in "$src/README.md" "$src"/docs/*.md; do
  cmds=$(awk '
    /^```sh quick[ \t]*$/ { on = 1; next }
    /^```/ { on = 0; next }
    on {
      line = $0
      if (cont != "") { line = cont " " line; cont = "" }
      if (line ~ /\\[ \t]*$/) { sub(/\\[ \t]*$/, "", line); cont = line; next }
      if (line ~ /^[ \t]*$/) next
      print line
    }' "$md")
  [ -z "$cmds" ] && continue
  while IFS= read -r cmd; do
    count=$((count + 1))
    echo "== ${md#$src/}: $cmd"
    if ! (cd "$work" && timeout 120 bash -c "$cmd" > "$work/last.log" 2>&1); then
      echo "FAILED (${md#$src/}): $cmd"; tail -5 "$work/last.log"; fail=1
    fi
  done <<< "$cmds"
done
echo "docs_commands: $count commands run"
[ "$count" -gt 0 ] || { echo "no 'sh quick' blocks found"; exit 1; }
exit $fail
