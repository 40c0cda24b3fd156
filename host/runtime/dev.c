/* dev.c: platform and device enumeration, device choice, context and queue. */
#include "dev.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "kern.h"

const char *dev_cl_error_str(cl_int err)
{
  switch (err) {
#define E(x)                                                                                       \
  case x:                                                                                          \
    return #x;
    E(CL_SUCCESS)
    E(CL_DEVICE_NOT_FOUND)
    E(CL_DEVICE_NOT_AVAILABLE)
    E(CL_COMPILER_NOT_AVAILABLE)
    E(CL_MEM_OBJECT_ALLOCATION_FAILURE)
    E(CL_OUT_OF_RESOURCES)
    E(CL_OUT_OF_HOST_MEMORY)
    E(CL_PROFILING_INFO_NOT_AVAILABLE)
    E(CL_MEM_COPY_OVERLAP)
    E(CL_IMAGE_FORMAT_MISMATCH)
    E(CL_IMAGE_FORMAT_NOT_SUPPORTED)
    E(CL_BUILD_PROGRAM_FAILURE)
    E(CL_MAP_FAILURE)
    E(CL_MISALIGNED_SUB_BUFFER_OFFSET)
    E(CL_EXEC_STATUS_ERROR_FOR_EVENTS_IN_WAIT_LIST)
    E(CL_COMPILE_PROGRAM_FAILURE)
    E(CL_LINKER_NOT_AVAILABLE)
    E(CL_LINK_PROGRAM_FAILURE)
    E(CL_DEVICE_PARTITION_FAILED)
    E(CL_KERNEL_ARG_INFO_NOT_AVAILABLE)
    E(CL_INVALID_VALUE)
    E(CL_INVALID_DEVICE_TYPE)
    E(CL_INVALID_PLATFORM)
    E(CL_INVALID_DEVICE)
    E(CL_INVALID_CONTEXT)
    E(CL_INVALID_QUEUE_PROPERTIES)
    E(CL_INVALID_COMMAND_QUEUE)
    E(CL_INVALID_HOST_PTR)
    E(CL_INVALID_MEM_OBJECT)
    E(CL_INVALID_IMAGE_FORMAT_DESCRIPTOR)
    E(CL_INVALID_IMAGE_SIZE)
    E(CL_INVALID_SAMPLER)
    E(CL_INVALID_BINARY)
    E(CL_INVALID_BUILD_OPTIONS)
    E(CL_INVALID_PROGRAM)
    E(CL_INVALID_PROGRAM_EXECUTABLE)
    E(CL_INVALID_KERNEL_NAME)
    E(CL_INVALID_KERNEL_DEFINITION)
    E(CL_INVALID_KERNEL)
    E(CL_INVALID_ARG_INDEX)
    E(CL_INVALID_ARG_VALUE)
    E(CL_INVALID_ARG_SIZE)
    E(CL_INVALID_KERNEL_ARGS)
    E(CL_INVALID_WORK_DIMENSION)
    E(CL_INVALID_WORK_GROUP_SIZE)
    E(CL_INVALID_WORK_ITEM_SIZE)
    E(CL_INVALID_GLOBAL_OFFSET)
    E(CL_INVALID_EVENT_WAIT_LIST)
    E(CL_INVALID_EVENT)
    E(CL_INVALID_OPERATION)
    E(CL_INVALID_GL_OBJECT)
    E(CL_INVALID_BUFFER_SIZE)
    E(CL_INVALID_MIP_LEVEL)
    E(CL_INVALID_GLOBAL_WORK_SIZE)
    E(CL_INVALID_PROPERTY)
    E(CL_INVALID_IMAGE_DESCRIPTOR)
    E(CL_INVALID_COMPILER_OPTIONS)
    E(CL_INVALID_LINKER_OPTIONS)
    E(CL_INVALID_DEVICE_PARTITION_COUNT)
#undef E
  case -1001:
    return "CL_PLATFORM_NOT_FOUND_KHR";
  default:
    return "CL_UNKNOWN_ERROR";
  }
}

/* Every device of every platform, flattened in platform order: the `clsph devices` index. */
struct dev_entry {
  cl_platform_id platform;
  cl_device_id id;
};

static enum clsph_status enumerate(struct dev_entry **out, int *count)
{
  enum clsph_status st = CLSPH_OK;
  cl_platform_id *plats = NULL;
  cl_device_id *ids = NULL;
  struct dev_entry *list = NULL;
  cl_uint nplat = 0;
  int n = 0;

