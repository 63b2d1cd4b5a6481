# OpenGL backend, headless OSMesa context and the SDL2 window (owned by gl).
# Included from app/CMakeLists.txt after render/sources.cmake. Decisions:
# - porelab_gl (GL backend + OSMesa) is built when pkg-config finds OSMesa (Debian
#   libosmesa6-dev); without it `--renderer gl` says how to get it and cairo stays the renderer.
#   The backend loads GL entry points through the context's get-proc-address, so it never
#   links libGL (the window's libGL comes from SDL at run time).
# - The window needs SDL2 (Debian libsdl2-dev) and porelab_gl. PL_WITH_SDL: AUTO (build the
#   window when SDL2 is found), ON (required: fail when missing), OFF (never). Without the
#   window, `porelab view` and `run --window` explain how to get it.
# Outputs for app/CMakeLists.txt:
#   PL_GL_APP_SOURCES  sources to compile into the porelab program
#   PL_GL_APP_LIBS     libraries the program links
set(_pl_gl_dir ${CMAKE_CURRENT_LIST_DIR})
set(_pl_win_dir ${CMAKE_CURRENT_LIST_DIR}/../window)
set(PL_GL_APP_SOURCES ${_pl_win_dir}/cmd_view.c ${_pl_gl_dir}/gl_cli.c)
set(PL_GL_APP_LIBS)

pkg_check_modules(OSMESA IMPORTED_TARGET osmesa)
if(OSMESA_FOUND AND NOT TARGET porelab_gl)
  add_library(porelab_gl STATIC
    ${_pl_gl_dir}/gl_funcs.c
    ${_pl_gl_dir}/gl_text.c
    ${_pl_gl_dir}/backend_gl.c
    ${_pl_gl_dir}/osmesa_context.c)
  target_include_directories(porelab_gl PUBLIC ${_pl_gl_dir})
  target_compile_definitions(porelab_gl PUBLIC PL_HAVE_GL=1)
  target_link_libraries(porelab_gl PUBLIC porelab_render PkgConfig::OSMESA PkgConfig::CAIRO m)
elseif(NOT OSMESA_FOUND)
  message(STATUS "OSMesa not found (Debian package libosmesa6-dev): the OpenGL renderer "
                 "(--renderer gl) and the window are not built")
endif()

if(NOT DEFINED PL_WITH_SDL OR PL_WITH_SDL STREQUAL "")
  set(PL_WITH_SDL AUTO)
endif()
set(PL_HAVE_WINDOW 0)
if(TARGET porelab_gl AND NOT PL_WITH_SDL STREQUAL "OFF")
  pkg_check_modules(SDL2 IMPORTED_TARGET sdl2)
  if(SDL2_FOUND)
    set(PL_HAVE_WINDOW 1)
  elseif(PL_WITH_SDL)  # ON / TRUE / 1 (AUTO is not a true constant)
    if(NOT PL_WITH_SDL STREQUAL "AUTO")
      message(FATAL_ERROR "PL_WITH_SDL=${PL_WITH_SDL} but SDL2 was not found "
                          "(Debian package libsdl2-dev)")
    endif()
  endif()
elseif(PL_WITH_SDL AND NOT PL_WITH_SDL STREQUAL "AUTO" AND NOT PL_WITH_SDL STREQUAL "OFF"
       AND NOT TARGET porelab_gl)
  message(FATAL_ERROR "PL_WITH_SDL=${PL_WITH_SDL}: the window needs OSMesa/OpenGL headers "
                      "(Debian package libosmesa6-dev)")
endif()

# visible to tests/gl/tests.cmake (another directory scope)
set(PL_HAVE_WINDOW ${PL_HAVE_WINDOW} CACHE INTERNAL "porelab window built")
if(TARGET porelab_gl)
  list(APPEND PL_GL_APP_LIBS porelab_gl)
endif()
if(PL_HAVE_WINDOW)
  list(APPEND PL_GL_APP_SOURCES
    ${_pl_win_dir}/window.c
    ${_pl_win_dir}/window_hud.c
    ${_pl_win_dir}/window_sim.c
    ${_pl_win_dir}/window_live.c
    ${_pl_win_dir}/window_picker.c)
  list(APPEND PL_GL_APP_LIBS PkgConfig::SDL2)
  message(STATUS "porelab window: SDL2 ${SDL2_VERSION} (porelab view SCENE.lua)")
else()
  list(APPEND PL_GL_APP_SOURCES ${_pl_win_dir}/window_missing.c)
  if(NOT PL_WITH_SDL STREQUAL "OFF")
    message(STATUS "porelab window not built (needs SDL2: Debian package libsdl2-dev, and OSMesa)")
  endif()
endif()
