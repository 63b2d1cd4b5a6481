# Render tests (label "render"): unit tests of the renderer's pieces, image-diff tests
# against tests/golden/, output paths (stills, frames, video, charts). Outputs and diff
# images go to <build>/tests/render-out/. The renderer library porelab_render comes from
# app/render/sources.cmake.
set(PL_RENDER_OUT ${CMAKE_CURRENT_BINARY_DIR}/render-out)
file(MAKE_DIRECTORY ${PL_RENDER_OUT})
set(_pl_render_defs PL_RENDER_OUT_DIR="${PL_RENDER_OUT}"
                    PL_GOLDEN_DIR="${CMAKE_SOURCE_DIR}/tests/golden")

pl_add_c_test(test_render_units SOURCES render/test_render_units.c
  LIBS porelab_render LABEL render)
pl_add_c_test(test_render_golden SOURCES render/test_render_golden.c render/render_scenes.c
  LIBS porelab_render LABEL render)
pl_add_c_test(test_render_output SOURCES render/test_render_output.c render/render_scenes.c
  LIBS porelab_render LABEL render)
foreach(t test_render_units test_render_golden test_render_output)
  target_compile_definitions(${t} PRIVATE ${_pl_render_defs})
endforeach()

# imgdiff: the comparison as a command (not a test): imgdiff EXPECTED ACTUAL [DIFF]
add_executable(imgdiff render/imgdiff.c)
target_link_libraries(imgdiff PRIVATE porelab_render)

# Benchmark (not a test): time per frame at 1280x720, split into build, raster, encode.
add_executable(bench_render bench/bench_render.c render/render_scenes.c)
target_include_directories(bench_render PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/render)
target_link_libraries(bench_render PRIVATE porelab_render)
target_compile_definitions(bench_render PRIVATE ${_pl_render_defs})

# Seed 000 Figs. 4-10 to 4-12 (pressure wave, FE against erfc) as charts; run by
# tools/figures.sh (not a test).
add_executable(wave_figures render/wave_figures.c)
target_link_libraries(wave_figures PRIVATE porelab_render)
target_include_directories(wave_figures PRIVATE ${PL_TEST_DIR})
