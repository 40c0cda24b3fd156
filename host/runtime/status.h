/* status.h: result codes of every fallible function, and the macros that propagate them. */
#ifndef CLSPH_STATUS_H
#define CLSPH_STATUS_H

#include "log.h"

enum clsph_status {
  CLSPH_OK = 0,
  CLSPH_E_NOMEM,
  CLSPH_E_IO,
  CLSPH_E_INPUT,
  CLSPH_E_CL,
  CLSPH_E_BUILD,
  CLSPH_E_NOFP64,
  CLSPH_E_UNSUPPORTED,
  CLSPH_E_NODEVICE,
  CLSPH_E_BLOWUP,      /* the run stopped: non-finite values, particles lost, time step collapsed */
  CLSPH_E_INTERRUPTED, /* SIGINT or SIGTERM: the run stopped after a step, with a checkpoint */
};

/** @brief Name of a status code, e.g. "CLSPH_E_CL". */
const char *clsph_status_str(enum clsph_status st);

/* Propagate a failure: log where, store it in the local `st`, jump to `done`. */
#define CLSPH_TRY(expr)                                                                            \
  do {                                                                                             \
    enum clsph_status try_st_ = (expr);                                                            \
    if (try_st_ != CLSPH_OK) {                                                                     \
      log_trace(__FILE__, __LINE__, __func__, clsph_status_str(try_st_));                          \
      st = try_st_;                                                                                \
      goto done;                                                                                   \
    }                                                                                              \
  } while (0)

/* An input error: always checked; the message says what is wrong and where. */
#define CLSPH_CHECK(cond, code, ...)                                                               \
  do {                                                                                             \
    if (!(cond)) {                                                                                 \
      log_error(__VA_ARGS__);                                                                      \
      st = (code);                                                                                 \
      goto done;                                                                                   \
    }                                                                                              \
  } while (0)

/* Internal invariant; disappears under NDEBUG. */
#ifdef NDEBUG
#define CLSPH_ASSERT(cond) ((void)0)
#else
#define CLSPH_ASSERT(cond)                                                                         \
  do {                                                                                             \
    if (!(cond)) log_fatal_assert(__FILE__, __LINE__, #cond);                                      \
  } while (0)
#endif

#endif /* CLSPH_STATUS_H */
