/* smoothing.h: choice of smoothing function and its constants, computed on the host in double and
 * handed to the kernels as -D switches (kernels/common/smoothing.h has the formulas). */
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
/** @brief Add SMOOTHING, SMOOTH_INV_H, SMOOTH_ALPHA, SMOOTH_SUPPORT to the build options. */
enum clsph_status smoothing_define(const struct smoothing *s, struct prog_opts *o);

#endif /* CLSPH_SMOOTHING_H */
