/* A small C host: the strength of three columns of five categories with CICE's defaults and
 * with Hibler's C_f, then one ridging step. Build: see fortran-bridge/Makefile; docs/c-api.md.
 */
#include <stdio.h>
#include <stdlib.h>

#include "pressridge.h"

/* Prints the last error and exits when a call fails. */
static void check(int32_t rc, const char *what) {
    if (rc == PRESSRIDGE_OK) return;
    char msg[512];
    pressridge_last_error(msg, sizeof msg, NULL);
    fprintf(stderr, "%s failed (status %d): %s\n", what, rc, msg);
    exit(1);
}

int main(void) {
    enum { NCAT = 5, NCOL = 3 };
    /* Fortran-style layout aicen[col][cat]: categories of one column are contiguous. */
    double aicen[NCOL][NCAT] = {
        {0.10, 0.30, 0.30, 0.15, 0.05},
        {0.40, 0.20, 0.10, 0.00, 0.00},
        {0.00, 0.00, 0.00, 0.00, 0.00},
    };
    double vicen[NCOL][NCAT] = {
        {0.03, 0.30, 0.57, 0.45, 0.21},
        {0.12, 0.20, 0.19, 0.00, 0.00},
        {0.00, 0.00, 0.00, 0.00, 0.00},
    };
    double aice0[NCOL] = {0.10, 0.30, 1.00};
    double strength[NCOL];

    char version[32];
    check(pressridge_version(version, sizeof version, NULL), "pressridge_version");
    printf("pressridge %s\n", version);

    PressridgeGrid grid;
    check(pressridge_grid_fortran(NCAT, NCOL, &grid), "pressridge_grid_fortran");
    PressridgeOptions opts;
    check(pressridge_options_default(&opts), "pressridge_options_default");
    check(pressridge_strength(&grid, &aicen[0][0], &vicen[0][0], aice0, NULL, &opts, strength,
                              NULL),
          "pressridge_strength");
    for (int c = 0; c < NCOL; c++) printf("column %d: P = %8.1f N/m (C_f = 17)\n", c, strength[c]);

    opts.cf = PRESSRIDGE_CF_HIBLER1980;
    check(pressridge_strength(&grid, &aicen[0][0], &vicen[0][0], aice0, NULL, &opts, strength,
                              NULL),
          "pressridge_strength");
    for (int c = 0; c < NCOL; c++) printf("column %d: P = %8.1f N/m (C_f = 2)\n", c, strength[c]);

    /* One ridging step of an hour at a convergence of 1e-6 1/s, CICE's default bounds. */
    double conv[NCOL] = {1e-6, 1e-6, 1e-6}, shear[NCOL] = {0, 0, 0}, closing[NCOL];
    PressridgeRidgeRates rates = {closing, NULL, NULL, NULL, NULL};
    check(pressridge_ridge_step(&grid, &aicen[0][0], &vicen[0][0], aice0, NULL, 0, conv, shear,
                                3600.0, NULL, NULL, &rates),
          "pressridge_ridge_step");
    for (int c = 0; c < NCOL; c++)
        printf("column %d: aice0 %.6f after ridging, closing rate %.3e 1/s\n", c, aice0[c],
               closing[c]);

    /* Errors are codes with a message, never a crash. */
    aicen[1][2] = -0.1;
    int32_t rc = pressridge_strength(&grid, &aicen[0][0], &vicen[0][0], NULL, NULL, NULL,
                                     strength, NULL);
    char msg[256];
    pressridge_last_error(msg, sizeof msg, NULL);
    printf("bad input gives status %d: %s\n", rc, msg);
    return rc == PRESSRIDGE_ERR_BAD_VALUE ? 0 : 1;
}
