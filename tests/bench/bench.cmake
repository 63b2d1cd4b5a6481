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
find_library(PL_STOKES_PLPLOT_LIB plplot)
find_path(PL_STOKES_PLPLOT_INCLUDE plplot.h PATH_SUFFIXES plplot)
if(PL_STOKES_PLPLOT_LIB AND PL_STOKES_PLPLOT_INCLUDE)
  target_compile_definitions(bench_stokes PRIVATE PL_STOKES_CHART=1)
  target_include_directories(bench_stokes PRIVATE ${PL_STOKES_PLPLOT_INCLUDE})
  target_link_libraries(bench_stokes PRIVATE ${PL_STOKES_PLPLOT_LIB})
endif()
