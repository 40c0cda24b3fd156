/* kern.h: kernel arguments set in signature order with every call checked, launches that name the
 * kernel when they fail, and per-kernel timing from profiling events: one timer a caller passes
 * (kern_timer), or the profile of every launch and transfer on a device (kern_profile, --profile).
 */
#ifndef CLSPH_KERN_H
#define CLSPH_KERN_H

#include "dev.h"

/** One kernel argument: its size and address (address NULL: local memory of that size). */
struct karg {
  size_t size;
  const void *ptr;
};
#define KARG(x)           ((struct karg){sizeof(x), &(x)})
#define KARG_LOCAL(bytes) ((struct karg){(bytes), NULL})
#define KARGV(a)          ((struct karg){(a).size, &(a).v}) /* a struct realv_arg */

/** @brief Set all arguments of a kernel, in signature order. */
enum clsph_status kern_set(cl_kernel k, size_t nargs, const struct karg *args);
/** @brief Set arguments first .. first + nargs − 1 (after those another call set). */
enum clsph_status kern_set_from(cl_kernel k, cl_uint first, size_t nargs, const struct karg *args);
#define KERN_SET_AT(k, first, ...)                                                                 \
  kern_set_from((k), (first), sizeof((struct karg[]){__VA_ARGS__}) / sizeof(struct karg),          \
                (struct karg[]){__VA_ARGS__})
/** @brief Set one argument (for kernels whose arguments are set in several steps). */
enum clsph_status kern_set_at(cl_kernel k, cl_uint index, struct karg a);
#define KERN_SET(k, ...)                                                                           \
  kern_set((k), sizeof((struct karg[]){__VA_ARGS__}) / sizeof(struct karg),                        \
           (struct karg[]){__VA_ARGS__})

/** Accumulated device time of one kernel (from profiling events), for benchmarks and --profile. */
struct kern_timer {
  int on;         /* record events when set */
  double seconds; /* accumulated device time */
  long launches;  /* launches recorded */
};

/** The device time of every launch and transfer on one device, by kernel function name, while it
 *  is on (struct dev's `profile`; NULL there costs one branch per launch and nothing else). Each
 *  command records an event; events are waited for in batches (after each blocking transfer,
 *  every 1024 commands, at kern_profile_stop) and add CL_PROFILING_COMMAND_END − START to the row
 *  of their kernel's function name. The transfers of kern_read/kern_write/kern_fill/kern_copy are
 *  the rows "(read)", "(write)", "(fill)" and "(copy)". The table grows with the names it meets.
 */
struct kern_profile;

/** One row of a profile. */
struct kern_profile_entry {
  const char *name; /* kernel function name, or "(read)", "(write)", "(fill)", "(copy)" */
  long launches;    /* commands recorded */
  double seconds;   /* their summed device time, s */
};

/** @brief Attach an empty profile, switched off, to a device (released by dev_close). */
enum clsph_status kern_profile_create(struct dev *dev);
/** @brief Forget what was recorded and switch recording on (no-op for NULL). */
void kern_profile_start(struct kern_profile *p);
/** @brief Switch recording off and wait for the commands recorded (no-op for NULL). */
enum clsph_status kern_profile_stop(struct kern_profile *p);
/** @brief The recorded rows, by decreasing time (ties by name), and their summed device time.
 *  @param out a new array of *n rows (free() it; the names belong to the profile). */
enum clsph_status kern_profile_entries(struct kern_profile *p, struct kern_profile_entry **out,
                                       size_t *n, double *device_seconds);
/** @brief Release a profile and clear the handle (safe on NULL). */
void kern_profile_free(struct kern_profile **p);

/** @brief Launch a 1-D kernel over n items, the global size rounded up to a multiple of dev->wg.
 *  A failure is logged as "clEnqueueNDRangeKernel(name): CL_...".
 *  @param timer NULL, or a timer that gets the launch's device time (this waits for it). */
enum clsph_status kern_launch(const struct dev *dev, cl_kernel k, size_t n,
                              struct kern_timer *timer);

/** @brief Launch with an explicit work-group size (global size rounded up to a multiple of it). */
enum clsph_status kern_launch_wg(const struct dev *dev, cl_kernel k, size_t n, size_t wg,
                                 struct kern_timer *timer);

/** @brief Wait for the queue; a failure names it. */
enum clsph_status kern_finish(const struct dev *dev);

/** @brief Create a device buffer of `bytes` (at least 1), optionally initialised from host. */
enum clsph_status kern_buffer(const struct dev *dev, size_t bytes, const void *init, cl_mem *out,
                              const char *name);
/** @brief Blocking copy device -> host. */
enum clsph_status kern_read(const struct dev *dev, cl_mem d, size_t bytes, void *h);
/** @brief Blocking copy device -> host of `bytes` from byte `offset` of the buffer. */
enum clsph_status kern_read_at(const struct dev *dev, cl_mem d, size_t offset, size_t bytes,
                               void *h);
/** @brief Non-blocking copy device -> host: h holds the data once a later blocking transfer or
 *  kern_finish has returned (the queue is in order). Several of them and one blocking read make
 *  one wait for the host instead of several. */
enum clsph_status kern_read_nb(const struct dev *dev, cl_mem d, size_t offset, size_t bytes,
                               void *h);
/** @brief Blocking copy host -> device. */
enum clsph_status kern_write(const struct dev *dev, cl_mem d, size_t bytes, const void *h);
/** @brief Blocking copy host -> device of `bytes` to byte `offset` of the buffer. */
enum clsph_status kern_write_at(const struct dev *dev, cl_mem d, size_t offset, size_t bytes,
                                const void *h);
/** @brief Non-blocking copy host -> device: h must stay as it is until a later blocking transfer
 *  or kern_finish has returned. */
enum clsph_status kern_write_nb(const struct dev *dev, cl_mem d, size_t bytes, const void *h);
/** @brief Fill a buffer with a repeated pattern (e.g. zero). */
enum clsph_status kern_fill(const struct dev *dev, cl_mem d, const void *pattern, size_t psize,
                            size_t bytes);
/** @brief Copy `bytes` from the start of one buffer to the start of another, on the device. */
enum clsph_status kern_copy(const struct dev *dev, cl_mem dst, cl_mem src, size_t bytes);
/** @brief Release a buffer and clear the handle. */
void kern_release(cl_mem *d);
/** @brief Device memory in buffers made by kern_buffer and not released yet, bytes. */
size_t kern_allocated(void);
/** @brief Device memory that modules have announced they will allocate at their first use (the
 *  pressure solver's stored operator), bytes: `bytes` is added (negative: taken back). */
void kern_reserve(double bytes);
/** @brief The sum of what kern_reserve announced, bytes. */
size_t kern_reserved(void);

#endif /* CLSPH_KERN_H */
