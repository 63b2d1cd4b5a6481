# OpenGL backend tests (label "gl"), built when the GL backend is (OSMesa found; see
# app/gl/sources.cmake). Outputs and diff images go to <build>/tests/gl-out/.
#   test_gl_render   image-diff vs tests/golden/gl/, GL vs cairo PSNR, rasterization units
#   gl_cli           porelab still/run --renderer gl against the cairo renderer
#   gl_window_xvfb   the SDL2 window under Xvfb driven by xdotool (needs xvfb, xdotool, SDL2)
#   gl_window_scenes every scene of scenes/ opens live; its screenshot = the headless render
if(TARGET porelab_gl)
  set(PL_GL_OUT ${CMAKE_CURRENT_BINARY_DIR}/gl-out)
  file(MAKE_DIRECTORY ${PL_GL_OUT})
  pl_add_c_test(test_gl_render SOURCES gl/test_gl_render.c render/render_scenes.c
    LIBS porelab_gl porelab_render LABEL gl)
  target_include_directories(test_gl_render PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/render
    ${CMAKE_CURRENT_SOURCE_DIR}/gl)
  target_compile_definitions(test_gl_render PRIVATE PL_GL_OUT_DIR="${PL_GL_OUT}"
    PL_GOLDEN_DIR="${CMAKE_SOURCE_DIR}/tests/golden")

  # psnr: PSNR of two PNGs, exit 1 when below a threshold (used by the shell tests)
  add_executable(gl_psnr gl/psnr_tool.c)
  target_include_directories(gl_psnr PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/gl)
  target_link_libraries(gl_psnr PRIVATE porelab_render)

  add_test(NAME gl_cli COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/gl/test_gl_cli.sh
    $<TARGET_FILE:porelab> $<TARGET_FILE:gl_psnr> ${CMAKE_SOURCE_DIR} ${PL_GL_OUT}/cli)
  set_tests_properties(gl_cli PROPERTIES LABELS gl TIMEOUT 180)

  pkg_check_modules(X11 IMPORTED_TARGET x11)
  find_program(PL_XVFB Xvfb)
  find_program(PL_XDOTOOL xdotool)
  if(PL_HAVE_WINDOW AND X11_FOUND AND PL_XVFB AND PL_XDOTOOL)
    add_executable(gl_xcapture gl/xcapture.c)
    target_link_libraries(gl_xcapture PRIVATE porelab_render PkgConfig::X11)
    add_test(NAME gl_window_xvfb COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/gl/test_window_xvfb.sh
      $<TARGET_FILE:porelab> $<TARGET_FILE:gl_psnr> $<TARGET_FILE:gl_xcapture>
      ${CMAKE_SOURCE_DIR} ${PL_GL_OUT}/window)
    set_tests_properties(gl_window_xvfb PROPERTIES LABELS gl TIMEOUT 240)
    add_test(NAME gl_window_scenes COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/gl/test_window_scenes.sh
      $<TARGET_FILE:porelab> $<TARGET_FILE:gl_psnr> ${CMAKE_SOURCE_DIR} ${PL_GL_OUT}/scenes)
    set_tests_properties(gl_window_scenes PROPERTIES LABELS gl TIMEOUT 900)
    # the window's sandbox limits: a hook's endless loop stopped with its line (issue 13 item 4)
    add_test(NAME gl_window_limits COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/gl/test_window_limits.sh
      $<TARGET_FILE:porelab> ${CMAKE_SOURCE_DIR} ${PL_GL_OUT}/limits)
    set_tests_properties(gl_window_limits PROPERTIES LABELS gl TIMEOUT 60)
  else()
    message(STATUS "gl_window_xvfb test skipped (needs the window, libx11-dev, xvfb, xdotool)")
  endif()

  add_executable(bench_gl bench/bench_gl.c render/render_scenes.c)
  target_include_directories(bench_gl PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/render)
  target_link_libraries(bench_gl PRIVATE porelab_gl porelab_render)
endif()
