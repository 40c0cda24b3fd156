/* tcheck.c: test harness. */
#include "tcheck.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

#include "clsph_config.h"

static int checks = 0, failures = 0;

static void report(int ok, const char *file, int line, const char *fmt, va_list ap)
{
  ++checks;
  if (!ok) ++failures;
  if (ok && getenv("CLSPH_TEST_VERBOSE") == NULL) return;
  printf("%s %s:%d: ", ok ? "ok  " : "FAIL", file, line);
  vprintf(fmt, ap);
  putchar('\n');
}

void tc_check(int ok, const char *file, int line, const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  report(ok, file, line, fmt, ap);
  va_end(ap);
}

void tc_near(double got, double want, double tol, const char *file, int line, const char *fmt, ...)
{
  int ok = fabs(got - want) <= tol; /* false for NaN */
  ++checks;
  if (!ok) ++failures;
  if (ok && getenv("CLSPH_TEST_VERBOSE") == NULL) return;
  va_list ap;
  va_start(ap, fmt);
  printf("%s %s:%d: ", ok ? "ok  " : "FAIL", file, line);
  vprintf(fmt, ap);
  va_end(ap);
  printf(": got %.17g, want %.17g, |diff| %.3g > tol %.3g\n", got, want, fabs(got - want), tol);
}

void tc_open_device(struct dev *dev)
{
  enum clsph_status st = dev_open(-1, CLSPH_DOUBLE, dev);
  if (st == CLSPH_E_NODEVICE || st == CLSPH_E_NOFP64) {
    printf("skip: no usable OpenCL device (%s)\n", clsph_status_str(st));
    exit(TC_SKIP);
  }
  if (st != CLSPH_OK) {
    printf("FAIL: cannot open the OpenCL device (%s)\n", clsph_status_str(st));
    exit(1);
  }
  printf("device: %s (%s), precision %s\n", dev->name, dev->platform_name, CLSPH_PRECISION_NAME);
}

char *tc_read_text(const char *path)
{
  FILE *f = fopen(path, "rb");
  if (f == NULL) {
    printf("FAIL: cannot read %s\n", path);
    exit(1);
  }
  fseek(f, 0, SEEK_END);
  long size = ftell(f);
  rewind(f);
  char *text = malloc((size_t)size + 1);
  if (text == NULL || fread(text, 1, (size_t)size, f) != (size_t)size) {
    printf("FAIL: cannot read %s\n", path);
    exit(1);
  }
  text[size] = '\0';
  fclose(f);
  return text;
}

int tc_finish(const char *name)
{
  printf("%s: %d checks, %d failed\n", name, checks, failures);
  return failures == 0 ? 0 : 1;
}