  cl_int err = clGetPlatformIDs(0, NULL, &nplat);
  if (err == -1001 /* CL_PLATFORM_NOT_FOUND_KHR */ || nplat == 0) {
    *out = NULL;
    *count = 0;
    goto done;
  }
  CLSPH_CL_CHECK_ERR(err, "clGetPlatformIDs");
  plats = malloc(nplat * sizeof *plats);
  CLSPH_CHECK(plats != NULL, CLSPH_E_NOMEM, "out of memory listing OpenCL platforms");
  CLSPH_CL_TRY(clGetPlatformIDs(nplat, plats, NULL));
  for (cl_uint p = 0; p < nplat; ++p) {
    cl_uint nd = 0;
    err = clGetDeviceIDs(plats[p], CL_DEVICE_TYPE_ALL, 0, NULL, &nd);
    if (err == CL_DEVICE_NOT_FOUND || nd == 0) continue;
    CLSPH_CL_CHECK_ERR(err, "clGetDeviceIDs");
    struct dev_entry *grown = realloc(list, (size_t)(n + (int)nd) * sizeof *list);
    CLSPH_CHECK(grown != NULL, CLSPH_E_NOMEM, "out of memory listing OpenCL devices");
    list = grown;
    free(ids);
    ids = malloc(nd * sizeof *ids);
    CLSPH_CHECK(ids != NULL, CLSPH_E_NOMEM, "out of memory listing OpenCL devices");
    CLSPH_CL_TRY(clGetDeviceIDs(plats[p], CL_DEVICE_TYPE_ALL, nd, ids, NULL));
    for (cl_uint d = 0; d < nd; ++d) {
      list[n].platform = plats[p];
      list[n].id = ids[d];
      ++n;
    }
  }
  *out = list;
  *count = n;
  list = NULL;
done:
  free(list);
  free(ids);
  free(plats);
  return st;
}

static enum clsph_status describe(const struct dev_entry *e, struct dev *d)
{
  enum clsph_status st = CLSPH_OK;
  cl_device_fp_config fp = 0;

  d->platform = e->platform;
  d->id = e->id;
  CLSPH_CL_TRY(clGetPlatformInfo(e->platform, CL_PLATFORM_NAME, sizeof d->platform_name,
                                 d->platform_name, NULL));
  CLSPH_CL_TRY(clGetDeviceInfo(e->id, CL_DEVICE_NAME, sizeof d->name, d->name, NULL));
  CLSPH_CL_TRY(clGetDeviceInfo(e->id, CL_DEVICE_VERSION, sizeof d->version, d->version, NULL));
  CLSPH_CL_TRY(clGetDeviceInfo(e->id, CL_DRIVER_VERSION, sizeof d->driver, d->driver, NULL));
  CLSPH_CL_TRY(clGetDeviceInfo(e->id, CL_DEVICE_TYPE, sizeof d->type, &d->type, NULL));
  CLSPH_CL_TRY(clGetDeviceInfo(e->id, CL_DEVICE_DOUBLE_FP_CONFIG, sizeof fp, &fp, NULL));
  CLSPH_CL_TRY(
      clGetDeviceInfo(e->id, CL_DEVICE_MAX_WORK_GROUP_SIZE, sizeof d->max_wg, &d->max_wg, NULL));
  CLSPH_CL_TRY(clGetDeviceInfo(e->id, CL_DEVICE_NATIVE_VECTOR_WIDTH_DOUBLE, sizeof d->native_double,
                               &d->native_double, NULL));
  CLSPH_CL_TRY(clGetDeviceInfo(e->id, CL_DEVICE_GLOBAL_MEM_SIZE, sizeof d->global_mem,
                               &d->global_mem, NULL));
  CLSPH_CL_TRY(clGetDeviceInfo(e->id, CL_DEVICE_MAX_MEM_ALLOC_SIZE, sizeof d->max_alloc,
                               &d->max_alloc, NULL));
  d->mem_limit = d->global_mem;
  d->fp64 = fp != 0;
  d->wg = d->max_wg < 64 ? d->max_wg : 64;
done:
  return st;
}

static const char *type_str(cl_device_type t)
{
  if (t & CL_DEVICE_TYPE_GPU) return "GPU";
  if (t & CL_DEVICE_TYPE_CPU) return "CPU";
  if (t & CL_DEVICE_TYPE_ACCELERATOR) return "accelerator";
  return "other";
}

static void no_device_message(void)
{
  log_error("no OpenCL device found: install an OpenCL driver, for the CPU "
            "'apt-get install pocl-opencl-icd'");
}

enum clsph_status dev_list(void)
{
  enum clsph_status st = CLSPH_OK;
  struct dev_entry *list = NULL;
  int n = 0;

