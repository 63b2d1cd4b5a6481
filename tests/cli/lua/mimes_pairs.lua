-- The contact parameters a MIMES listing produces (run by ctest as cli_mimes_pairs; issue 13
-- item 7). The material block of seed 000 Appendix C.2 (scenes/mimes/buoyancy.lua) sets
-- friction, k_normal and k_shear of every pair in three commands; each must survive the
-- others. Before the fix only k_shear did: k_N = 39.8 N/m (E = 200 by seed 003 eq. 2.36) and
-- friction 0.5 (the default) instead of 400000 and 0.1.
local M = require("porelab.mimes").session()
M.install(_ENV)
set("matnum", 2)
create_material_list_ui(2)
set("E(1)", 200)
set("nu(1)", 0.3)
set("density(1)", 1.5)
set("E(2)", 200)
set("nu(2)", 0.3)
set("density(2)", 0.5)
apply_material_list(2)
set("fric(1,1)", 0.1)
set("fric(2,1)", 0.1)
set("fric(2,2)", 0.1)
apply_fric(2)
set("k_normal(1,1)", 400000)
set("k_normal(2,1)", 400000)
set("k_normal(2,2)", 400000)
apply_kn(2)
set("k_shear(1,1)", 600000)
set("k_shear(2,1)", 600000)
set("k_shear(2,2)", 600000)
apply_ks(2)

local w = M.world
local function check(a, b, field, want)
  local got = w:pair_params(a, b)[field]
  assert(got == want, string.format("pair (%s, %s): %s = %s, the listing sets %s", a, b, field, tostring(got), tostring(want)))
end
for _, ab in ipairs { { "mimes1", "mimes1" }, { "mimes2", "mimes1" }, { "mimes1", "mimes2" }, { "mimes2", "mimes2" } } do
  check(ab[1], ab[2], "kn", 400000)
  check(ab[1], ab[2], "ks", 600000)
  check(ab[1], ab[2], "friction", 0.1)
end

-- world:pair merges with the pair's override; the fields it omits keep their earlier values,
-- and pairs never overridden keep the combination rules
local a = w:material { name = "a", density = 1000, kn = 1e5, friction = 0.4 }
local b = w:material { name = "b", density = 1000, kn = 3e5, friction = 0.6 }
w:pair(a, b, { friction = 0.2 })
w:pair(a, b, { kn = 7e4 })
w:pair(b, a, { restitution = 0.5 })
local p = w:pair_params(a, b)
assert(p.friction == 0.2 and p.kn == 7e4 and p.restitution == 0.5, "pair: merged override lost a field")
assert(p.ks == 2 * (2 / 3 * 1e5) * (2 / 3 * 3e5) / (2 / 3 * 1e5 + 2 / 3 * 3e5), "pair: ks must stay the series default")
local q = w:pair_params(a, a)
assert(q.kn == 1e5 and q.friction == 0.4 and q.restitution == nil, "pair_params: defaults of an untouched pair")
print("mimes pairs: k_N 400000, k_S 600000, friction 0.1 on all pairs of the C.2 listing")
