/* smoothing.h: choice of smoothing function and its constants, computed on the host in double.
 * The kernels (kernels/common/smoothing.h has the formulas) get the function as a -D switch and the
 * constants at run time, in struct smooth_dev, so that one program build serves every smoothing
 * length. */
#ifndef CLSPH_SMOOTHING_H
#define CLSPH_SMOOTHING_H

#include "prog.h"

enum smoothing_kind {
  SMOOTHING_WENDLAND_C2 = 1,  /* Leroy et al. 2014 eq 1, support 2h */
  SMOOTHING_CUBIC_SPLINE = 2, /* Monaghan 1992, support 2h */
  SMOOTHING_GAUSSIAN = 3,     /* truncated, Hosseini & Feng 2011 eq 23, support 3h */
};

/** A smoothing function for one dimension and smoothing length. */
struct smoothing {
  enum smoothing_kind kind;
  int dim;        /* 1, 2 or 3 */
  double h;       /* smoothing length, m */
  double alpha;   /* normalisation divided by h^dim, m^-dim */
  double support; /* radius of the support, m */
};

/** Device view of the constants in the build's precision (struct smooth in
 *  kernels/common/smoothing.h): it rides in struct grid_dev, or goes alone as a kernel argument. */
struct smooth_dev {
  real inv_h;    /* 1/h */
  real alpha;    /* normalisation divided by h^dim */
  real support;  /* radius of the support */
  real support2; /* support² */
};

/** @brief Kind from its name ("wendland", "cubic_spline", "gaussian"); an unknown name lists them.
 */
enum clsph_status smoothing_kind_from_name(const char *name, enum smoothing_kind *out);
/** @brief Name of a kind. */
const char *smoothing_name(enum smoothing_kind kind);
/** @brief Support radius in units of h (2, 2, 3). */
double smoothing_qmax(enum smoothing_kind kind);
/** @brief Constants of `kind` in `dim` dimensions with smoothing length h > 0. */
enum clsph_status smoothing_make(enum smoothing_kind kind, int dim, double h,
                                 struct smoothing *out);
/** @brief The device view of s. */
struct smooth_dev smoothing_dev(const struct smoothing *s);
/** @brief Add SMOOTHING (the function, not its length) to the build options. */
enum clsph_status smoothing_define(const struct smoothing *s, struct prog_opts *o);

#endif /* CLSPH_SMOOTHING_H */