  CLSPH_TRY(enumerate(&list, &n));
  if (n == 0) {
    no_device_message();
    st = CLSPH_E_NODEVICE;
    goto done;
  }
  printf("%-3s %-5s %-40s %-28s %-22s %10s %5s\n", "#", "type", "device", "platform", "OpenCL",
         "memory", "fp64");
  for (int i = 0; i < n; ++i) {
    struct dev d = {0};
    CLSPH_TRY(describe(&list[i], &d));
    printf("%-3d %-5s %-40.40s %-28.28s %-22.22s %6.1f GiB %5s\n", i, type_str(d.type), d.name,
           d.platform_name, d.version, (double)d.global_mem / (1024.0 * 1024.0 * 1024.0),
           d.fp64 ? "yes" : "no");
  }
done:
  free(list);
  return st;
}

/* Parse a device index from text (the option or the environment variable). */
static enum clsph_status parse_index(const char *text, const char *where, int *out)
{
  enum clsph_status st = CLSPH_OK;
  char *end = NULL;
  errno = 0;
  long v = strtol(text, &end, 10);
  CLSPH_CHECK(errno == 0 && end != text && *end == '\0' && v >= 0 && v < 1000000, CLSPH_E_INPUT,
              "%s: '%s' is not a device index (a number from `clsph devices`)", where, text);
  *out = (int)v;
done:
  return st;
}

enum clsph_status dev_open(int index, int need_fp64, struct dev *out)
{
  enum clsph_status st = CLSPH_OK;
  struct dev_entry *list = NULL;
  struct dev d = {0};
  int n = 0;
  cl_int err = CL_SUCCESS;
  const char *where = "--device";

  CLSPH_TRY(enumerate(&list, &n));
  if (n == 0) {
    no_device_message();
    st = CLSPH_E_NODEVICE;
    goto done;
  }
  if (index < 0) {
    const char *env = getenv("CLSPH_DEVICE");
    if (env != NULL && env[0] != '\0') {
      where = "CLSPH_DEVICE";
      CLSPH_TRY(parse_index(env, "environment variable CLSPH_DEVICE", &index));
    }
  }
  if (index < 0) { /* default: the first GPU, else the first CPU, else the first device */
    int cpu = -1;
    for (int i = 0; i < n && index < 0; ++i) {
      cl_device_type t = 0;
      CLSPH_CL_TRY(clGetDeviceInfo(list[i].id, CL_DEVICE_TYPE, sizeof t, &t, NULL));
      if (t & CL_DEVICE_TYPE_GPU) index = i;
      if ((t & CL_DEVICE_TYPE_CPU) && cpu < 0) cpu = i;
    }
    if (index < 0) index = cpu >= 0 ? cpu : 0;
  }
  CLSPH_CHECK(index < n, CLSPH_E_INPUT,
              "%s: device %d does not exist; there %s %d device%s (0 to %d), `clsph devices` lists "
              "them",
              where, index, n == 1 ? "is" : "are", n, n == 1 ? "" : "s", n - 1);
  CLSPH_TRY(describe(&list[index], &d));
  d.index = index;
  CLSPH_CHECK(!need_fp64 || d.fp64, CLSPH_E_NOFP64,
              "device %d (%s) has no double precision (cl_khr_fp64); use a float build "
              "(cmake -DCLSPH_REAL=float) or another device",
              index, d.name);
  cl_context_properties props[] = {CL_CONTEXT_PLATFORM, (cl_context_properties)d.platform, 0};
  d.ctx = clCreateContext(props, 1, &d.id, NULL, NULL, &err);
  CLSPH_CL_CHECK_ERR(err, "clCreateContext");
  d.queue = clCreateCommandQueue(d.ctx, d.id, CL_QUEUE_PROFILING_ENABLE, &err);
  CLSPH_CL_CHECK_ERR(err, "clCreateCommandQueue");
  *out = d;
  d.ctx = NULL;
  d.queue = NULL;
done:
  dev_close(&d);
  free(list);
  return st;
}

void dev_close(struct dev *dev)
{
  kern_profile_free(&dev->profile);
  /* what was enqueued runs to its end first: a run that stops early (a refused restart, a
   * blow-up) would otherwise exit while PoCL's threads still compile or run its kernels, which
   * crashed the process at exit */
  if (dev->queue != NULL && clFinish(dev->queue) != CL_SUCCESS)
    log_warn("clFinish at exit failed: the device may have been lost");
  if (dev->queue != NULL) clReleaseCommandQueue(dev->queue);
  if (dev->ctx != NULL) clReleaseContext(dev->ctx);
  dev->queue = NULL;
  dev->ctx = NULL;
}

real2 dev_real2(double x, double y)
{
  real2 v;
  v.s[0] = (real)x;
  v.s[1] = (real)y;
  return v;
}

struct realv_arg dev_realv(int dim, const double *x)
{
  struct realv_arg a;
  memset(&a, 0, sizeof a);
  for (int k = 0; k < dim && k < 3; ++k) a.v.s[k] = (real)x[k];
  a.size = dim == 3 ? sizeof(real4) : sizeof(real2);
  return a;
}
