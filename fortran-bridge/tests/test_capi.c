/* Tests of the C ABI from C: status codes and messages for null pointers, bad sizes and bad
 * values (never a crash), the required-length protocol, handles, and calls from several
 * threads at once (results identical to a serial run, errors kept per thread).
 * Prints "N passed, M failed"; exits non-zero on a failure.
 */
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "pressridge.h"

static int passed = 0, failed = 0;

static void check(int ok, const char *name) {
    if (ok) {
        passed++;
        printf("ok     %s\n", name);
    } else {
        failed++;
        char msg[512];
        pressridge_last_error(msg, sizeof msg, NULL);
        printf("FAILED %s (last error: %s)\n", name, msg);
    }
}

static const char *last_error(void) {
    static _Thread_local char msg[1024];
    pressridge_last_error(msg, sizeof msg, NULL);
    return msg;
}

enum { NCAT = 5, NCOL = 2000, NTHREADS = 8, REPS = 50 };
static double A[NCOL * NCAT], V[NCOL * NCAT], A0[NCOL], REF[NCOL], REF_TABLE[NCOL];
static PressridgeCfTable *TABLE;

/* Deterministic synthetic columns, Fortran layout a[c*NCAT + n]; total area exactly 1. */
static void make_columns(void) {
    for (int c = 0; c < NCOL; c++) {
        double sum = 0;
        for (int n = 0; n < NCAT; n++) {
            double a = 0.2 * fabs(sin(0.37 * c + 1.3 * n + 0.1));
            A[c * NCAT + n] = a;
            V[c * NCAT + n] = a * (0.3 + 0.9 * n + 0.2 * cos(0.11 * c));
            sum += a;
        }
        A0[c] = 1.0 - sum;
    }
}

static int strength(const double *a, const double *v, const double *a0, int64_t ncol,
                    const PressridgeOptions *o, double *out) {
    PressridgeGrid g;
    pressridge_grid_fortran(NCAT, ncol, &g);
    return pressridge_strength(&g, a, v, a0, NULL, o, out, NULL);
}

static void *worker(void *arg) {
    long t = (long)arg;
    int *bad = calloc(1, sizeof(int));
    double *out = malloc(sizeof(double) * NCOL);
    PressridgeOptions table_opts;
    pressridge_options_default(&table_opts);
    table_opts.cf_source = PRESSRIDGE_CF_SOURCE_TABLE;
    table_opts.cf_table = TABLE; /* one handle shared by every thread */
    for (int r = 0; r < REPS; r++) {
        if ((t + r) % 4 == 0) {
            /* An error on this thread: its own code and message. */
            double a[NCAT] = {0.1, NAN, 0.1, 0.1, 0.1};
            if (strength(a, a, NULL, 1, NULL, out) != PRESSRIDGE_ERR_NOT_FINITE) (*bad)++;
            if (!strstr(last_error(), "not finite")) (*bad)++;
        } else {
            const PressridgeOptions *o = (r % 2) ? &table_opts : NULL;
            const double *ref = (r % 2) ? REF_TABLE : REF;
            if (strength(A, V, A0, NCOL, o, out) != PRESSRIDGE_OK) (*bad)++;
            if (strcmp(last_error(), "") != 0) (*bad)++; /* no other thread's error */
            if (memcmp(out, ref, sizeof(double) * NCOL) != 0) (*bad)++;
        }
    }
    free(out);
    return bad;
}

