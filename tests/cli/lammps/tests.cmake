# porelab export-lammps / import-lammps (issue 21; docs/scaling.md, "LAMMPS"). Label cli.
set(PL_LAMMPS_DIR ${CMAKE_CURRENT_LIST_DIR})
add_test(NAME cli_lammps_settle COMMAND bash ${PL_LAMMPS_DIR}/lammps_settle.sh $<TARGET_FILE:porelab>
         ${PL_LAMMPS_DIR}/settle.lua ${PL_CLI_OUT}/lammps_settle)
set_tests_properties(cli_lammps_settle PROPERTIES LABELS cli TIMEOUT 300 SKIP_RETURN_CODE 77)

# what LAMMPS cannot express is refused with every feature listed, and nothing is written
pl_cli_test(lammps_refuse_liquefaction RC 1 ARGS export-lammps scenes/soil/liquefaction.lua
  --out ${PL_CLI_OUT}/lammps_refuse_liq
  MATCH "cannot express 6 features this scene uses:.*7 polygons.*4 moving bodies.*the model 'darcy'.*discs of 3 materials with different contact laws.*walls .* touch discs of materials with different contact laws.*have discs on both sides.*nothing was written")
pl_cli_test(lammps_refuse_shaking RC 1 ARGS export-lammps scenes/grains/shaking_table.lua
  --out ${PL_CLI_OUT}/lammps_refuse_st NO_FILE ${PL_CLI_OUT}/lammps_refuse_st/in.lammps
  MATCH "cannot express 1 feature this scene uses:.*3 moving bodies \\(1, 2, 3: prescribed velocity, shaking table, servo or hinged wall\\)")
pl_cli_test(lammps_refuse_polygons RC 1 ARGS export-lammps scenes/figures/polygon_packing.lua
  --out ${PL_CLI_OUT}/lammps_refuse_poly
  MATCH "400 polygons.*local \\(non-viscous\\) damping LOCAL_DAMPING = 0.3")
pl_cli_test(lammps_import_missing RC 1 ARGS import-lammps tests/cli/lammps/no_such.dump --meta tests/cli/lammps/meta_bad.txt
  --out ${PL_CLI_OUT}/lammps_import_missing
  MATCH "meta_bad.txt:3: cannot read the 'dt' line")
pl_cli_test(lammps_import_bad_dump RC 1 ARGS import-lammps tests/cli/lammps/bad.dump --meta tests/cli/lammps/meta_ok.txt
  --contacts tests/cli/lammps/bad.dump --out ${PL_CLI_OUT}/lammps_import_bad
  MATCH "bad.dump:9: the dump needs the columns id type radius x y")
pl_cli_test(lammps_import_no_out RC 2 ARGS import-lammps tests/cli/lammps/bad.dump
  MATCH "give one dump file and --out DIR")
pl_cli_test(lammps_refuse_mix RC 1 ARGS export-lammps tests/cli/lammps/refuse_mix.lua --out ${PL_CLI_OUT}/lammps_refuse_mix
  NO_FILE ${PL_CLI_OUT}/lammps_refuse_mix/in.lammps
  MATCH "cannot express 5 features this scene uses:.*wall 1 \\(from \\(0, 0\\) to \\(1, 0.2\\) m\\) is slanted.*1 bond between grains.*GLOBAL_DAMPING_ROT = 0.01.*rolling resistance 0.1 between discs.*cohesion 2 N between discs")
