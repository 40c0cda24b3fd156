/* channel1d.c: the fully developed k-ε channel across the half channel (Wang, Sun & Hu, sec 5.1,
 * eq 41), by finite differences on the nodes y_i = y_p + i Δ, Δ = (δ − y_p)/cells:
 *   (ν + ν_t) du/dy = u_τ² (1 − y/δ)                      integrated from the wall function's u
 *                                                           at y_p, by the trapezoidal rule
 *   0 = ν_t (du/dy)² − ε + d/dy((ν + ν_t/σ_k) dk/dy)       node 0: G = G_k,p (eq 13), no diffusive
 *                                                           flux to the wall (sec 4.3, third type)
 *   0 = C1 ε/k ν_t (du/dy)² − C2 ε²/k + d/dy((ν + ν_t/σ_ε) dε/dy)   node 0: ε_p (eq 14)
 * with symmetry at y = δ. Eq 41 writes the diffusion as (ν + ν_t/σ) d²φ/dy², which drops the
 * dν_t/dy dφ/dy part of the k-ε model's ∇·(D ∇φ) (eqs 7-8); `paper_diffusion` selects it.
 * The steady state is reached in pseudo-time, implicitly in the diffusion and in the linearised
 * sinks of eqs 28-30 (every coefficient positive: k and ε stay positive), with the local step
 * k/ε. The paper integrates u with the backward (first-order) difference; the trapezoidal rule
 * here keeps the stream second order, but the wall node's sources act over its half cell Δ/2
 * (node 0 takes the mirror φ_{−1} = φ_1), so the whole scheme converges at first order, and to
 * a limit in which the wall function's production and ε act on a vanishing layer
 * (test_channel1d measures the order).
 * The SPH channel's wall model acts on its first particle row, a layer of one spacing whose
 * bottom is the offset wall (sec 4.4), and which shrinks as the particles refine: `rows` puts
 * the nodes on the rows of an SPH run with cells of one spacing around them (the first one's
 * bottom face the offset wall, the wall function's sources over the whole cell), so that the
 * same model on the same points, with the same wall layer, is the reference of that run. At
 * 20 rows (y_p = 0.05, the first cell [0, 2 y_p]) it is OpenFOAM's wall-function mesh.
 * `fv` discretises as a cell-centred finite volume on the same nodes instead (the faces' mean ν_t
 * in the momentum flux, the production from central differences of u): on OpenFOAM's mesh it
 * reproduces OpenFOAM's channel (test_channel1d: u_τ within 0.24%), where the default stands 2.4%
 * under it; both converge to the same grid limit. */
#include "channel1d.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

struct channel1d_model channel1d_standard(void)
{
  struct channel1d_model m = {.c_mu = 0.09,
                              .c1 = 1.44,
                              .c2 = 1.92,
                              .sigma_k = 1.0,
                              .sigma_eps = 1.3,
                              .kappa = 0.41,
                              .e_wall = 9.793,
                              .y_plus_lam = 11.225,
                              .paper_diffusion = 0,
                              .fv = 0,
                              .backward = 0};
  return m;
}

/* u+ (eq 11) and its integral from the wall, ∫_0^Y u+ dy+ */
static double u_plus(const struct channel1d_model *m, double yp)
{
  return yp < m->y_plus_lam ? yp : log(m->e_wall * yp) / m->kappa;
}

static double u_plus_integral(const struct channel1d_model *m, double yp)
{
  double yl = m->y_plus_lam;
  if (yp <= yl) return 0.5 * yp * yp;
  double f = yp * (log(m->e_wall * yp) - 1.0) - yl * (log(m->e_wall * yl) - 1.0);
  return 0.5 * yl * yl + f / m->kappa;
}

double channel1d_wall_u(const struct channel1d_model *m, double nu, double u_tau, double k_p,
                        double y)
{
  double u_star = m->ustar_law ? u_tau : pow(m->c_mu, 0.25) * sqrt(k_p);
  /* τ_w = ρ U C_μ^¼ k^½ / u+ (eq 12) with τ_w = ρ u_τ²; or U = u_τ u+ (Leroy et al. eq 23) */
  return u_tau * u_tau / u_star * u_plus(m, y * u_star / nu);
}

