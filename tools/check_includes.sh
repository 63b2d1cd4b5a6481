#!/bin/sh
# The engine's include rules, checked from the `#include` lines (POSIX sh + awk, no python).
#
#   tools/check_includes.sh [ENGINE_DIR]      (default: the engine/ next to this script)
#
# A module is a directory of ENGINE_DIR/src: core, geom, dem, mesh, coupling, world, solid,
# ... and, under fluid/, one module per model (fluid/darcy, fluid/hydrostatic); files
# directly in fluid/ form the module "fluid". A quoted include is resolved as the compiler
# does (the including file's directory first, then src/); includes that resolve to no file
# of src/ (public porelab/ headers, system headers) add no edge. Fails (exit 1, every
# violation on its own line) when
#   1. the module graph has a cycle (named: "dem -> fluid -> dem", with one include per edge);
#   2. any file of src/ or include/ includes a Lua, cairo, GL, SDL or PLplot header;
#   3. dem includes from fluid (any model), or fluid (any model) from dem;
#   4. one fluid model includes from another (fluid/X from fluid/Y). fluid/common and
#      fluid/shared are shared fluid code, not models.
# Exit 0 and a one-line summary otherwise; exit 2 on usage errors.
set -eu

here=$(cd "$(dirname "$0")" && pwd)
engine=${1:-$here/../engine}
if [ ! -d "$engine/src" ]; then
    echo "check_includes: no src/ directory in '$engine'" >&2
    exit 2
fi
engine=$(cd "$engine" && pwd)

list=$(mktemp "${TMPDIR:-/tmp}/pl_includes.XXXXXX")
trap 'rm -f "$list"' EXIT INT TERM
# One line per file: "src <path under src>" or "include <path under include>".
(cd "$engine/src" && find . -type f \( -name '*.c' -o -name '*.h' \) | sed 's|^\./||' | LC_ALL=C sort |
    sed 's|^|src |') >"$list"
if [ -d "$engine/include" ]; then
    (cd "$engine/include" && find . -type f -name '*.h' | sed 's|^\./||' | LC_ALL=C sort |
        sed 's|^|include |') >>"$list"
fi

# awk reads the list first (NR == FNR), then every file in turn (named on the command line).
set --
while read -r root path; do
    set -- "$@" "$engine/$root/$path"
done <"$list"

LC_ALL=C awk -v engine="$engine" '
function normalize(p,    n, parts, out, k, i) {
    n = split(p, parts, "/")
    k = 0
    for (i = 1; i <= n; i++) {
        if (parts[i] == "" || parts[i] == ".") continue
        if (parts[i] == "..") { if (k > 0) k--; else return ""; continue }
        out[++k] = parts[i]
    }
    p = ""
    for (i = 1; i <= k; i++) p = p (i > 1 ? "/" : "") out[i]
    return p
}
function dirname(p) { return (p ~ /\//) ? substr(p, 1, match(p, /\/[^\/]*$/) - 1) : "" }
function module(p,    parts, n) {
    n = split(p, parts, "/")
    if (n == 1) return "(top)"
    if (parts[1] == "fluid" && n >= 3) return "fluid/" parts[2]
    return parts[1]
}
function is_fluid(m) { return m == "fluid" || m ~ /^fluid\// }
function is_model(m) { return m ~ /^fluid\// && m != "fluid/common" && m != "fluid/shared" }
function fail(msg) { print "check_includes: " msg; failures++ }
function add_module(m) { if (!(m in seen_module)) { seen_module[m] = 1; modules[++nmodules] = m } }
function forbidden(h,    b) {
    b = h; sub(/^.*\//, "", b)
    return h ~ /^(GL|GLES[0-9]*|EGL|SDL[0-9]*|cairo|plplot|lua[0-9.]*|luajit[-0-9.]*)\// ||
           b ~ /^(lua|lualib|lauxlib|luaconf)\.h(pp)?$/ || b ~ /^cairo.*\.h$/ ||
           b ~ /^SDL.*\.h$/ || b ~ /^plplot.*\.h$/ || b ~ /^(gl|glu|glext|glew|glad|glx|GL)\.h$/
}
NR == FNR {
    root[$2] = $1
    if ($1 == "src") { is_src[$2] = 1; add_module(module($2)) }
    next
}
FNR == 1 {
    file = substr(FILENAME, length(engine) + 2)  # "src/dem/world.c"
    rel = file; sub(/^(src|include)\//, "", rel)
    in_src = (file ~ /^src\//)
    from = in_src ? module(rel) : "(public)"
    in_comment = 0
}
{
    # drop block comments (an include inside /* ... */ is no include)
    line = $0; out = ""
    while (1) {
        if (in_comment) {
            p = index(line, "*/")
            if (!p) { line = ""; break }
            line = substr(line, p + 2); in_comment = 0
        }
        p = index(line, "/*")
        if (!p) break
        out = out substr(line, 1, p - 1) " "; line = substr(line, p + 2); in_comment = 1
    }
    line = out line
    if (line !~ /^[ \t]*#[ \t]*include[ \t]*["<]/) next
    h = line; sub(/^[ \t]*#[ \t]*include[ \t]*/, "", h)
    quoted = (substr(h, 1, 1) == "\"")
    h = substr(h, 2); sub(quoted ? "\".*$" : ">.*$", "", h)
    if (forbidden(h)) fail(file ":" FNR ": includes <" h "> (the engine includes no Lua, cairo, GL, SDL or PLplot header)")
    if (!quoted || !in_src) next
    target = ""
    cand = normalize(dirname(rel) "/" h)
    if (cand in is_src) target = cand
    else { cand = normalize(h); if (cand in is_src) target = cand }
    if (target == "") next
    to = module(target)
    if (to == from) next
    if ((from == "dem" && is_fluid(to)) || (is_fluid(from) && to == "dem"))
        fail(file ":" FNR ": " from " includes " target " (dem and fluid never include each other; forces reach the grains through the world)")
    if (is_model(from) && is_model(to))
        fail(file ":" FNR ": " from " includes " target " (one fluid model never includes another)")
    key = from SUBSEP to
    if (!(key in edge)) {
        edge[key] = file ":" FNR " includes " target
        adjn[from]++; adj[from, adjn[from]] = to
        nedges++
    }
}
# Depth-first search; a grey successor closes a cycle, reported once per back edge.
function dfs(u,    i, v, k, cyc, via) {
    color[u] = 1; path[++depth] = u
    for (i = 1; i <= adjn[u]; i++) {
        v = adj[u, i]
        if (color[v] == 1) {
            for (k = depth; path[k] != v; k--) ;
            cyc = ""; via = ""
            for (; k <= depth; k++) {
                cyc = cyc path[k] " -> "
                via = via "\n    " edge[path[k], (k < depth ? path[k + 1] : v)]
            }
            fail("module cycle " cyc v ":" via)
        } else if (!color[v]) dfs(v)
    }
    color[u] = 2; depth--
}
END {
    for (i = 1; i <= nmodules; i++) if (!color[modules[i]]) dfs(modules[i])
    if (failures) { print "check_includes: " failures " violation(s) in " engine; exit 1 }
    printf "check_includes: %d modules, %d module edges, no cycle, no forbidden include (%s)\n", nmodules, nedges, engine
}' "$list" "$@"
