/* tcheck.h: the small harness every ctest executable uses. A test prints what it compares, exits
 * 0 (pass), 1 (fail) or 77 (skip: no OpenCL device, or no fp64 in a double build). */
#ifndef CLSPH_TCHECK_H
#define CLSPH_TCHECK_H

#include <stddef.h>

#include "dev.h"

#define TC_SKIP 77

/** @brief Record a check; prints a line on failure (and on success with CLSPH_TEST_VERBOSE). */
void tc_check(int ok, const char *file, int line, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
#define TC_CHECK(ok, ...) tc_check((ok), __FILE__, __LINE__, __VA_ARGS__)

/** @brief |got − want| <= tol, printed with the names. */
#define TC_NEAR(got, want, tol, ...)                                                               \
  tc_near((double)(got), (double)(want), (double)(tol), __FILE__, __LINE__, __VA_ARGS__)
void tc_near(double got, double want, double tol, const char *file, int line, const char *fmt, ...)
    __attribute__((format(printf, 6, 7)));

/** @brief Open the default device with fp64 when this is a double build; exits 77 when there is
 *  none. Also points the program cache at $CLSPH_CACHE_DIR (set by ctest). */
void tc_open_device(struct dev *dev);

/** @brief Read a whole text file (exits 1 when it cannot). */
char *tc_read_text(const char *path);

/** @brief Summary line and exit status: 0 when every check passed, else 1. */
int tc_finish(const char *name);

#endif /* CLSPH_TCHECK_H */
