# Faults (issue 13, items 12, 15, 17, 18): output that survives a kill and a failed write,
# range checks instead of hangs, readable chart messages, `porelab info` failing like run.
# Included from tests/cli/tests.cmake (pl_cli_test, PL_CLI_OUT).
set(PL_FAULTS tests/cli/faults)
set(PL_FAULTS_DIR ${CMAKE_CURRENT_LIST_DIR})

# kill -9 at seeded moments: every PNG whole, every CSV ending in a whole line.
add_test(NAME cli_faults_kill
  COMMAND sh ${PL_FAULTS_DIR}/kill_run.sh $<TARGET_FILE:porelab> $<TARGET_FILE:imgdiff>
          ${PL_FAULTS}/kill_scene.lua ${PL_CLI_OUT}/faults_kill 5 13
  WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
set_tests_properties(cli_faults_kill PROPERTIES LABELS cli TIMEOUT 60)
# A write that fails (file size limit, EFBIG): a message and a non-zero exit.
add_test(NAME cli_faults_write_fail
  COMMAND sh ${PL_FAULTS_DIR}/write_fail.sh $<TARGET_FILE:porelab> ${CMAKE_SOURCE_DIR}
          ${PL_CLI_OUT}/faults_write_fail
  WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
set_tests_properties(cli_faults_write_fail PROPERTIES LABELS cli TIMEOUT 60)

# Hangs become range errors that name the scene, the setting and the valid range.
function(pl_faults_test name)
  pl_cli_test(${name} ${ARGN})
  set_tests_properties(cli_${name} PROPERTIES TIMEOUT 20)
endfunction()
set(steps_re "the run would take 1e\\+22 steps \\(run.t_end: 1 s at dt = 1e-22 s\\); the valid range is 0..1e\\+15 steps")
pl_faults_test(faults_tiny_dt_run RC 1
  ARGS run ${PL_FAULTS}/tiny_dt.lua --quiet --out ${PL_CLI_OUT}/faults_tiny_dt
  MATCH "^porelab: tests/cli/faults/tiny_dt.lua:6: ${steps_re}")
pl_faults_test(faults_tiny_dt_info RC 1 ARGS info ${PL_FAULTS}/tiny_dt.lua
  MATCH "tiny_dt.lua:6: ${steps_re}")
pl_faults_test(faults_tiny_dt_308_info RC 1 ARGS info ${PL_FAULTS}/tiny_dt_308.lua
  MATCH "tiny_dt_308.lua:5: the run would take 1e\\+308 steps \\(default: 1 s at dt = 1e-308 s\\); the valid range is 0..1e\\+15 steps")
pl_faults_test(faults_tiny_dt_308_run RC 1
  ARGS run ${PL_FAULTS}/tiny_dt_308.lua --quiet --out ${PL_CLI_OUT}/faults_tiny_dt_308
  MATCH "tiny_dt_308.lua:5: the run would take 1e\\+308 steps")
pl_faults_test(faults_until_huge RC 2
  ARGS run ${PL_FAULTS}/plain.lua --until 1e300 --quiet --out ${PL_CLI_OUT}/faults_until
  MATCH "plain.lua:5: the run would take 1e\\+303 steps \\(--until: 1e\\+300 s at dt = 0.001 s\\)")
# a frame rate so low that the next frame is beyond any step count (the frame loop never ended)
pl_faults_test(faults_fps_tiny RC 0
  ARGS run ${PL_FAULTS}/plain.lua --fps 1e-300 --steps 10 --out ${PL_CLI_OUT}/faults_fps
  MATCH "frames +1 in .*faults_fps/")
pl_faults_test(faults_still_at_huge RC 1
  ARGS still ${PL_FAULTS}/plain.lua --at 1e300 -o ${PL_CLI_OUT}/faults_at.png
       --out ${PL_CLI_OUT}/faults_at
  MATCH "--at 1e\\+300 s is 1e\\+303 steps of dt = 0.001 s after the start; the valid range is up to 1e\\+15 steps")
set(camera_re "tiny_camera.lua:6: render: camera \\{0, 0, 1e-300, 1e-300\\} is 1e-300 x 1e-300 m; the valid range is 1e-09..1e\\+09 m each side")
foreach(cmd run still info)
  set(extra)
  if(cmd STREQUAL "run")
    set(extra --quiet --out ${PL_CLI_OUT}/faults_camera)
  elseif(cmd STREQUAL "still")
    set(extra -o ${PL_CLI_OUT}/faults_camera.png --out ${PL_CLI_OUT}/faults_camera)
  endif()
  pl_faults_test(faults_camera_${cmd} RC 1 ARGS ${cmd} ${PL_FAULTS}/tiny_camera.lua ${extra}
    MATCH "${camera_re}")
endforeach()

# Chart messages show their numbers (lua_pushfstring knows no %g or %lld).
pl_cli_test(faults_chart_range RC 1
  ARGS run ${PL_FAULTS}/chart_range.lua --quiet --out ${PL_CLI_OUT}/faults_chart
  MATCH "chart_range.lua:3: chart: xrange must be \\{min, max\\} with min < max \\(got \\{2, 1\\}\\)"
  NOMATCH "invalid option")
pl_cli_test(faults_chart_no_series RC 1
  ARGS run ${PL_FAULTS}/chart_no_series.lua --quiet --out ${PL_CLI_OUT}/faults_chart
  MATCH "chart_no_series.lua:3: chart: series must hold 1 to [0-9]+ entries \\(got 0\\)"
  NOMATCH "invalid option")

# porelab info fails like run: on an error in the run table, and it checks render.
pl_cli_test(faults_info_bad_run RC 1 ARGS info ${PL_FAULTS}/bad_run_table.lua
  MATCH "bad_run_table.lua(:[0-9]+)?: run: unknown field 'stepz'")
pl_cli_test(faults_info_bad_render RC 1 ARGS info ${PL_BAD}/bad_render.lua
  MATCH "bad_render.lua(:[0-9]+)?: render: layers: unknown layer 'force'")
pl_cli_test(faults_info_bad_overlay RC 1 ARGS info ${PL_BAD}/bad_overlay.lua
  MATCH "bad_overlay.lua(:[0-9]+)?: render: overlay\\[2\\]: radius must be > 0")
