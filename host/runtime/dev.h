/* dev.h: OpenCL platform and device choice, context and queue, and checked OpenCL calls. */
#ifndef CLSPH_DEV_H
#define CLSPH_DEV_H

#define CL_TARGET_OPENCL_VERSION 120
#include <CL/cl.h>
#include <stddef.h>

#include "clsph_config.h"
#include "status.h"

struct kern_profile; /* kern.h */

/* Host views of the device real2 and real4 (aligned like the device types). */
#if CLSPH_DOUBLE
typedef cl_double2 real2;
typedef cl_double4 real4;
#else
typedef cl_float2 real2;
typedef cl_float4 real4;
#endif

/** @brief A real2 kernel argument from two doubles. */
real2 dev_real2(double x, double y);

/** A vector kernel argument of the program's DIM (the kernels' realv): real2 in 2-D, real4
 *  (x, y, z, 0) in 3-D; pass it with KARGV (kern.h). */
struct realv_arg {
  real4 v;
  size_t size;
};
/** @brief The realv argument of the first `dim` (2 or 3) components of x. */
struct realv_arg dev_realv(int dim, const double *x);

/** An open device: the context and the in-order queue every launch goes through. */
struct dev {
  cl_platform_id platform;
  cl_device_id id;
  cl_context ctx;
  cl_command_queue queue;       /* in order, with profiling enabled */
  int index;                    /* index in the `clsph devices` list */
  char name[256];               /* device name */
  char platform_name[256];      /* platform name */
  char version[256];            /* device OpenCL version string */
  char driver[256];             /* driver version */
  cl_device_type type;          /* CL_DEVICE_TYPE_GPU, _CPU, ... */
  int fp64;                     /* 1 when cl_khr_fp64 is usable */
  cl_uint native_double;        /* CL_DEVICE_NATIVE_VECTOR_WIDTH_DOUBLE (8 on AVX-512) */
  size_t max_wg;                /* largest work-group size */
  size_t wg;                    /* work-group size used for 1-D launches */
  cl_ulong global_mem;          /* bytes */
  cl_ulong max_alloc;           /* the largest buffer it allocates, bytes */
  cl_ulong mem_limit;           /* the most a run may use: global_mem, or less (--device-memory) */
  struct kern_profile *profile; /* device time per kernel (--profile, kern.h); NULL: off */
};

/** @brief Symbolic name of an OpenCL error code, e.g. "CL_OUT_OF_RESOURCES". */
const char *dev_cl_error_str(cl_int err);

/* A failing OpenCL call becomes CLSPH_E_CL, logged once with the call and its error name. */
#define CLSPH_CL_TRY(call)                                                                         \
  do {                                                                                             \
    cl_int cl_err_ = (call);                                                                       \
    if (cl_err_ != CL_SUCCESS) {                                                                   \
      log_error("%s: %s (%s:%d)", #call, dev_cl_error_str(cl_err_), __FILE__, __LINE__);           \
      st = CLSPH_E_CL;                                                                             \
      goto done;                                                                                   \
    }                                                                                              \
  } while (0)

/* For calls that return an object and set errcode_ret: name the call in the message. */
#define CLSPH_CL_CHECK_ERR(err, what)                                                              \
  do {                                                                                             \
    if ((err) != CL_SUCCESS) {                                                                     \
      log_error("%s: %s (%s:%d)", what, dev_cl_error_str(err), __FILE__, __LINE__);                \
      st = CLSPH_E_CL;                                                                             \
      goto done;                                                                                   \
    }                                                                                              \
  } while (0)

/** @brief Print every platform and device with its OpenCL version, memory and fp64 support.
 *  @return CLSPH_E_NODEVICE when there is none. */
enum clsph_status dev_list(void);

/** @brief Open a device.
 *  @param index  index from `clsph devices`, or -1 for $CLSPH_DEVICE, else the first GPU, else
 *                the first CPU device.
 *  @param need_fp64 stop with CLSPH_E_NOFP64 when the device has no double precision.
 *  @param out    filled on success; release with dev_close(). */
enum clsph_status dev_open(int index, int need_fp64, struct dev *out);

/** @brief Release the profile, the queue and the context. Safe on a zeroed struct. */
void dev_close(struct dev *dev);

#endif /* CLSPH_DEV_H */
