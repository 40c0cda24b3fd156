/* spectrum.h: the dominant frequency of a sampled signal (vortex shedding from a force history). */
#ifndef CLSPH_SPECTRUM_H
#define CLSPH_SPECTRUM_H

#include <stddef.h>

#include "status.h"

struct spectrum_peak {
  double frequency; /* of the largest amplitude, Hz (1 / the unit of t) */
  double amplitude; /* of the signal's oscillation at that frequency (units of y) */
  double median;    /* median amplitude over the frequencies scanned: the noise floor */
  double mean;      /* the signal's time-weighted mean */
};

/** @brief The amplitude spectrum of y(t), A(f) = 2 |Σ w_k (y_k − ȳ) e^(−2πi f (t_k − t_1))| / T
 *         (trapezoid weights w_k, so the samples need not be evenly spaced; T = t_n − t_1; a
 *         sinusoid of amplitude a reads a), scanned from fmin to fmax in steps of 0.1 / T, its
 *         largest value refined by golden-section search.
 *  @param f_lo lowest frequency (<= 0: 3 / T, three periods in the record)
 *  @param f_hi highest frequency (<= 0 or above it: the mean sampling rate's Nyquist frequency)
 *  @return CLSPH_E_INPUT for fewer than 8 samples, times not increasing or an empty range */
enum clsph_status spectrum_peak(size_t n, const double *t, const double *y, double f_lo,
                                double f_hi, struct spectrum_peak *out);

#endif /* CLSPH_SPECTRUM_H */
