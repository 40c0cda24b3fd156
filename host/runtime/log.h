/* log.h: the only way library code prints. Messages go to stderr, prefixed by their level. */
#ifndef CLSPH_LOG_H
#define CLSPH_LOG_H

enum log_level { LOG_ERROR = 0, LOG_WARN, LOG_INFO, LOG_DEBUG };

/** @brief Set the most verbose level printed (default LOG_INFO). */
void log_set_level(enum log_level level);
/** @brief Current level. */
enum log_level log_get_level(void);

#if defined(__GNUC__)
#define LOG_PRINTF(a, b) __attribute__((format(printf, a, b)))
#else
#define LOG_PRINTF(a, b)
#endif

void log_error(const char *fmt, ...) LOG_PRINTF(1, 2);
void log_warn(const char *fmt, ...) LOG_PRINTF(1, 2);
void log_info(const char *fmt, ...) LOG_PRINTF(1, 2);
void log_debug(const char *fmt, ...) LOG_PRINTF(1, 2);
/** @brief Where a failure passed through (printed at debug level only: the error itself was
 *  already reported once where it happened). */
void log_trace(const char *file, int line, const char *func, const char *what);
/** @brief A broken internal invariant: prints and aborts. */
void log_fatal_assert(const char *file, int line, const char *cond);

#endif /* CLSPH_LOG_H */
