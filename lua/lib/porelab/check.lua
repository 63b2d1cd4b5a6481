-- porelab.check: the argument checks that the pure-Lua helpers (porelab.packing, porelab.rock,
-- porelab.mimes) share. Their errors are located at the line of the scene that called the
-- helper (porelab.error skips the embedded helpers' own frames).
--   local check = require "porelab.check"
--   local fail, check_fields = check.for_module("packing.")
--   fail("box", "lo must be below hi (got %g)", y)          -> "packing.box: lo must be ..."
--   check_fields("box", def, {"lo", "hi", "material"})     -> refuses unknown fields, by name
local porelab = require "porelab"

local check = {}

--- Two functions for a helper module whose messages start with `prefix` (e.g. "packing."):
-- fail(fn, fmt, ...) raises "<prefix><fn>: <message>"; fields(fn, def, valid) refuses a
-- non-table and any field not in the list `valid`, naming the valid ones.
function check.for_module(prefix)
  local function fail(fn, msg, ...)
    porelab.error(string.format(prefix .. fn .. ": " .. msg, ...))
  end
  local function fields(fn, def, valid)
    if type(def) ~= "table" then fail(fn, "expected a table of fields (got %s)", type(def)) end
    local ok = {}
    for _, k in ipairs(valid) do ok[k] = true end
    for k in pairs(def) do
      if not ok[k] then
        fail(fn, "unknown field '%s' (valid: %s)", tostring(k), table.concat(valid, ", "))
      end
    end
  end
  return fail, fields
end

--- True for a finite number only: inf and nan pass "> 0" tests and turn into huge loops or
-- nan positions.
function check.finite(v)
  return type(v) == "number" and v == v and v > -math.huge and v < math.huge
end

return check
