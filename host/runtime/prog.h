/* prog.h: OpenCL programs built from the sources under kernels/, with -D switches, cached on disk.
 *
 * A program is an ordered list of source paths relative to kernels/ ("common/real.h", ...). The
 * texts come from the table CMake embeds in the binary, or from --kernel-dir. Each text is preceded
 * by a #line directive, so a compiler message names the file and line in kernels/. */
#ifndef CLSPH_PROG_H
#define CLSPH_PROG_H

#include <stddef.h>

#include "dev.h"

/** One embedded source file (generated table). */
struct prog_embedded {
  const char *path; /* relative to kernels/ */
  const char *text;
  size_t len; /* bytes, without the terminating zero */
};
extern const struct prog_embedded prog_embedded_sources[];
extern const size_t prog_embedded_count;

/** Build options, one -D at a time. */
struct prog_opts {
  char *text; /* space-separated options, NUL-terminated */
  size_t len, cap;
};

/** @brief Read kernel sources from DIR instead of the embedded table (NULL: embedded). */
void prog_set_kernel_dir(const char *dir);
/** @brief Program cache folder (NULL: $CLSPH_CACHE_DIR, else $XDG_CACHE_HOME/clsph, else
 *  ~/.cache/clsph); "" disables the cache. */
void prog_set_cache_dir(const char *dir);
/** @brief Allow -cl-fast-relaxed-math (off by default; tests never use it). */
void prog_set_fast_math(int on);

/** @brief The neighbour loops' lanes the programs for dev take (NEIGH_W: 4 or 8; CLSPH_LANES). */
enum clsph_status prog_neigh_lanes(const struct dev *dev, int *lanes);
/** @brief Append "-D NAME=VALUE" (VALUE NULL: "-D NAME"). */
enum clsph_status prog_opts_define(struct prog_opts *o, const char *name, const char *value);
/** @brief Append "-D NAME=V" for an integer. */
enum clsph_status prog_opts_define_int(struct prog_opts *o, const char *name, long v);
/** @brief Append "-D NAME=R(V)" for a real constant, printed exactly (17 digits). */
enum clsph_status prog_opts_define_real(struct prog_opts *o, const char *name, double v);
/** @brief Release the option text. */
void prog_opts_free(struct prog_opts *o);

/** @brief Build a program.
 *  @param sources NULL-terminated list of paths relative to kernels/, in order.
 *  @param opts    scene switches; the precision switch CLSPH_DOUBLE is always added.
 *  @param out     the built program, owned by the caller.
 *  @return CLSPH_E_BUILD with the compiler log printed when compilation fails. */
enum clsph_status prog_build(const struct dev *dev, const char *const *sources,
                             const struct prog_opts *opts, cl_program *out);

/** @brief prog_build() with one more source text after `sources` (tests use it for their own
 *  kernels). @param extra_name the file name compiler messages give for it. */
enum clsph_status prog_build_extra(const struct dev *dev, const char *const *sources,
                                   const char *extra_name, const char *extra_text,
                                   const struct prog_opts *opts, cl_program *out);

/** @brief Whether the last prog_build() came from the disk cache (for tests and logs). */
int prog_last_from_cache(void);

/** @brief Create a kernel by name; a failure names the kernel. */
enum clsph_status prog_kernel(cl_program prog, const char *name, cl_kernel *out);

#endif /* CLSPH_PROG_H */
