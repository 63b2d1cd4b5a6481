# Renderer sources (owned by the renderer). Included from app/CMakeLists.txt.
#
# 1. PL_RENDER_SOURCES: the renderer's core sources relative to app/ (the program may compile
#    them directly).
# 2. porelab_render: a static library with the whole renderer (core + PLplot charts), used by
#    the program and by the render tests. Link it with target_link_libraries(... porelab_render).
list(APPEND PL_RENDER_SOURCES
  render/drawlist.c
  render/colormap.c
  render/isolines.c
  render/backend_cairo.c
  render/svg_text.c
  render/label_place.c
  render/raster_gouraud.c
  render/raster_aa.c
  render/png_io.c
  render/draw_world.c
  render/draw_annot.c
  render/draw_field.c
  render/draw_fluid.c
  render/render.c
  render/frames.c
  render/chart_text.c
  render/image_compare.c)

if(NOT TARGET porelab_render)
  set(_pl_render_dir ${CMAKE_CURRENT_LIST_DIR})
  set(_pl_render_srcs ${PL_RENDER_SOURCES})
  list(TRANSFORM _pl_render_srcs REPLACE "^render/" "${_pl_render_dir}/")
  find_package(Threads REQUIRED)
  pkg_check_modules(PLPLOT IMPORTED_TARGET plplot)
  if(PLPLOT_FOUND)
    list(APPEND _pl_render_srcs ${_pl_render_dir}/charts.c)
  else()
    message(WARNING "PLplot not found (Debian package libplplot-dev): charts are not built")
    list(APPEND _pl_render_srcs ${_pl_render_dir}/charts_missing.c)
  endif()
  add_library(porelab_render STATIC ${_pl_render_srcs})
  target_include_directories(porelab_render PUBLIC ${_pl_render_dir})
  target_link_libraries(porelab_render PUBLIC porelab_engine PkgConfig::CAIRO PkgConfig::PNG
    Threads::Threads m)
  if(PLPLOT_FOUND)
    target_link_libraries(porelab_render PRIVATE PkgConfig::PLPLOT)
  endif()
endif()
