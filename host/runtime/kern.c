/* kern.c: checked kernel arguments, launches and buffer transfers, and the device profile. */
#include "kern.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *kernel_name(cl_kernel k, char *buf, size_t size)
{
  if (clGetKernelInfo(k, CL_KERNEL_FUNCTION_NAME, size, buf, NULL) != CL_SUCCESS)
    snprintf(buf, size, "?");
  return buf;
}

enum clsph_status kern_set(cl_kernel k, size_t nargs, const struct karg *args)
{
  return kern_set_from(k, 0, nargs, args);
}

enum clsph_status kern_set_from(cl_kernel k, cl_uint first, size_t nargs, const struct karg *args)
{
  enum clsph_status st = CLSPH_OK;
  char name[128];
  /* no more than the kernel takes (fewer: kern_set_at sets the rest): PoCL crashes on an argument
   * index past the kernel's instead of returning CL_INVALID_ARG_INDEX */
  cl_uint have = 0;
  cl_int err = clGetKernelInfo(k, CL_KERNEL_NUM_ARGS, sizeof have, &have, NULL);
  if (err != CL_SUCCESS || first + nargs > have) {
    if (err != CL_SUCCESS)
      log_error("clGetKernelInfo(CL_KERNEL_NUM_ARGS): %s", dev_cl_error_str(err));
    else
      log_error("kernel %s takes %u arguments, the host passes %zu",
                kernel_name(k, name, sizeof name), have, first + nargs);
    st = CLSPH_E_CL;
    goto done;
  }
  for (size_t i = 0; i < nargs; ++i) {
    err = clSetKernelArg(k, first + (cl_uint)i, args[i].size, args[i].ptr);
    if (err != CL_SUCCESS) {
      log_error("clSetKernelArg(%s, argument %zu): %s", kernel_name(k, name, sizeof name),
                first + i, dev_cl_error_str(err));
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

/* ---- profile ----
 * Waiting for each command as it is enqueued adds a host round trip per launch (tens of µs with
 * PoCL: it doubled the wall time of a 40² cavity run, where every BiCGStab iteration is a dozen
 * launches) and would inflate the "host and waiting" time the profile reports. A recorded event
 * is kept instead and resolved in batches: after each blocking transfer (by then the in-order
 * queue has run everything before it; the reductions read back many times per step), every
 * PROFILE_BATCH commands, and when the profile stops. */

#define PROFILE_BATCH 1024 /* events kept before they are waited for and resolved */

/* One row of the table: a kernel function name or a kind of transfer. */
struct profile_row {
  char *name;
  long launches;
  double seconds; /* s */
};

/* A kernel object met before, retained while cached so that its handle names no other kernel. */
struct profile_kernel {
  cl_kernel k;
  size_t row; /* its row in rows */
};

struct kern_profile {
  int on;                            /* record while set */
  struct profile_row *rows;          /* one per name, in the order met */
  size_t nrows, cap_rows;            /* rows used and allocated */
  struct profile_kernel *kernels;    /* kernel object -> row, so a name is asked for once */
  size_t nkernels, cap_kernels;      /* entries used and allocated */
  size_t last;                       /* index in kernels of the last kernel looked up */
  cl_event pending[PROFILE_BATCH];   /* recorded commands not yet resolved, in queue order */
  size_t pending_row[PROFILE_BATCH]; /* their rows */
  size_t npending;
};

enum clsph_status kern_profile_create(struct dev *dev)
{
  enum clsph_status st = CLSPH_OK;
  struct kern_profile *p = calloc(1, sizeof *p);
  CLSPH_CHECK(p != NULL, CLSPH_E_NOMEM, "out of memory for the profile");
  kern_profile_free(&dev->profile);
  dev->profile = p;
done:
  return st;
}

/* Forget the recorded commands not yet resolved. */
static void profile_drop_pending(struct kern_profile *p)
{
  for (size_t i = 0; i < p->npending; ++i) clReleaseEvent(p->pending[i]);
  p->npending = 0;
}

/* Device time of a finished command: CL_PROFILING_COMMAND_END − START. */
static enum clsph_status event_seconds(cl_event ev, double *seconds)
{
  enum clsph_status st = CLSPH_OK;
  cl_ulong t0 = 0, t1 = 0;
  CLSPH_CL_TRY(clGetEventProfilingInfo(ev, CL_PROFILING_COMMAND_START, sizeof t0, &t0, NULL));
  CLSPH_CL_TRY(clGetEventProfilingInfo(ev, CL_PROFILING_COMMAND_END, sizeof t1, &t1, NULL));
  *seconds = t1 > t0 ? (double)(t1 - t0) * 1e-9 : 0.0;
done:
  return st;
}

/* Wait for the recorded commands and add their device times to their rows. */
static enum clsph_status profile_flush(struct kern_profile *p)
{
  enum clsph_status st = CLSPH_OK;
  if (p->npending == 0) goto done;
  CLSPH_CL_TRY(clWaitForEvents((cl_uint)p->npending, p->pending));
  for (size_t i = 0; i < p->npending; ++i) {
    double s = 0.0;
    CLSPH_TRY(event_seconds(p->pending[i], &s));
    p->rows[p->pending_row[i]].launches += 1;
    p->rows[p->pending_row[i]].seconds += s;
  }
done:
  profile_drop_pending(p);
  return st;
}

void kern_profile_start(struct kern_profile *p)
{
  if (p == NULL) return;
  profile_drop_pending(p);
  for (size_t i = 0; i < p->nrows; ++i) {
    p->rows[i].launches = 0;
    p->rows[i].seconds = 0.0;
  }
  p->on = 1;
}

enum clsph_status kern_profile_stop(struct kern_profile *p)
{
  enum clsph_status st = CLSPH_OK;
  if (p == NULL) goto done;
  p->on = 0;
  CLSPH_TRY(profile_flush(p));
done:
  return st;
}

/* Slowest first; equal times by name, so the order is reproducible. */
static int by_time(const void *a, const void *b)
{
  const struct kern_profile_entry *x = a, *y = b;
  if (x->seconds != y->seconds) return x->seconds < y->seconds ? 1 : -1;
  return strcmp(x->name, y->name);
}

enum clsph_status kern_profile_entries(struct kern_profile *p, struct kern_profile_entry **out,
                                       size_t *n, double *device_seconds)
{
  enum clsph_status st = CLSPH_OK;
  struct kern_profile_entry *e = NULL;
  size_t m = 0;
  double sum = 0.0;
  CLSPH_TRY(profile_flush(p));
  e = malloc((p->nrows > 0 ? p->nrows : 1) * sizeof *e);
  CLSPH_CHECK(e != NULL, CLSPH_E_NOMEM, "out of memory for the profile");
  for (size_t i = 0; i < p->nrows; ++i) {
    if (p->rows[i].launches == 0) continue; /* met before the last kern_profile_start only */
    e[m].name = p->rows[i].name;
    e[m].launches = p->rows[i].launches;
    e[m].seconds = p->rows[i].seconds;
    sum += e[m].seconds;
    ++m;
  }
  qsort(e, m, sizeof *e, by_time);
  *out = e;
  *n = m;
  *device_seconds = sum;
  e = NULL;
done:
  free(e);
  return st;
}

void kern_profile_free(struct kern_profile **p)
{
  struct kern_profile *q = *p;
  if (q == NULL) return;
  profile_drop_pending(q);
  for (size_t i = 0; i < q->nkernels; ++i) clReleaseKernel(q->kernels[i].k);
  for (size_t i = 0; i < q->nrows; ++i) free(q->rows[i].name);
  free(q->kernels);
  free(q->rows);
  free(q);
  *p = NULL;
}

/* The row of a name, appended when new. */
static enum clsph_status profile_row(struct kern_profile *p, const char *name, size_t *row)
{
  enum clsph_status st = CLSPH_OK;
  char *copy = NULL;
  for (size_t i = 0; i < p->nrows; ++i) {
    if (strcmp(p->rows[i].name, name) == 0) {
      *row = i;
      goto done;
    }
  }
  if (p->nrows == p->cap_rows) {
    size_t cap = p->cap_rows > 0 ? 2 * p->cap_rows : 32;
    struct profile_row *grown = realloc(p->rows, cap * sizeof *grown);
    CLSPH_CHECK(grown != NULL, CLSPH_E_NOMEM, "out of memory for the profile");
    p->rows = grown;
    p->cap_rows = cap;
  }
  size_t len = strlen(name);
  copy = malloc(len + 1);
  CLSPH_CHECK(copy != NULL, CLSPH_E_NOMEM, "out of memory for the profile");
  memcpy(copy, name, len + 1);
  p->rows[p->nrows].name = copy;
  p->rows[p->nrows].launches = 0;
  p->rows[p->nrows].seconds = 0.0;
  copy = NULL; /* the row owns it */
  *row = p->nrows++;
done:
  free(copy);
  return st;
}

/* The row of a kernel object: its function name is asked for on its first launch only. */
static enum clsph_status profile_kernel_row(struct kern_profile *p, cl_kernel k, size_t *row)
{
  enum clsph_status st = CLSPH_OK;
  char *name = NULL;
  size_t size = 0, r = 0;
  if (p->last < p->nkernels && p->kernels[p->last].k == k) { /* the same kernel again */
    *row = p->kernels[p->last].row;
    goto done;
  }
  for (size_t i = 0; i < p->nkernels; ++i) {
    if (p->kernels[i].k == k) {
      p->last = i;
      *row = p->kernels[i].row;
      goto done;
    }
  }
  CLSPH_CL_TRY(clGetKernelInfo(k, CL_KERNEL_FUNCTION_NAME, 0, NULL, &size));
  name = malloc(size + 1);
  CLSPH_CHECK(name != NULL, CLSPH_E_NOMEM, "out of memory for the profile");
  CLSPH_CL_TRY(clGetKernelInfo(k, CL_KERNEL_FUNCTION_NAME, size, name, NULL));
  name[size] = '\0';
  if (p->nkernels == p->cap_kernels) {
    size_t cap = p->cap_kernels > 0 ? 2 * p->cap_kernels : 32;
    struct profile_kernel *grown = realloc(p->kernels, cap * sizeof *grown);
    CLSPH_CHECK(grown != NULL, CLSPH_E_NOMEM, "out of memory for the profile");
    p->kernels = grown;
    p->cap_kernels = cap;
  }
  CLSPH_TRY(profile_row(p, name, &r));
  CLSPH_CL_TRY(clRetainKernel(k));
  p->kernels[p->nkernels].k = k;
  p->kernels[p->nkernels].row = r;
  p->last = p->nkernels++;
  *row = r;
done:
  free(name);
  return st;
}

/* Where a command puts its event: &ev while the device's profile records, else nowhere. */
static cl_event *profile_event(const struct dev *dev, cl_event *ev)
{
  return dev->profile != NULL && dev->profile->on ? ev : NULL;
}

/* Keep a recorded command for the next flush; the profile takes over the reference to ev. */
static enum clsph_status profile_keep(struct kern_profile *p, size_t row, cl_event ev)
{
  enum clsph_status st = CLSPH_OK;
  if (p->npending == PROFILE_BATCH) CLSPH_TRY(profile_flush(p));
  p->pending[p->npending] = ev;
  p->pending_row[p->npending] = row;
  ++p->npending;
  ev = NULL;
done:
  if (ev != NULL) clReleaseEvent(ev);
  return st;
}

/* Record a transfer ("(read)", ...) whose event is *ev (nothing when it recorded none; the profile
 * takes it over and clears *ev); after a blocking one everything before it has run, so the kept
 * commands are resolved without waiting. */
static enum clsph_status profile_transfer(const struct dev *dev, const char *what, cl_event *ev,
                                          int blocking)
{
  enum clsph_status st = CLSPH_OK;
  size_t row = 0;
  if (*ev == NULL) goto done;
  CLSPH_TRY(profile_row(dev->profile, what, &row));
  cl_event kept = *ev;
  *ev = NULL;
  CLSPH_TRY(profile_keep(dev->profile, row, kept));
  if (blocking) CLSPH_TRY(profile_flush(dev->profile));
done:
  return st;
}

/* ---- launches and transfers ---- */

enum clsph_status kern_launch_wg(const struct dev *dev, cl_kernel k, size_t n, size_t wg,
                                 struct kern_timer *timer)
{
  enum clsph_status st = CLSPH_OK;
  cl_event ev = NULL;
  char name[128];
  size_t global = (n + wg - 1) / wg * wg;
  if (global == 0) goto done;
  int timed = timer != NULL && timer->on;
  int profiled = profile_event(dev, &ev) != NULL;
  cl_int err = clEnqueueNDRangeKernel(dev->queue, k, 1, NULL, &global, &wg, 0, NULL,
                                      timed || profiled ? &ev : NULL);
  if (err != CL_SUCCESS) {
    log_error("clEnqueueNDRangeKernel(%s): %s", kernel_name(k, name, sizeof name),
              dev_cl_error_str(err));
    st = CLSPH_E_CL;
    goto done;
  }
  if (profiled) {
    size_t row = 0;
    CLSPH_TRY(profile_kernel_row(dev->profile, k, &row));
    if (timed) CLSPH_CL_TRY(clRetainEvent(ev)); /* one reference for the profile, one here */
    cl_event kept = ev;
    if (!timed) ev = NULL; /* the profile's now */
    CLSPH_TRY(profile_keep(dev->profile, row, kept));
  }
  if (timed) {
    double s = 0.0;
    CLSPH_CL_TRY(clWaitForEvents(1, &ev));
    CLSPH_TRY(event_seconds(ev, &s));
    timer->seconds += s;
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

/* Device memory in kern_buffer's buffers, and what modules announced (process-wide: one device
 * at a time in a process). */
static size_t allocated = 0;
static double reserved = 0.0;

size_t kern_allocated(void)
{
  return allocated;
}

void kern_reserve(double bytes)
{
  reserved += bytes;
  if (reserved < 0.0) reserved = 0.0;
}

size_t kern_reserved(void)
{
  return (size_t)reserved;
}

enum clsph_status kern_buffer(const struct dev *dev, size_t bytes, const void *init, cl_mem *out,
                              const char *name)
{
  enum clsph_status st = CLSPH_OK;
  cl_int err = CL_SUCCESS;
  cl_mem_flags flags = CL_MEM_READ_WRITE | (init != NULL ? CL_MEM_COPY_HOST_PTR : 0);
  CLSPH_CHECK(dev->max_alloc == 0 || (cl_ulong)bytes <= dev->max_alloc, CLSPH_E_NOMEM,
              "the buffer '%s' needs %.1f MiB, more than the %.1f MiB the device %s allocates at "
              "once (CL_DEVICE_MAX_MEM_ALLOC_SIZE): a coarser dr, or another device (clsph "
              "devices)",
              name, (double)bytes / 1048576.0, (double)dev->max_alloc / 1048576.0, dev->name);
  cl_mem d = clCreateBuffer(dev->ctx, flags, bytes > 0 ? bytes : 1, (void *)(size_t)init, &err);
  if (err != CL_SUCCESS) {
    log_error("clCreateBuffer(%s, %zu bytes): %s", name, bytes, dev_cl_error_str(err));
    st = CLSPH_E_CL;
    goto done;
  }
  allocated += bytes > 0 ? bytes : 1;
  *out = d;
done:
  return st;
}

/* One transfer between the host and d, waited for (blocking) or queued. */
static enum clsph_status transfer(const struct dev *dev, cl_mem d, int write, size_t offset,
                                  size_t bytes, void *h, int blocking)
{
  enum clsph_status st = CLSPH_OK;
  cl_event ev = NULL;
  const cl_bool b = blocking ? CL_TRUE : CL_FALSE;
  if (bytes == 0) goto done;
  if (write)
    CLSPH_CL_TRY(
        clEnqueueWriteBuffer(dev->queue, d, b, offset, bytes, h, 0, NULL, profile_event(dev, &ev)));
  else
    CLSPH_CL_TRY(
        clEnqueueReadBuffer(dev->queue, d, b, offset, bytes, h, 0, NULL, profile_event(dev, &ev)));
  CLSPH_TRY(profile_transfer(dev,
                             write ? (blocking ? "(write)" : "(write, queued)")
                                   : (blocking ? "(read)" : "(read, queued)"),
                             &ev, blocking));
done:
  if (ev != NULL) clReleaseEvent(ev);
  return st;
}

enum clsph_status kern_read_at(const struct dev *dev, cl_mem d, size_t offset, size_t bytes,
                               void *h)
{
  return transfer(dev, d, 0, offset, bytes, h, 1);
}

enum clsph_status kern_read_nb(const struct dev *dev, cl_mem d, size_t offset, size_t bytes,
                               void *h)
{
  return transfer(dev, d, 0, offset, bytes, h, 0);
}

enum clsph_status kern_read(const struct dev *dev, cl_mem d, size_t bytes, void *h)
{
  return transfer(dev, d, 0, 0, bytes, h, 1);
}

/* clEnqueueWriteBuffer takes a const pointer: the cast only shares transfer() with the reads */
enum clsph_status kern_write(const struct dev *dev, cl_mem d, size_t bytes, const void *h)
{
  return transfer(dev, d, 1, 0, bytes, (void *)(size_t)h, 1);
}

enum clsph_status kern_write_at(const struct dev *dev, cl_mem d, size_t offset, size_t bytes,
                                const void *h)
{
  return transfer(dev, d, 1, offset, bytes, (void *)(size_t)h, 1);
}

enum clsph_status kern_write_nb(const struct dev *dev, cl_mem d, size_t bytes, const void *h)
{
  return transfer(dev, d, 1, 0, bytes, (void *)(size_t)h, 0);
}

enum clsph_status kern_fill(const struct dev *dev, cl_mem d, const void *pattern, size_t psize,
                            size_t bytes)
{
  enum clsph_status st = CLSPH_OK;
  cl_event ev = NULL;
  if (bytes == 0) goto done;
  CLSPH_CL_TRY(clEnqueueFillBuffer(dev->queue, d, pattern, psize, 0, bytes, 0, NULL,
                                   profile_event(dev, &ev)));
  CLSPH_TRY(profile_transfer(dev, "(fill)", &ev, 0));
done:
  if (ev != NULL) clReleaseEvent(ev);
  return st;
}

enum clsph_status kern_copy(const struct dev *dev, cl_mem dst, cl_mem src, size_t bytes)
{
  enum clsph_status st = CLSPH_OK;
  cl_event ev = NULL;
  if (bytes == 0) goto done;
  CLSPH_CL_TRY(
      clEnqueueCopyBuffer(dev->queue, src, dst, 0, 0, bytes, 0, NULL, profile_event(dev, &ev)));
  CLSPH_TRY(profile_transfer(dev, "(copy)", &ev, 0));
done:
  if (ev != NULL) clReleaseEvent(ev);
  return st;
}

void kern_release(cl_mem *d)
{
  size_t bytes = 0;
  if (*d != NULL && clGetMemObjectInfo(*d, CL_MEM_SIZE, sizeof bytes, &bytes, NULL) == CL_SUCCESS)
    allocated -= bytes <= allocated ? bytes : allocated;
  if (*d != NULL) clReleaseMemObject(*d);
  *d = NULL;
}
