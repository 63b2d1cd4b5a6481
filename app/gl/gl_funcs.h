/// OpenGL entry points used by the GL backend, loaded at run time through a get-proc-address
/// function (OSMesaGetProcAddress headless, SDL_GL_GetProcAddress in the window).
///
/// Why a table instead of calling gl* by name: the program may hold two GL implementations
/// at once (libOSMesa for headless renders, libGL loaded by SDL for the window), both
/// exporting the same gl* symbols. Calling through pointers obtained from the context's own
/// loader always reaches the implementation that owns the current context.
///
/// Version used: OpenGL 2.1 (GLSL 1.20, compatibility profile) plus framebuffer objects
/// (GL 3.0 or ARB_framebuffer_object) for multisampled offscreen rendering. llvmpipe through
/// OSMesa and every SDL2 window on a desktop driver provide this.
#ifndef PORELAB_GL_FUNCS_H
#define PORELAB_GL_FUNCS_H

#include <GL/gl.h>
#include <GL/glext.h>

typedef void *(*pl_gl_get_proc)(const char *name);

/* X(return type, name without "gl", argument list) */
#define PL_GL_REQUIRED(X)                                                                     \
    X(void, Clear, (GLbitfield))                                                              \
    X(void, ClearColor, (GLclampf, GLclampf, GLclampf, GLclampf))                             \
    X(void, ClearDepth, (GLclampd))                                                           \
    X(void, Enable, (GLenum))                                                                 \
    X(void, Disable, (GLenum))                                                                \
    X(void, BlendFunc, (GLenum, GLenum))                                                      \
    X(void, DepthFunc, (GLenum))                                                              \
    X(void, DepthMask, (GLboolean))                                                           \
    X(void, Viewport, (GLint, GLint, GLsizei, GLsizei))                                       \
    X(void, ReadPixels, (GLint, GLint, GLsizei, GLsizei, GLenum, GLenum, GLvoid *))           \
    X(void, GetIntegerv, (GLenum, GLint *))                                                   \
    X(const GLubyte *, GetString, (GLenum))                                                   \
    X(void, GenTextures, (GLsizei, GLuint *))                                                 \
    X(void, DeleteTextures, (GLsizei, const GLuint *))                                        \
    X(void, BindTexture, (GLenum, GLuint))                                                    \
    X(void, TexImage2D, (GLenum, GLint, GLint, GLsizei, GLsizei, GLint, GLenum, GLenum,       \
                         const GLvoid *))                                                     \
    X(void, TexParameteri, (GLenum, GLenum, GLint))                                           \
    X(void, PixelStorei, (GLenum, GLint))                                                     \
    X(void, DrawElements, (GLenum, GLsizei, GLenum, const GLvoid *))                          \
    X(GLenum, GetError, (void))                                                               \
    X(void, Finish, (void))                                                                   \
    X(GLuint, CreateShader, (GLenum))                                                         \
    X(void, ShaderSource, (GLuint, GLsizei, const GLchar *const *, const GLint *))            \
    X(void, CompileShader, (GLuint))                                                          \
    X(void, GetShaderiv, (GLuint, GLenum, GLint *))                                           \
    X(void, GetShaderInfoLog, (GLuint, GLsizei, GLsizei *, GLchar *))                         \
    X(GLuint, CreateProgram, (void))                                                          \
    X(void, AttachShader, (GLuint, GLuint))                                                   \
    X(void, LinkProgram, (GLuint))                                                            \
    X(void, GetProgramiv, (GLuint, GLenum, GLint *))                                          \
    X(void, GetProgramInfoLog, (GLuint, GLsizei, GLsizei *, GLchar *))                        \
    X(void, UseProgram, (GLuint))                                                             \
    X(GLint, GetUniformLocation, (GLuint, const GLchar *))                                    \
    X(void, Uniform2f, (GLint, GLfloat, GLfloat))                                             \
    X(void, Uniform4f, (GLint, GLfloat, GLfloat, GLfloat, GLfloat))                           \
    X(void, Uniform1i, (GLint, GLint))                                                        \
    X(void, Uniform1f, (GLint, GLfloat))                                                      \
    X(void, BindAttribLocation, (GLuint, GLuint, const GLchar *))                             \
    X(void, EnableVertexAttribArray, (GLuint))                                                \
    X(void, VertexAttribPointer, (GLuint, GLint, GLenum, GLboolean, GLsizei, const GLvoid *)) \
    X(void, DeleteShader, (GLuint))                                                           \
    X(void, DeleteProgram, (GLuint))                                                          \
    X(void, GenBuffers, (GLsizei, GLuint *))                                                  \
    X(void, DeleteBuffers, (GLsizei, const GLuint *))                                         \
    X(void, BindBuffer, (GLenum, GLuint))                                                     \
    X(void, BufferData, (GLenum, GLsizeiptr, const GLvoid *, GLenum))                         \
    X(void, BufferSubData, (GLenum, GLintptr, GLsizeiptr, const GLvoid *))                    \
    X(void, ActiveTexture, (GLenum))                                                          \
    X(void, BlendFuncSeparate, (GLenum, GLenum, GLenum, GLenum))                              \
    X(void, GenFramebuffers, (GLsizei, GLuint *))                                             \
    X(void, DeleteFramebuffers, (GLsizei, const GLuint *))                                    \
    X(void, BindFramebuffer, (GLenum, GLuint))                                                \
    X(void, GenRenderbuffers, (GLsizei, GLuint *))                                            \
    X(void, DeleteRenderbuffers, (GLsizei, const GLuint *))                                   \
    X(void, BindRenderbuffer, (GLenum, GLuint))                                               \
    X(void, RenderbufferStorage, (GLenum, GLenum, GLsizei, GLsizei))                          \
    X(void, FramebufferRenderbuffer, (GLenum, GLenum, GLenum, GLuint))                        \
    X(GLenum, CheckFramebufferStatus, (GLenum))                                               \
    X(void, BlitFramebuffer, (GLint, GLint, GLint, GLint, GLint, GLint, GLint, GLint,         \
                              GLbitfield, GLenum))

/* Optional: missing ones leave NULL (no multisampling, no vertex array object). */
#define PL_GL_OPTIONAL(X)                                                                     \
    X(void, RenderbufferStorageMultisample, (GLenum, GLsizei, GLenum, GLsizei, GLsizei))      \
    X(void, GenVertexArrays, (GLsizei, GLuint *))                                             \
    X(void, BindVertexArray, (GLuint))                                                        \
    X(void, DeleteVertexArrays, (GLsizei, const GLuint *))

#define PL_GL_FIELD(ret, name, args) ret (*name) args;
typedef struct pl_gl_funcs {
    PL_GL_REQUIRED(PL_GL_FIELD)
    PL_GL_OPTIONAL(PL_GL_FIELD)
} pl_gl_funcs;
#undef PL_GL_FIELD

/// Loads every entry point. Returns 0, or -1 naming the first missing required one in err.
int pl_gl_funcs_load(pl_gl_funcs *f, pl_gl_get_proc get_proc, char *err, unsigned errlen);

#endif
