/* See gmsh_session.h. */
#include "mesh/gmsh_session.h"

#if PL_HAVE_GMSH
#include "core/alloc.h"
#include <gmshc.h>
#include <stdlib.h>
#include <string.h>

int pl__gmsh_initialize(void)
{
    const char *home = getenv("HOME");
    char *saved = NULL;
    if (home) {
        size_t n = strlen(home) + 1;
        saved = pl_malloc(n);
        if (!saved) return -1;
        memcpy(saved, home, n);
    }
    setenv("HOME", "/dev/null", 1);
    int ierr = 0;
    gmshInitialize(0, NULL, 0, &ierr);
    if (saved) {
        setenv("HOME", saved, 1);
        pl_free(saved);
    } else {
        unsetenv("HOME");
    }
    return ierr;
}
#else
int pl__gmsh_initialize(void) { return -1; }
#endif