/* Thomas algorithm: a_i x_{i−1} + b_i x_i + c_i x_{i+1} = d_i, i = 0..n−1 (a_0 = c_{n−1} = 0);
 * overwrites c and d, the solution in d */
static void tridiag(int n, const double *a, const double *b, double *c, double *d)
{
  c[0] /= b[0];
  d[0] /= b[0];
  for (int i = 1; i < n; ++i) {
    double q = b[i] - a[i] * c[i - 1];
    c[i] /= q;
    d[i] = (d[i] - a[i] * d[i - 1]) / q;
  }
  for (int i = n - 2; i >= 0; --i) d[i] -= c[i] * d[i + 1];
}

void channel1d_free(struct channel1d_solution *s)
{
  free(s->y);
  s->y = s->u = s->k = s->eps = s->nu_t = NULL;
}

/* The diffusion coefficients between nodes i and i+1 (conservative), or at the nodes (eq 41) */
static void diffusion(const struct channel1d_problem *p, const double *nu_t, double sigma, int n,
                      double *face, double *node)
{
  for (int i = 0; i < n; ++i) node[i] = p->nu + nu_t[i] / sigma;
  for (int i = 0; i + 1 < n; ++i) face[i] = p->nu + 0.5 * (nu_t[i] + nu_t[i + 1]) / sigma;
}

/* The rows of −d/dy(D dφ/dy) at node i (with a zero-flux node 0 and a symmetric node n−1):
 * coefficients of φ_{i−1}, φ_i, φ_{i+1}. Node 0 takes no flux through the face below it: on the
 * node (the mirror φ_{−1} = φ_1, a half cell) or, with `rows`, half a spacing below (the cell of
 * an SPH row, whose bottom face is the offset wall). The symmetry plane lies on node n−1
 * (φ_n = φ_{n−2}) or, with `half`, half a spacing beyond it (φ_n = φ_{n−1}). */
static void diffusion_row(const struct channel1d_model *m, const double *face, const double *node,
                          int i, int n, int rows, int half, double dx, double *a, double *b,
                          double *c)
{
  double r = 1.0 / (dx * dx);
  double dl, dr;
  if (m->paper_diffusion) {
    dl = dr = node[i];
  } else {
    dl = i > 0 ? face[i - 1] : 0.0;
    dr = i + 1 < n ? face[i] : 0.0;
  }
  if (i == 0) { /* no flux into the wall */
    *a = 0.0;
    *c = -(rows ? 1.0 : 2.0) * (m->paper_diffusion ? node[0] : face[0]) * r;
    *b = -*c;
  } else if (i == n - 1) { /* symmetry: φ_n = φ_{n−2}, or φ_n = φ_{n−1} (half) */
    *a = -(half ? 1.0 : 2.0) * (m->paper_diffusion ? node[i] : face[i - 1]) * r;
    *c = 0.0;
    *b = -*a;
  } else {
    *a = -dl * r;
    *c = -dr * r;
    *b = (dl + dr) * r;
  }
}

