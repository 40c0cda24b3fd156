/* kern.h: kernel arguments set in signature order with every call checked, launches that name the
 * kernel when they fail, and per-kernel timing from profiling events. */
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

/** @brief Set all arguments of a kernel, in signature order. */
enum clsph_status kern_set(cl_kernel k, size_t nargs, const struct karg *args);
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
/** @brief Blocking copy host -> device. */
enum clsph_status kern_write(const struct dev *dev, cl_mem d, size_t bytes, const void *h);
/** @brief Fill a buffer with a repeated pattern (e.g. zero). */
enum clsph_status kern_fill(const struct dev *dev, cl_mem d, const void *pattern, size_t psize,
                            size_t bytes);
/** @brief Release a buffer and clear the handle. */
void kern_release(cl_mem *d);

#endif /* CLSPH_KERN_H */
