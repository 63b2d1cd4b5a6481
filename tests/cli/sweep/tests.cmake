# porelab sweep / collect and the run contract (issue 21; docs/scaling.md). Label cli.
set(PL_SWEEP_DIR ${CMAKE_CURRENT_LIST_DIR})
add_test(NAME cli_sweep_parallel COMMAND bash ${PL_SWEEP_DIR}/sweep_parallel.sh $<TARGET_FILE:porelab>
         ${CMAKE_SOURCE_DIR}/scenes/grains/shaking_table.lua ${PL_CLI_OUT}/sweep_parallel)
set_tests_properties(cli_sweep_parallel PROPERTIES LABELS cli TIMEOUT 300 SKIP_RETURN_CODE 77)

# the run contract's bad input: the parameter and its range named
pl_cli_test(run_param_unknown RC 1 ARGS run scenes/grains/shaking_table.lua --steps 1 -q --param ampl=0.01
  --out ${PL_CLI_OUT}/param_unknown
  MATCH "--param ampl=0.01: scenes/grains/shaking_table.lua declares no parameter 'ampl'; its parameters: amp in \\[0.001, 0.02\\] m, freq in \\[1, 15\\] Hz")
pl_cli_test(run_param_range RC 1 ARGS run scenes/grains/shaking_table.lua --steps 1 -q --param freq=20
  --out ${PL_CLI_OUT}/param_range
  MATCH "shaking_table.lua:[0-9]+: --param freq=20: freq must be in \\[1, 15\\] Hz")
pl_cli_test(run_param_malformed RC 2 ARGS run scenes/grains/shaking_table.lua --param freq
  MATCH "--param must be NAME=NUMBER")
pl_cli_test(run_param_twice RC 2 ARGS run scenes/grains/shaking_table.lua --param freq=5 --param freq=6
  MATCH "--param freq given twice")
pl_cli_test(run_seed_bad RC 2 ARGS run scenes/grains/shaking_table.lua --seed -3
  MATCH "--seed must be an integer in \\[0, 9007199254740991\\]")
pl_cli_test(run_manifest RC 0 ARGS run scenes/grains/shaking_table.lua --steps 20 -q --no-frames --param amp=0.01
  --seed 4 --out ${PL_CLI_OUT}/run_manifest
  EXPECT_FILE ${PL_CLI_OUT}/run_manifest/manifest.json
  FILE_MATCH "\"seed\": 4,.*\"amp\": {\"value\": 0.01, \"unit\": \"m\", \"min\": 0.001, \"max\": 0.02, \"given\": true}.*\"exit_status\": 0,.*\"nut_rise_mm\": {\"value\": [-0-9.e]+, \"unit\": \"mm\"}")
pl_cli_test(run_results_bad RC 1 ARGS run tests/cli/sweep/bad_results.lua -q --no-frames --out ${PL_CLI_OUT}/bad_results
  MATCH "bad_results.lua:6: results.ru: unknown field '1' \\(valid: value, unit\\)"
  EXPECT_FILE ${PL_CLI_OUT}/bad_results/manifest.json FILE_MATCH "\"exit_status\": 1,")
pl_cli_test(sweep_grid_unknown RC 2 ARGS sweep scenes/grains/shaking_table.lua --grid "amplitude=1,2"
  --out ${PL_CLI_OUT}/sweep_unknown
  MATCH "--grid amplitude: scenes/grains/shaking_table.lua declares no parameter 'amplitude'; its parameters: amp in \\[0.001, 0.02\\] m")
pl_cli_test(sweep_grid_range RC 2 ARGS sweep scenes/grains/shaking_table.lua --grid "freq=2,30"
  --out ${PL_CLI_OUT}/sweep_range MATCH "--grid freq: 30 is outside the declared range \\[1, 15\\] Hz")
pl_cli_test(sweep_seeds_bad RC 2 ARGS sweep scenes/grains/shaking_table.lua --seeds 5..2
  --out ${PL_CLI_OUT}/sweep_seeds MATCH "--seeds: each range A..B needs 0 <= A <= B")
pl_cli_test(sweep_lhs RC 0 ARGS sweep scenes/grains/shaking_table.lua --lhs 5 --range amp=0.002:0.012 --seeds 1..2
  --out ${PL_CLI_OUT}/sweep_lhs MATCH "10 jobs \\(Latin hypercube 5 points over 1 parameters x 2 seeds\\)"
  EXPECT_FILE ${PL_CLI_OUT}/sweep_lhs/jobs.txt FILE_MATCH "--param amp=0.00[2-9][0-9]*.* --seed 2")
pl_cli_test(collect_none RC 1 ARGS collect tests/cli/sweep
  MATCH "tests/cli/sweep holds no manifest.json")
