/* log.c: levelled messages on stderr. */
#include "log.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

static enum log_level current = LOG_INFO;

void log_set_level(enum log_level level)
{
  current = level;
}

enum log_level log_get_level(void)
{
  return current;
}

static void vlog(enum log_level level, const char *prefix, const char *fmt, va_list ap)
{
  if (level > current) return;
  fputs(prefix, stderr);
  vfprintf(stderr, fmt, ap);
  fputc('\n', stderr);
}

#define LOG_DEFINE(fn, level, prefix)                                                              \
  void fn(const char *fmt, ...)                                                                    \
  {                                                                                                \
    va_list ap;                                                                                    \
    va_start(ap, fmt);                                                                             \
    vlog(level, prefix, fmt, ap);                                                                  \
    va_end(ap);                                                                                    \
  }

LOG_DEFINE(log_error, LOG_ERROR, "clsph: error: ")
LOG_DEFINE(log_warn, LOG_WARN, "clsph: warning: ")
LOG_DEFINE(log_info, LOG_INFO, "")
LOG_DEFINE(log_debug, LOG_DEBUG, "clsph: debug: ")

void log_trace(const char *file, int line, const char *func, const char *what)
{
  if (current >= LOG_DEBUG)
    fprintf(stderr, "clsph: debug: %s:%d: %s: %s\n", file, line, func, what);
}

void log_fatal_assert(const char *file, int line, const char *cond)
{
  fprintf(stderr, "clsph: internal error: %s:%d: assertion '%s' failed\n", file, line, cond);
  abort();
}
