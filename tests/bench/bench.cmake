# Benchmark programs (built with the project, run by tests/bench/run_all.sh, never by ctest).
find_package(Threads REQUIRED)
add_executable(bench_dem bench/bench_dem.c ${CMAKE_SOURCE_DIR}/app/thread_pool.c)
target_include_directories(bench_dem PRIVATE ${CMAKE_SOURCE_DIR}/app)
target_link_libraries(bench_dem PRIVATE porelab_engine Threads::Threads)
add_executable(bench_bonds bench/bench_bonds.c)
target_link_libraries(bench_bonds PRIVATE porelab_engine)
# Solid kernels: element-steps per second (tests/bench/bench_solid.c; needs gmsh for the mesh).
add_executable(bench_solid bench/bench_solid.c)
target_include_directories(bench_solid PRIVATE ${CMAKE_SOURCE_DIR}/engine/src)
target_link_libraries(bench_solid PRIVATE porelab_engine)
# Boundary-element Stokes: error against CPU time, cost per coupled step, the fluid rungs side
# by side (tests/bench/bench_stokes.c; chart with PLplot):  build/tests/bench_stokes docs/figures
add_executable(bench_stokes bench/bench_stokes.c)
target_include_directories(bench_stokes PRIVATE ${PL_TEST_DIR} ${CMAKE_SOURCE_DIR}/engine/src)
target_link_libraries(bench_stokes PRIVATE porelab_engine)
# the chart through the app's charts (house style); only the chart, from a full run's CSV:
#   build/tests/bench_stokes docs/figures --chart-from docs/figures/bench_stokes.csv
if(TARGET porelab_render)
  target_sources(bench_stokes PRIVATE bench/bench_chart.c)
  target_compile_definitions(bench_stokes PRIVATE BENCH_CHART=1)
  target_include_directories(bench_stokes PRIVATE ${CMAKE_SOURCE_DIR}/app/render)
  target_link_libraries(bench_stokes PRIVATE porelab_render)
endif()