int main(void) {
    int32_t abi = -1;
    check(pressridge_abi_version(&abi) == PRESSRIDGE_OK && abi == PRESSRIDGE_ABI_VERSION,
          "ABI version of the library equals the header's");

    /* Required-length protocol. */
    int64_t need = 0;
    check(pressridge_version(NULL, 0, &need) == PRESSRIDGE_ERR_BUFFER_TOO_SMALL && need > 1,
          "version: null buffer gives the required length");
    char small[2];
    check(pressridge_version(small, 2, NULL) == PRESSRIDGE_ERR_BUFFER_TOO_SMALL &&
              small[1] == '\0',
          "version: short buffer is cut and NUL-terminated");
    char name[64];
    pressridge_status_name(PRESSRIDGE_ERR_IO, name, sizeof name, NULL);
    check(strcmp(name, "PRESSRIDGE_ERR_IO") == 0, "status names");

    make_columns();
    double out[NCOL];
    PressridgeGrid g;
    check(pressridge_grid_fortran(NCAT, NCOL, &g) == PRESSRIDGE_OK, "Fortran grid");
    check(pressridge_strength(&g, A, V, A0, NULL, NULL, REF, NULL) == PRESSRIDGE_OK,
          "strength of the synthetic grid");
    check(strcmp(last_error(), "") == 0, "success leaves no message");

    /* Null pointers. */
    check(pressridge_strength(NULL, A, V, A0, NULL, NULL, out, NULL) ==
              PRESSRIDGE_ERR_NULL_POINTER,
          "null grid");
    check(pressridge_strength(&g, NULL, V, A0, NULL, NULL, out, NULL) ==
                  PRESSRIDGE_ERR_NULL_POINTER &&
              strstr(last_error(), "aicen"),
          "null aicen, named in the message");
    check(pressridge_strength(&g, A, V, A0, NULL, NULL, NULL, NULL) ==
              PRESSRIDGE_ERR_NULL_POINTER,
          "null output");
    check(pressridge_options_default(NULL) == PRESSRIDGE_ERR_NULL_POINTER, "null options out");
    check(pressridge_ridge_step(&g, A, V, NULL, NULL, 0, A0, A0, 1.0, NULL, NULL, NULL) ==
              PRESSRIDGE_ERR_NULL_POINTER,
          "null aice0 in the ridging step");
    check(pressridge_cf_table_open(NULL, 3, &TABLE) == PRESSRIDGE_ERR_NULL_POINTER, "null path");
    check(pressridge_cf_table_free(NULL) == PRESSRIDGE_OK, "freeing null is a no-op");
    check(pressridge_scene_run("x", 1, NULL) == PRESSRIDGE_ERR_NULL_POINTER, "null run out");

    /* Sizes. */
    PressridgeGrid b = g;
    b.ncat = 0;
    check(pressridge_strength(&b, A, V, A0, NULL, NULL, out, NULL) == PRESSRIDGE_ERR_BAD_SIZE,
          "ncat = 0");
    b = g;
    b.ncol = -5;
    check(pressridge_strength(&b, A, V, A0, NULL, NULL, out, NULL) == PRESSRIDGE_ERR_BAD_SIZE,
          "negative ncol");
    b = g;
    b.len = NCAT * NCOL - 1;
    check(pressridge_strength(&b, A, V, A0, NULL, NULL, out, NULL) == PRESSRIDGE_ERR_BAD_SIZE &&
              strstr(last_error(), "too short"),
          "buffer length shorter than the layout");
    b = g;
    b.col_stride = 2;
    check(pressridge_strength(&b, A, V, A0, NULL, NULL, out, NULL) == PRESSRIDGE_ERR_BAD_SIZE,
          "overlapping strides");
    check(pressridge_grid_fortran(5, 0, &b) == PRESSRIDGE_ERR_BAD_SIZE, "grid with no columns");
    check(pressridge_strength(&g, A, V, A0, NULL, NULL, A, NULL) == PRESSRIDGE_ERR_BAD_SIZE,
          "output overlapping an input");

    /* Values. */
    double a[2 * NCAT], v[2 * NCAT], a0[2] = {0.5, 0.5};
    for (int k = 0; k < 2 * NCAT; k++) a[k] = 0.1, v[k] = 0.2;
    a[NCAT + 3] = NAN;
    int32_t code = -1;
    int64_t column = -1;
    check(strength(a, v, a0, 2, NULL, out) == PRESSRIDGE_ERR_NOT_FINITE, "NaN");
    pressridge_last_error_info(&code, &column);
    check(code == PRESSRIDGE_ERR_NOT_FINITE && column == 1, "NaN: code and column recorded");
    a[NCAT + 3] = -0.01;
    check(strength(a, v, a0, 2, NULL, out) == PRESSRIDGE_ERR_BAD_VALUE &&
              strstr(last_error(), "negative"),
          "negative area");
    a[NCAT + 3] = 0.1;
    a0[0] = 0.7;
    check(strength(a, v, a0, 2, NULL, out) == PRESSRIDGE_ERR_BAD_VALUE, "area sum is not 1");
    a0[0] = 0.5;
    PressridgeOptions o;
    pressridge_options_default(&o);
    o.redistribution = 9;
    check(strength(a, v, a0, 2, &o, out) == PRESSRIDGE_ERR_BAD_VALUE, "unknown option code");
    pressridge_options_default(&o);
    o.params.mu_rdg = -1;
    check(strength(a, v, a0, 2, &o, out) == PRESSRIDGE_ERR_BAD_VALUE &&
              strstr(last_error(), "mu_rdg"),
          "negative parameter");
    double conv[2] = {1e-6, 1e-6}, sh[2] = {0, 0};
    PressridgeGrid g2;
    pressridge_grid_fortran(NCAT, 2, &g2);
    check(pressridge_ridge_step(&g2, a, v, a0, NULL, 0, conv, sh, -60.0, NULL, NULL, NULL) ==
              PRESSRIDGE_ERR_BAD_VALUE,
          "negative time step");

    /* Tables. */
    const char *missing = "no-such-table.nc";
    PressridgeCfTable *t = NULL;
    check(pressridge_cf_table_open(missing, (int64_t)strlen(missing), &t) == PRESSRIDGE_ERR_IO &&
              t == NULL && strstr(last_error(), missing),
          "unreadable C_f table: IO error naming the file");
    double th[3] = {0.2, 1.0, 3.0}, cf[3] = {8.0, 12.0, 20.0};
    check(pressridge_cf_table_new(th, cf, 3, &TABLE) == PRESSRIDGE_OK, "C_f table from nodes");
    PressridgeOptions table_opts;
    pressridge_options_default(&table_opts);
    table_opts.cf_source = PRESSRIDGE_CF_SOURCE_TABLE;
    table_opts.cf_table = TABLE;
    check(strength(A, V, A0, NCOL, &table_opts, REF_TABLE) == PRESSRIDGE_OK,
          "strength with a C_f table");
    PressridgeRun *run = NULL;
    const char *bad_scene = "[sheet]\nthicknes = 0.3\n";
    check(pressridge_scene_run(bad_scene, (int64_t)strlen(bad_scene), &run) ==
                  PRESSRIDGE_ERR_PARSE &&
              run == NULL && strstr(last_error(), "thicknes"),
          "scene with an unknown key");

    /* Threads: the same answers as the serial run, each thread its own errors. */
    pthread_t th_ids[NTHREADS];
    for (long k = 0; k < NTHREADS; k++) pthread_create(&th_ids[k], NULL, worker, (void *)k);
    int bad = 0;
    for (int k = 0; k < NTHREADS; k++) {
        void *r;
        pthread_join(th_ids[k], &r);
        bad += *(int *)r;
        free(r);
    }
    check(bad == 0, "8 threads x 50 calls: identical results, per-thread errors");
    check(pressridge_cf_table_free(TABLE) == PRESSRIDGE_OK, "free the shared C_f table");

    printf("%d passed, %d failed\n", passed, failed);
    return failed == 0 ? 0 : 1;
}
