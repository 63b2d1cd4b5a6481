/// porelab core types: vectors, status codes, hashing.
/// The engine is plain C11; it includes no Lua, cairo, GL or SDL header.
#ifndef PORELAB_CORE_H
#define PORELAB_CORE_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define PL_VERSION_STRING "0.1.0"

/// A 2D vector. Units depend on use (m, m/s, N).
typedef struct pl_vec2 {
    double x, y;
} pl_vec2;

/// Status codes: 0 ok, negative errors. The world keeps a message for the last error
/// (pl_world_last_error) naming what, where and when.
typedef enum pl_status {
    PL_OK = 0,
    PL_ERR_ARG = -1,       ///< an argument is out of its valid range (user input)
    PL_ERR_STATE = -2,     ///< the call is not valid in the current state
    PL_ERR_UNSTABLE = -3,  ///< a stability guard stopped the run (NaN, energy surge, overlap)
    PL_ERR_NOT_BUILT = -4, ///< a recognised feature that this build does not provide yet
    PL_ERR_NUMERIC = -5,   ///< a numerical failure (singular matrix, no convergence)
    PL_ERR_IO = -6,        ///< a file could not be read or written
    PL_ERR_NOMEM = -7,     ///< out of memory
    PL_ERR_UNKNOWN = -8    ///< an unknown name (flag, material, option)
} pl_status;

/// Short name of a status ("ok", "bad argument", ...).
const char *pl_status_name(pl_status s);

/// Where the engine's file output goes. The engine opens no files itself: every file it makes
/// (VTK of bodies, contacts and the fluid, the MIMES geometry and pressure files) is formatted
/// in memory and handed whole to the host's writer, which decides where it may go (the Lua
/// sandbox keeps it inside the output folder) and how it is written (whole files: temporary
/// name, then rename). Without a writer, file output is refused with a message.
typedef struct pl_file_writer {
    /// Writes len bytes to path: append = 0 replaces the file, 1 appends to it. Returns 0, or -1
    /// with a message in msg (msglen bytes).
    int (*write)(void *ctx, const char *path, int append, const void *data, size_t len, char *msg,
                 size_t msglen);
    void *ctx;
} pl_file_writer;

/// FNV-1a 64-bit hash, used for state hashes (determinism tests).
uint64_t pl_hash_bytes(uint64_t h, const void *data, size_t n);
#define PL_HASH_SEED 1469598103934665603ull

#ifdef __cplusplus
}
#endif
#endif