int channel1d_solve(const struct channel1d_model *m, const struct channel1d_problem *p,
                    struct channel1d_solution *s)
{
  int rows = p->rows > 0, n = rows ? (p->rows + 1) / 2 : p->cells + 1;
  int half = rows && p->rows % 2 == 0;
  const char *bad = NULL;
  if (rows ? p->rows < 8 : p->cells < 4)
    bad = rows ? "rows must be 8 or more" : "cells must be 4 or more";
  else if (!(p->delta > 0) || !(p->nu > 0))
    bad = "δ and ν must be positive";
  else if (!(p->y_p > 0) || !(p->y_p < p->delta))
    bad = "y_p must lie between 0 and δ";
  else if (!(p->u_tau > 0 || p->u_bulk > 0))
    bad = "give a positive u_bulk or u_tau";
  else if (p->bulk_over_rows && !rows)
    bad = "a bulk over the rows needs rows";
  else if (p->offset_momentum && !p->bulk_over_rows)
    bad = "the offset wall's momentum balance needs the bulk over the rows";
  else if (m->fv && m->backward)
    bad = "one scheme: the finite volume's (--fv) or the backward differences (--backward)";
  if (bad != NULL) {
    fprintf(stderr, "channel1d: %s\n", bad);
    return -1;
  }
  double *mem = calloc((size_t)n * 14, sizeof(double));
  if (mem == NULL) {
    fprintf(stderr, "channel1d: out of memory\n");
    return -1;
  }
  s->nodes = n;
  s->y = mem;
  s->u = mem + n;
  s->k = mem + 2 * n;
  s->eps = mem + 3 * n;
  s->nu_t = mem + 4 * n;
  double *g = mem + 5 * n, *prod = mem + 6 * n, *a = mem + 7 * n, *b = mem + 8 * n;
  double *c = mem + 9 * n, *d = mem + 10 * n, *face = mem + 11 * n, *node = mem + 12 * n;
  double *old = mem + 13 * n;
  double dx = rows ? 2.0 * (p->delta - p->y_p) / (p->rows - 1) : (p->delta - p->y_p) / p->cells;
  /* the total stress over u_τ² at y = 0 (p->offset_momentum: 1/(1 − y_w/δ), the wall's stress at
   * the offset wall y_w = y_p − Δ/2) */
  const double stress = p->offset_momentum ? p->delta / (p->delta - (p->y_p - 0.5 * dx)) : 1.0;
  double cmu = m->c_mu, cmu14 = pow(cmu, 0.25), cmu34 = pow(cmu, 0.75);

