/* imgdiff: compares two PNG files with the renderer's tolerance.
 *   imgdiff EXPECTED.png ACTUAL.png [DIFF.png] [--channel N] [--fraction F]
 * Prints the measured numbers; exits 0 when the images match, 1 when they differ (writing
 * DIFF.png if given), 2 on errors. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "image_compare.h"

int main(int argc, char **argv) {
    const char *paths[3] = {NULL, NULL, NULL};
    int np = 0;
    pl_compare_tolerance tol = pl_default_compare_tolerance();
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--channel") == 0 && i + 1 < argc) {
            tol.channel_tolerance = atoi(argv[++i]);
        } else if (strcmp(argv[i], "--fraction") == 0 && i + 1 < argc) {
            tol.max_fraction = atof(argv[++i]);
        } else if (argv[i][0] == '-' && argv[i][1] == '-') {
            fprintf(stderr, "imgdiff: unknown option %s (valid: --channel N, --fraction F)\n", argv[i]);
            return 2;
        } else if (np < 3) {
            paths[np++] = argv[i];
        } else {
            np = 4;
        }
    }
    if (np < 2 || np > 3) {
        fprintf(stderr, "usage: imgdiff EXPECTED.png ACTUAL.png [DIFF.png] [--channel N] [--fraction F]\n"
                        "  tolerance: a pixel differs when a channel differs by more than N "
                        "(default %d of 255);\n  the images match when at most F of the pixels "
                        "differ (default %g)\n",
                tol.channel_tolerance, tol.max_fraction);
        return 2;
    }
    char msg[1024];
    int rc = pl_png_compare(paths[0], paths[1], &tol, paths[2], NULL, msg, sizeof msg);
    printf("%s: %s\n", rc == 1 ? "match" : (rc == 0 ? "differ" : "error"), msg);
    return rc == 1 ? 0 : (rc == 0 ? 1 : 2);
}
