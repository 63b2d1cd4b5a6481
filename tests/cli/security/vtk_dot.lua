-- security: a VTK prefix naming the output folder itself ("", ".", "./") would write
-- <outdir>_bodies.vtu beside the folder
local w = porelab.world { dt = 1e-3 }
w:disc { center = { 0, 0 }, radius = 0.1, material = w:material { name = "m", density = 1000, kn = 1e5 } }
for _, p in ipairs { "", "./", "sub/.." } do
  local ok, err = pcall(w.write_vtk, w, p)
  print(ok and ("written with prefix '" .. p .. "'") or ("refused: " .. err))
end
w:write_vtk(".")