  /* start: the log layer's equilibrium at u_τ = 0.05 U */
  double u_tau = p->u_tau > 0 ? p->u_tau : 0.05 * p->u_bulk;
  for (int i = 0; i < n; ++i) {
    s->y[i] = p->y_p + i * dx;
    s->k[i] = u_tau * u_tau / sqrt(cmu) * fmax(1.0 - s->y[i] / p->delta, 0.1);
    s->eps[i] = cmu34 * pow(s->k[i], 1.5) / (m->kappa * fmin(s->y[i], 0.2 * p->delta));
  }
  int it;
  double change = 1.0;
  for (it = 1; it <= 200000 && change > 1e-10; ++it) {
    for (int i = 0; i < n; ++i) s->nu_t[i] = cmu * s->k[i] * s->k[i] / s->eps[i]; /* eq 6 */
    /* u = u_τ² f: f from the wall function at y_p and (ν + ν_t) df/dy = 1 − y/δ */
    double u_star = m->ustar_law ? u_tau : cmu14 * sqrt(s->k[0]);
    double yp_plus = p->y_p * u_star / p->nu;
    double f0 = u_plus(m, yp_plus) / u_star;
    for (int i = 0; i < n; ++i) g[i] = (1.0 - s->y[i] / p->delta) * stress / (p->nu + s->nu_t[i]);
    double flux = p->nu / (u_star * u_star) * u_plus_integral(m, yp_plus); /* ∫_0^{y_p} f dy */
    old[0] = f0;
    for (int i = 1; i < n; ++i) {
      if (m->backward) {
        old[i] = old[i - 1] + dx * g[i];
      } else if (m->fv) { /* the flux through the face between the nodes */
        const double yf = 0.5 * (s->y[i - 1] + s->y[i]);
        old[i] = old[i - 1] + dx * (1.0 - yf / p->delta) * stress /
                                  (p->nu + 0.5 * (s->nu_t[i - 1] + s->nu_t[i]));
      } else {
        old[i] = old[i - 1] + 0.5 * dx * (g[i - 1] + g[i]);
      }
      flux += 0.5 * dx * (old[i - 1] + old[i]);
    }
    if (half) { /* the last half spacing, to the centre plane where df/dy = 0 */
      double f_c = old[n - 1] + 0.25 * dx * g[n - 1];
      flux += 0.25 * dx * (old[n - 1] + f_c);
    }
    double rows_sum = 0.0, rows_w = 0.0; /* the mean over the rows, the centre node's half */
    for (int i = 0; i < n; ++i) {
      double w = !half && i == n - 1 ? 0.5 : 1.0;
      rows_sum += w * old[i];
      rows_w += w;
    }
    if (p->u_tau <= 0)
      u_tau = sqrt(p->bulk_over_rows ? p->u_bulk * rows_w / rows_sum : p->u_bulk * p->delta / flux);
    double ut2 = u_tau * u_tau;
    change = 0.0;
    for (int i = 0; i < n; ++i) {
      double u = ut2 * old[i];
      change = fmax(change, fabs(u - s->u[i]) / (ut2 * old[n - 1]));
      s->u[i] = u;
    }
    s->u_tau = u_tau;
    s->u_bulk = ut2 * flux / p->delta;
    s->u_rows = ut2 * rows_sum / rows_w;
    s->y_plus_p = yp_plus;
    /* production: ν_t (du/dy)² in the stream, τ_w (∂U/∂n)_p at the first node (eq 13) */
    for (int i = 1; i < n; ++i) prod[i] = s->nu_t[i] * ut2 * g[i] * ut2 * g[i];
    if (m->backward)
      for (int i = 1; i < n; ++i) {
        const double du = (s->u[i] - s->u[i - 1]) / dx;
        prod[i] = s->nu_t[i] * du * du;
      }
    else if (m->fv) /* the central difference; beyond the last node its mirror about the centre */
      for (int i = 1; i < n; ++i) {
        const double up = i + 1 < n ? s->u[i + 1] : (half ? s->u[i] : s->u[i - 1]);
        const double du = (up - s->u[i - 1]) / (2.0 * dx);
        prod[i] = s->nu_t[i] * du * du;
      }
    double dudn = yp_plus < m->y_plus_lam ? ut2 / p->nu : ut2 / (u_star * m->kappa * p->y_p);
    prod[0] = ut2 * dudn;
    /* k (eqs 28, 30) */
    diffusion(p, s->nu_t, m->sigma_k, n, face, node);
    for (int i = 0; i < n; ++i) {
      double rate = s->eps[i] / s->k[i], dt = 1.0 / rate;
      diffusion_row(m, face, node, i, n, rows, half, dx, &a[i], &b[i], &c[i]);
      a[i] *= dt;
      c[i] *= dt;
      b[i] = 1.0 + dt * (b[i] + rate);
      d[i] = s->k[i] + dt * prod[i];
      old[i] = s->k[i];
    }
    tridiag(n, a, b, c, d);
    for (int i = 0; i < n; ++i) {
      change = fmax(change, fabs(d[i] - old[i]) / d[i]);
      s->k[i] = d[i];
    }
    /* ε (eqs 29, 30); the first node takes eq 14 */
    diffusion(p, s->nu_t, m->sigma_eps, n, face, node);
    double eps_p = cmu34 * pow(s->k[0], 1.5) / (m->kappa * p->y_p);
    for (int i = 0; i < n; ++i) {
      old[i] = s->eps[i];
      if (i == 0) {
        a[0] = 0.0;
        b[0] = 1.0;
        c[0] = 0.0;
        d[0] = eps_p;
        continue;
      }
      double rate = s->eps[i] / s->k[i], dt = 1.0 / rate;
      diffusion_row(m, face, node, i, n, rows, half, dx, &a[i], &b[i], &c[i]);
      a[i] *= dt;
      c[i] *= dt;
      b[i] = 1.0 + dt * (b[i] + m->c2 * rate);
      d[i] = s->eps[i] + dt * m->c1 * rate * prod[i];
    }
    tridiag(n, a, b, c, d);
    for (int i = 0; i < n; ++i) {
      change = fmax(change, fabs(d[i] - old[i]) / d[i]);
      s->eps[i] = d[i];
    }
  }
  s->iterations = it - 1;
  s->residual = change;
  for (int i = 0; i < n; ++i) s->nu_t[i] = cmu * s->k[i] * s->k[i] / s->eps[i];
  if (change > 1e-10) {
    fprintf(stderr, "channel1d: no steady state after %d iterations (change %.3g)\n", it - 1,
            change);
    return -1;
  }
  return 0;
}
