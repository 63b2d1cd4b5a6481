/* The engine's file writer for scenes (lua/file_writer.c). */
#ifndef PL_LUA_FILE_WRITER_H
#define PL_LUA_FILE_WRITER_H
#include "context.h"
#include "porelab/core.h"

/* A writer that keeps the engine's files inside ctx's output folder (sandbox) and writes them
   whole; ctx must outlive every world that uses it. */
pl_file_writer pl_lua_file_writer(pl_lua_context *ctx);
#endif
