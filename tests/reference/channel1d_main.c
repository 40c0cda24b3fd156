/* channel1d_main.c: the 1-D k-ε channel reference (channel1d.h) as a command that writes the
 * profile as CSV.
 *   channel1d [--delta 1] [--nu 1e-4] [--y-p 0.05] [--u-bulk 1 | --u-tau U]
 *             [--cells 3200 | --rows N_f [--bulk-over-rows [--offset-momentum]]]
 *             [--paper-diffusion] [--log-b B]
 *             [--wall-law u_k|u_tau] [--fv | --backward] [--out FILE]
 * --fv discretises as a cell-centred finite volume on the same nodes (channel1d.h: the faces'
 * mean ν_t in the momentum flux, the production from central differences of u): with OpenFOAM's
 * log law (--log-b 5.5667: E = 9.8) on 20 rows it is OpenFOAM's 20-cell wall-function channel.
 * --backward takes the paper's backward difference for du/dy in the momentum equation and the
 * production (sec 5.1), a first-order scheme.
 * --log-b B takes the log law u+ = ln(y+)/κ + B (E = exp(κ B)) with the switch to u+ = y+ where
 * the two meet: B = 5.2 is Leroy et al.'s wall law (eq 23), the default E = 9.793 (B = 5.56) Wang,
 * Sun & Hu's (eq 11). --wall-law u_tau scales the law with the friction velocity itself, as
 * Leroy et al.'s wall condition does (eq 23), instead of C_μ^¼ k_p^½ (u_k, the default).
 * --rows N_f puts the nodes on the particle rows of an SPH channel of N_f rows across with its
 * first row at y_p (channel1d.h); --bulk-over-rows then holds the mean of u over those rows at
 * --u-bulk, as the SPH run's flow-rate control holds its particles' mean; --offset-momentum
 * takes the SPH run's momentum balance between its offset walls (channel1d.h: the wall's stress
 * at y_p − Δ/2), that of wcsph-riemann's offset_layer = "none".
 * The defaults are Lee & Moser's Re_τ = 543.5 channel (δ = 1, U_b = 1, ν = 1e-4) with the
 * wall model at y_p = 0.05 (half the spacing of 20 particles across the channel), on 3200 cells
 * (test_channel1d: u_τ there within 0.03% of its grid limit). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "channel1d.h"

static int number(const char *opt, const char *text, double *out)
{
  char *end = NULL;
  *out = strtod(text, &end);
  if (end == text || *end != '\0') {
    fprintf(stderr, "channel1d: %s: '%s' is not a number\n", opt, text);
    return -1;
  }
  return 0;
}

int main(int argc, char **argv)
{
  struct channel1d_model m = channel1d_standard();
  struct channel1d_problem p = {
      .delta = 1.0, .nu = 1e-4, .y_p = 0.05, .u_bulk = 1.0, .cells = 3200};
  const char *out = NULL;
  for (int i = 1; i < argc; ++i) {
    const char *o = argv[i];
    double v = 0.0;
    if (strcmp(o, "--paper-diffusion") == 0) {
      m.paper_diffusion = 1;
      continue;
    }
    if (strcmp(o, "--bulk-over-rows") == 0) {
      p.bulk_over_rows = 1;
      continue;
    }
    if (strcmp(o, "--offset-momentum") == 0) {
      p.offset_momentum = 1;
      continue;
    }
    if (strcmp(o, "--fv") == 0 || strcmp(o, "--backward") == 0) {
      *(strcmp(o, "--fv") == 0 ? &m.fv : &m.backward) = 1;
      continue;
    }
    if (i + 1 >= argc) {
      fprintf(stderr, "channel1d: %s needs a value (see the header of channel1d_main.c)\n", o);
      return 2;
    }
    const char *val = argv[++i];
    if (strcmp(o, "--out") == 0) {
      out = val;
      continue;
    }
    if (strcmp(o, "--wall-law") == 0) {
      if (strcmp(val, "u_k") != 0 && strcmp(val, "u_tau") != 0) {
        fprintf(stderr,
                "channel1d: --wall-law must be u_k (Wang, Sun & Hu eq 12) or u_tau "
                "(Leroy et al. eq 23), not %s\n",
                val);
        return 2;
      }
      m.ustar_law = strcmp(val, "u_tau") == 0;
      continue;
    }
    if (number(o, val, &v) != 0) return 2;
    if (strcmp(o, "--delta") == 0)
      p.delta = v;
    else if (strcmp(o, "--nu") == 0)
      p.nu = v;
    else if (strcmp(o, "--y-p") == 0)
      p.y_p = v;
    else if (strcmp(o, "--u-bulk") == 0)
      p.u_bulk = v, p.u_tau = 0.0;
    else if (strcmp(o, "--u-tau") == 0)
      p.u_tau = v;
    else if (strcmp(o, "--log-b") == 0) {
      if (!(v > 0.0 && v < 20.0)) {
        fprintf(stderr, "channel1d: --log-b must be an additive constant from 0 to 20, not %s\n",
                val);
        return 2;
      }
      m.e_wall = exp(m.kappa * v);
      double y = 11.0; /* where y+ = ln(E y+)/κ: a fixed point, contracting there */
      for (int it = 0; it < 200; ++it) y = log(m.e_wall * y) / m.kappa;
      m.y_plus_lam = y;
    } else if (strcmp(o, "--cells") == 0 || strcmp(o, "--rows") == 0) {
      if (!(v >= 1.0 && v <= 1e7) || v != floor(v)) {
        fprintf(stderr, "channel1d: %s must be a whole number from 1 to 1e7, not %s\n", o, val);
        return 2;
      }
      *(strcmp(o, "--cells") == 0 ? &p.cells : &p.rows) = (int)v;
    } else {
      fprintf(stderr, "channel1d: unknown option %s\n", o);
      return 2;
    }
  }
  struct channel1d_solution s = {0};
  if (channel1d_solve(&m, &p, &s) != 0) return 1;
  FILE *f = out ? fopen(out, "w") : stdout;
  if (f == NULL) {
    fprintf(stderr, "channel1d: cannot write %s\n", out);
    channel1d_free(&s);
    return 1;
  }
  double ut = s.u_tau;
  fprintf(f,
          "# channel1d (tests/reference): standard k-epsilon, wall function at y_p = %g "
          "(Wang, Sun & Hu sec 5.1, eq 41)%s%s%s; log law E = %.6g (B = %.4g), u+ = y+ below y+ = "
          "%.5g\n",
          p.y_p, m.paper_diffusion ? ", diffusion as eq 41 writes it" : "",
          m.ustar_law ? ", the law scaled by u_tau (Leroy et al. eq 23)" : "",
          m.fv         ? ", a cell-centred finite volume's fluxes and central production"
          : m.backward ? ", the paper's backward differences for du/dy"
                       : "",
          m.e_wall, log(m.e_wall) / m.kappa, m.y_plus_lam);
  char grid[128];
  if (p.rows > 0)
    snprintf(grid, sizeof grid, "rows = %d (spacing %.6g)%s%s", p.rows, s.y[1] - s.y[0],
             p.bulk_over_rows ? ", bulk over the rows" : "",
             p.offset_momentum ? ", the stress of the offset walls" : "");
  else
    snprintf(grid, sizeof grid, "cells = %d", p.cells);
  fprintf(f,
          "# delta = %g, nu = %g, %s: u_tau = %.6g, Re_tau = %.6g, u_bulk = %.6g, "
          "u_rows = %.6g, y+ at y_p = %.5g, %d iterations\n",
          p.delta, p.nu, grid, ut, ut * p.delta / p.nu, s.u_bulk, s.u_rows, s.y_plus_p,
          s.iterations);
  fprintf(f, "# made by: channel1d");
  for (int i = 1; i < argc; ++i) fprintf(f, " %s", argv[i]);
  fprintf(f, "\n");
  fprintf(f, "y,y_over_delta,y_plus,u,u_plus,k,k_plus,epsilon,nu_t\n");
  for (int i = 0; i < s.nodes; ++i)
    fprintf(f, "%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", s.y[i], s.y[i] / p.delta,
            s.y[i] * ut / p.nu, s.u[i], s.u[i] / ut, s.k[i], s.k[i] / (ut * ut), s.eps[i],
            s.nu_t[i]);
  if (out) fclose(f);
  channel1d_free(&s);
  return 0;
}
