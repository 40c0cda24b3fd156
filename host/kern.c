/* kern.c: checked kernel arguments, launches and buffer transfers. */
#include "kern.h"

#include <stdio.h>

static const char *kernel_name(cl_kernel k, char *buf, size_t size)
{
  if (clGetKernelInfo(k, CL_KERNEL_FUNCTION_NAME, size, buf, NULL) != CL_SUCCESS)
    snprintf(buf, size, "?");
  return buf;
}

enum clsph_status kern_set(cl_kernel k, size_t nargs, const struct karg *args)
{
  enum clsph_status st = CLSPH_OK;
  char name[128];
  for (size_t i = 0; i < nargs; ++i) {
    cl_int err = clSetKernelArg(k, (cl_uint)i, args[i].size, args[i].ptr);
    if (err != CL_SUCCESS) {
      log_error("clSetKernelArg(%s, argument %zu): %s", kernel_name(k, name, sizeof name), i,
                dev_cl_error_str(err));
      st = CLSPH_E_CL;
      goto done;
    }
  }
done:
  return st;
}

enum clsph_status kern_set_at(cl_kernel k, cl_uint index, struct karg a)
{
  enum clsph_status st = CLSPH_OK;
  char name[128];
  cl_int err = clSetKernelArg(k, index, a.size, a.ptr);
  if (err != CL_SUCCESS) {
    log_error("clSetKernelArg(%s, argument %u): %s", kernel_name(k, name, sizeof name), index,
              dev_cl_error_str(err));
    st = CLSPH_E_CL;
  }
  return st;
}

enum clsph_status kern_launch_wg(const struct dev *dev, cl_kernel k, size_t n, size_t wg,
                                 struct kern_timer *timer)
{
  enum clsph_status st = CLSPH_OK;
  cl_event ev = NULL;
  char name[128];
  size_t global = (n + wg - 1) / wg * wg;
  if (global == 0) goto done;
  int timed = timer != NULL && timer->on;
  cl_int err =
      clEnqueueNDRangeKernel(dev->queue, k, 1, NULL, &global, &wg, 0, NULL, timed ? &ev : NULL);
  if (err != CL_SUCCESS) {
    log_error("clEnqueueNDRangeKernel(%s): %s", kernel_name(k, name, sizeof name),
              dev_cl_error_str(err));
    st = CLSPH_E_CL;
    goto done;
  }
  if (timed) {
    cl_ulong t0 = 0, t1 = 0;
    CLSPH_CL_TRY(clWaitForEvents(1, &ev));
    CLSPH_CL_TRY(clGetEventProfilingInfo(ev, CL_PROFILING_COMMAND_START, sizeof t0, &t0, NULL));
    CLSPH_CL_TRY(clGetEventProfilingInfo(ev, CL_PROFILING_COMMAND_END, sizeof t1, &t1, NULL));
    timer->seconds += (double)(t1 - t0) * 1e-9;
    timer->launches += 1;
  }
done:
  if (ev != NULL) clReleaseEvent(ev);
  return st;
}

enum clsph_status kern_launch(const struct dev *dev, cl_kernel k, size_t n,
                              struct kern_timer *timer)
{
  return kern_launch_wg(dev, k, n, dev->wg, timer);
}

enum clsph_status kern_finish(const struct dev *dev)
{
  enum clsph_status st = CLSPH_OK;
  CLSPH_CL_TRY(clFinish(dev->queue));
done:
  return st;
}

enum clsph_status kern_buffer(const struct dev *dev, size_t bytes, const void *init, cl_mem *out,
                              const char *name)
{
  enum clsph_status st = CLSPH_OK;
  cl_int err = CL_SUCCESS;
  cl_mem_flags flags = CL_MEM_READ_WRITE | (init != NULL ? CL_MEM_COPY_HOST_PTR : 0);
  cl_mem d = clCreateBuffer(dev->ctx, flags, bytes > 0 ? bytes : 1, (void *)(size_t)init, &err);
  if (err != CL_SUCCESS) {
    log_error("clCreateBuffer(%s, %zu bytes): %s", name, bytes, dev_cl_error_str(err));
    st = CLSPH_E_CL;
    goto done;
  }
  *out = d;
done:
  return st;
}

enum clsph_status kern_read(const struct dev *dev, cl_mem d, size_t bytes, void *h)
{
  enum clsph_status st = CLSPH_OK;
  if (bytes == 0) goto done;
  CLSPH_CL_TRY(clEnqueueReadBuffer(dev->queue, d, CL_TRUE, 0, bytes, h, 0, NULL, NULL));
done:
  return st;
}

enum clsph_status kern_write(const struct dev *dev, cl_mem d, size_t bytes, const void *h)
{
  enum clsph_status st = CLSPH_OK;
  if (bytes == 0) goto done;
  CLSPH_CL_TRY(clEnqueueWriteBuffer(dev->queue, d, CL_TRUE, 0, bytes, h, 0, NULL, NULL));
done:
  return st;
}

enum clsph_status kern_fill(const struct dev *dev, cl_mem d, const void *pattern, size_t psize,
                            size_t bytes)
{
  enum clsph_status st = CLSPH_OK;
  if (bytes == 0) goto done;
  CLSPH_CL_TRY(clEnqueueFillBuffer(dev->queue, d, pattern, psize, 0, bytes, 0, NULL, NULL));
done:
  return st;
}

void kern_release(cl_mem *d)
{
  if (*d != NULL) clReleaseMemObject(*d);
  *d = NULL;
}
