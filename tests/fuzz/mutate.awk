# Mutates one Lua scene (tests/fuzz/fuzz.sh). Portable awk (mawk, gawk, busybox): its own
# Park-Miller generator, so a seed gives the same case everywhere. Variables: seed, n (how many
# mutations to apply, 1-3). Reads the scene, writes the mutated text to stdout.
function rnd(k) { st = (st * 16807) % 2147483647; return int(st / 2147483647 * k) }
function pick_nasty_number() {
  return nasty_num[rnd(nn) + 1]
}
# Replace the j-th match of regex re in line i by text r (literal).
function subst_nth(i, re, r,    s, out, k, j, cnt) {
  s = L[i]; out = ""; cnt = 0
  while (match(s, re)) { cnt++; out = out substr(s, 1, RSTART + RLENGTH - 1); s = substr(s, RSTART + RLENGTH) }
  if (cnt == 0) return 0
  j = rnd(cnt) + 1
  s = L[i]; out = ""; k = 0
  while (match(s, re)) {
    k++
    if (k == j) { out = out substr(s, 1, RSTART - 1) r; s = substr(s, RSTART + RLENGTH); break }
    out = out substr(s, 1, RSTART + RLENGTH - 1); s = substr(s, RSTART + RLENGTH)
  }
  L[i] = out s
  return 1
}
# A random line index matching re (code, not a comment), 0 if none.
function line_with(re,    i, c, cand) {
  c = 0
  for (i = 1; i <= N; i++) if (L[i] ~ re && L[i] !~ /^[ \t]*--/) cand[++c] = i
  if (c == 0) return 0
  return cand[rnd(c) + 1]
}
BEGIN {
  st = (seed % 2147483646) + 1; rnd(2); rnd(2)
  nn = split("1e308|-1e308|(0/0)|(1/0)|(-1/0)|0|-1|1e-300|-0.0|\"x\"|nil|{}|true|9223372036854775807|-9223372036854775808|1e20|-1e20|2^53|1e-21|1e-12|3.5|1e9|{1/0,0/0}|{1,2,3,4,5}|function() end", nasty_num, "|")
  ns = split("\"\"|\"../../escape.txt\"|\"/tmp/porelab-fuzz-escape\"|42|nil|{}|string.rep(\"a\",100000)|\"a\\nb\"|\"\\0\"|\"\\27[31mred\"|\"./\"|\".\"|\"%s%d%n\"|true", nasty_str, "|")
  nst = split("error(\"boom\")|error()|error({})|collectgarbage()|porelab = nil|string = nil|setmetatable(_G, { __index = function(t, k) error(\"no \" .. k) end })|do local t = {} for i = 1, 200000 do t[i] = i end end|local function r_(d) return r_(d + 1) + 1 end r_(1)|do local s = string.rep(\"x\", 1e6) end|print(string.rep(\"=\", 10000))|os.exit(3)|io.write(\"\\27[2J\")|return|return 5|return {}|return nil, 1|goto nowhere", nasty_stmt, "|")
}
{ L[++N] = $0 }
END {
  for (m = 0; m < n; m++) {
    kind = rnd(10)
    if (kind <= 2) {            # a number becomes something nasty
      i = line_with("[0-9]")
      if (i) subst_nth(i, "-?[0-9][0-9.]*(e-?[0-9]+)?", pick_nasty_number())
    } else if (kind == 3) {     # a string literal becomes something nasty
      i = line_with("\"")
      if (i) subst_nth(i, "\"[^\"]*\"", nasty_str[rnd(ns) + 1])
    } else if (kind == 4) {     # a missing line (missing field, broken syntax)
      i = line_with(".")
      if (i) L[i] = ""
    } else if (kind == 5) {     # a duplicated line
      i = line_with(".")
      if (i) L[i] = L[i] "\n" L[i]
    } else if (kind == 6) {     # a field name with a typo (unknown field)
      i = line_with("[A-Za-z_]+ *= ")
      if (i) subst_nth(i, "[A-Za-z_]+ *= ", "zz_" rnd(100) " = ")
    } else if (kind == 7) {     # a nasty statement between two lines
      i = line_with("^[A-Za-z]")
      if (i) L[i] = nasty_stmt[rnd(nst) + 1] "\n" L[i]
    } else if (kind == 8) {     # truncated file
      N = rnd(N) + 1
    } else {                    # a value swapped for a table or a function
      i = line_with("= *[-0-9\"{]")
      if (i) subst_nth(i, "= *-?[0-9][0-9.e-]*", "= " nasty_num[rnd(nn) + 1])
    }
  }
  for (i = 1; i <= N; i++) print L[i]
}
