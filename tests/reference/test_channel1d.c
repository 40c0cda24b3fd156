/* test_channel1d: the 1-D k-ε channel reference (channel1d.h) is a steady solution of its
 * discrete equations, converges under grid refinement at its observed order, reproduces the log
 * law of its wall function in the overlap region, and refuses a bad problem. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "channel1d.h"
#include "tcheck.h"

/* The largest residual of the discrete k and ε equations at the inner nodes, over their sink
 * there (the solver's own stencil, conservative form) */
static double steady_residual(const struct channel1d_model *m, const struct channel1d_problem *p,
                              const struct channel1d_solution *s)
{
  double dx = s->y[1] - s->y[0], worst = 0.0;
  for (int i = 1; i + 1 < s->nodes; ++i) {
    /* du/dy from the momentum equation, as the solver takes it (u integrates it) */
    double ut = s->u_tau, yw = p->offset_momentum ? p->y_p - 0.5 * dx : 0.0;
    double dudy =
        ut * ut * (1.0 - s->y[i] / p->delta) / (1.0 - yw / p->delta) / (p->nu + s->nu_t[i]);
    double g = s->nu_t[i] * dudy * dudy;
    double d[2];
    for (int e = 0; e < 2; ++e) {
      double sig = e == 0 ? m->sigma_k : m->sigma_eps;
      const double *f = e == 0 ? s->k : s->eps;
      double dl = p->nu + 0.5 * (s->nu_t[i - 1] + s->nu_t[i]) / sig;
      double dr = p->nu + 0.5 * (s->nu_t[i] + s->nu_t[i + 1]) / sig;
      d[e] = (dr * (f[i + 1] - f[i]) - dl * (f[i] - f[i - 1])) / (dx * dx);
    }
    double rk = g - s->eps[i] + d[0];
    double re = m->c1 * s->eps[i] / s->k[i] * g - m->c2 * s->eps[i] * s->eps[i] / s->k[i] + d[1];
    worst = fmax(worst, fabs(rk) / s->eps[i]);
    worst = fmax(worst, fabs(re) / (s->eps[i] * s->eps[i] / s->k[i]));
  }
  return worst;
}

/* The finite-volume discretisation (model.fv) on OpenFOAM's mesh against OpenFOAM itself
 * (tests/data/openfoam_channel_straight.csv, setting a: ν = 1e-4, y_p = 0.05, 20 cells, E = 9.8
 * and y*_lam = 11.53, simpleFoam v1912 with the standard k-ε and wall functions): the same model
 * on the same cells, so the two codes must agree. Measured: u_τ +0.24%, U within 0.17%, ν_t
 * 0.8%, k 1.6% and ε 2.4% (both largest in the wall cell) on every cell; bounds about twice
 * these. The default discretisation (trapezoidal momentum, exact local du/dy) gives u_τ 2.4%
 * under OpenFOAM's on the same rows: across the log layer's 1/y the trapezoidal rule
 * over-integrates du/dy (1.8%), and the central difference over-reads the production (0.6%). */
static void check_openfoam(const char *dir)
{
  char path[1024], line[1024];
  snprintf(path, sizeof path, "%s/openfoam_channel_straight.csv", dir);
  FILE *f = fopen(path, "r");
  TC_CHECK(f != NULL, "open %s", path);
  if (f == NULL) return;
  struct channel1d_model m = channel1d_standard();
  m.e_wall = 9.8;
  m.y_plus_lam = 11.0; /* where y+ = ln(E y+)/κ: OpenFOAM's yPlusLam */
  for (int it = 0; it < 200; ++it) m.y_plus_lam = log(m.e_wall * m.y_plus_lam) / m.kappa;
  m.fv = 1;
  struct channel1d_problem q = {
      .delta = 1.0, .nu = 1e-4, .y_p = 0.05, .u_bulk = 1.0, .rows = 20, .bulk_over_rows = 1};
  struct channel1d_solution s = {0};
  TC_CHECK(channel1d_solve(&m, &q, &s) == 0, "the finite-volume solve on 20 rows");
  double worst[4] = {0.0, 0.0, 0.0, 0.0}, ut = 0.0;
  int cells = 0;
  while (fgets(line, sizeof line, f)) {
    double nu, yp, y, U, k, eps, nut, u_tau;
    char mesh[64];
    if (line[0] != 'a' ||
        sscanf(line, "a,%lf,%lf,%63[^,],%lf,%lf,%lf,%lf,%lf,%lf", &nu, &yp, mesh, &u_tau, &y, &U,
               &k, &eps, &nut) != 9 ||
        nu != 1e-4 || yp != 0.05 || strcmp(mesh, "uniform_20") != 0)
      continue;
    if (cells >= s.nodes) break;
    TC_NEAR(y, s.y[cells], 1e-9, "the cell centre %d", cells + 1);
    const double d[4] = {s.u[cells] / U - 1.0, s.nu_t[cells] / nut - 1.0, s.k[cells] / k - 1.0,
                         s.eps[cells] / eps - 1.0};
    for (int e = 0; e < 4; ++e) worst[e] = fmax(worst[e], fabs(d[e]));
    ut = u_tau;
    ++cells;
  }
  fclose(f);
  TC_CHECK(cells == 10, "%s: the 10 cells of the lower half (%d)", path, cells);
  printf("finite volume on OpenFOAM's 20 cells: u_tau %.6f against %.6f (%+.2f%%); largest "
         "deviations U %.2f%%, nu_t %.2f%%, k %.2f%%, eps %.2f%%\n",
         s.u_tau, ut, 100.0 * (s.u_tau / ut - 1.0), 100.0 * worst[0], 100.0 * worst[1],
         100.0 * worst[2], 100.0 * worst[3]);
  TC_CHECK(fabs(s.u_tau / ut - 1.0) < 0.005, "u_tau within 0.5%% of OpenFOAM's");
  TC_CHECK(worst[0] < 0.005 && worst[1] < 0.015 && worst[2] < 0.03 && worst[3] < 0.05,
           "U, nu_t, k, eps within 0.5, 1.5, 3 and 5%% of OpenFOAM's on every cell");
  channel1d_free(&s);
}

/* The stored rows reference (tests/data/channel1d_rowsN.csv, which cases/channel_ke.lua reads,
 * and with `offset` channel1d_rowsN_offset.csv, the offset walls' momentum balance) against a
 * solve now: u_τ of its header, u and k on every row, to 1e-6 */
static void check_rows_file(const struct channel1d_model *m, const char *dir, int rows, int offset)
{
  char path[1024];
  snprintf(path, sizeof path, "%s/channel1d_rows%d%s.csv", dir, rows, offset ? "_offset" : "");
  FILE *f = fopen(path, "r");
  TC_CHECK(f != NULL, "open %s", path);
  if (f == NULL) return;
  struct channel1d_problem q = {.delta = 1.0,
                                .nu = 1e-4,
                                .y_p = 0.05,
                                .u_bulk = 1.0,
                                .rows = rows,
                                .bulk_over_rows = 1,
                                .offset_momentum = offset};
  struct channel1d_solution s = {0};
  TC_CHECK(channel1d_solve(m, &q, &s) == 0, "solve on %d rows", rows);
  char line[1024];
  int row = 0;
  double ut = -1.0;
  while (fgets(line, sizeof line, f)) {
    const char *at = strstr(line, "u_tau = ");
    if (line[0] == '#') {
      if (at) ut = strtod(at + 8, NULL);
      continue;
    }
    double y, yd, yplus, u, uplus, k;
    if (sscanf(line, "%lf,%lf,%lf,%lf,%lf,%lf", &y, &yd, &yplus, &u, &uplus, &k) != 6) continue;
    if (row < s.nodes) {
      TC_NEAR(y, s.y[row], 1e-8, "%s: y of row %d", path, row + 1);
      TC_NEAR(u / s.u[row], 1.0, 1e-6, "%s: u of row %d", path, row + 1);
      TC_NEAR(k / s.k[row], 1.0, 1e-6, "%s: k of row %d", path, row + 1);
    }
    ++row;
  }
  fclose(f);
  TC_CHECK(row == s.nodes, "%s: %d rows, the solve %d", path, row, s.nodes);
  TC_NEAR(ut / s.u_tau, 1.0, 1e-5, "%s: u_tau %.6g against %.7g", path, ut, s.u_tau);
  channel1d_free(&s);
}

int main(int argc, char **argv)
{
  struct channel1d_model m = channel1d_standard();
  /* Lee & Moser's Re_τ = 543.5 channel (δ = 1, U_b = 1, ν = 1e-4), the wall model at y_p = 0.05 */
  struct channel1d_problem p = {.delta = 1.0, .nu = 1e-4, .y_p = 0.05, .u_bulk = 1.0};
  int cells[5] = {100, 200, 400, 800, 1600};
  double ut[5];
  for (int g = 0; g < 5; ++g) {
    struct channel1d_solution s = {0};
    p.cells = cells[g];
    TC_CHECK(channel1d_solve(&m, &p, &s) == 0, "solve, %d cells", cells[g]);
    ut[g] = s.u_tau;
    printf("cells %5d: u_tau %.7f, y+ at y_p %.3f, U_centre/U_b %.5f, %d iterations\n", cells[g],
           s.u_tau, s.y_plus_p, s.u[s.nodes - 1], s.iterations);
    TC_NEAR(s.u_bulk, 1.0, 1e-12, "bulk velocity, %d cells", cells[g]);
    /* the iteration stops at a relative change of 1e-10 per step; the discrete equations then
     * hold to far better than the 1e-6 of their largest term */
    double r = steady_residual(&m, &p, &s);
    TC_CHECK(r < 1e-6, "steady residual %.3g < 1e-6, %d cells", r, cells[g]);
    channel1d_free(&s);
  }
  /* observed order from three grids: the wall node's half cell makes the scheme first order
   * (its source is a point value over a cell of Δ/2), the stream second */
  double order = log((ut[2] - ut[3]) / (ut[3] - ut[4])) / log(2.0);
  double limit = ut[4] + (ut[4] - ut[3]) / (pow(2.0, order) - 1.0);
  printf("observed order %.3f, Richardson limit u_tau %.7f (Re_tau %.2f)\n", order, limit,
         limit / p.nu);
  TC_CHECK(order > 0.8 && order < 1.3, "observed order %.3f in (0.8, 1.3)", order);
  TC_CHECK(ut[0] > ut[1] && ut[1] > ut[2] && ut[2] > ut[3] && ut[3] > ut[4],
           "u_tau falls monotonically with refinement");
  /* the reference profiles take 3200 cells (half this error): the goal for the SPH channel is
   * u_τ within 1% of the reference, so the reference's own error stays ten times below that */
  TC_CHECK(fabs(ut[4] / limit - 1.0) < 1e-3, "1600 cells within 0.1%% of the limit (%.2e)",
           ut[4] / limit - 1.0);

  /* the two drives agree: given u_τ, the bulk velocity that comes out gives u_τ back */
  {
    struct channel1d_problem q = p;
    struct channel1d_solution s1 = {0}, s2 = {0};
    q.cells = 400;
    q.u_tau = 0.0543496;
    TC_CHECK(channel1d_solve(&m, &q, &s1) == 0, "solve with u_tau given");
    q.u_tau = 0.0;
    q.u_bulk = s1.u_bulk;
    TC_CHECK(channel1d_solve(&m, &q, &s2) == 0, "solve with the bulk velocity given");
    TC_NEAR(s2.u_tau, 0.0543496, 1e-8, "u_tau from the bulk velocity %.6f", s1.u_bulk);
    channel1d_free(&s1);
    channel1d_free(&s2);
  }

  /* the log law in the overlap region, at Re_τ = 20000 (y+ = 100-800 is y/δ < 0.04): the
   * profile starts on the wall function's law at y_p (κ = 0.41, E = 9.793) and the model's own
   * log layer has κ' = √((C2 − C1) σ_ε √C_μ) = 0.433, so over y+ = 50-800 it may drift below
   * by at most ln(16) (1/0.41 − 1/0.433) = 0.36; in local equilibrium k+ = (1 − y/δ)/√C_μ,
   * less the small part diffusion carries (3%) */
  {
    struct channel1d_problem q = {
        .delta = 1.0, .nu = 2.5e-6, .y_p = 0.0025, .u_tau = 0.05, .cells = 4000};
    struct channel1d_solution s = {0};
    TC_CHECK(channel1d_solve(&m, &q, &s) == 0, "solve at Re_tau = 20000");
    double worst_u = 0.0, worst_k = 0.0;
    for (int i = 0; i < s.nodes; ++i) {
      double yp = s.y[i] * q.u_tau / q.nu;
      if (yp < 100.0 || yp > 800.0) continue;
      double dev = s.u[i] / q.u_tau - log(m.e_wall * yp) / m.kappa;
      double keq = (1.0 - s.y[i] / q.delta) / sqrt(m.c_mu);
      TC_CHECK(dev > -0.36 && dev < 0.36, "u+ − ln(E y+)/κ = %.3f at y+ = %.0f", dev, yp);
      worst_u = fmax(worst_u, fabs(dev));
      worst_k = fmax(worst_k, fabs(s.k[i] / (q.u_tau * q.u_tau) / keq - 1.0));
    }
    printf("log law, y+ 100-800: largest |u+ − ln(E y+)/κ| %.3f, largest k+ deviation %.2f%%\n",
           worst_u, 100.0 * worst_k);
    TC_CHECK(worst_k < 0.03, "k+ within 3%% of (1 − y/δ)/√C_μ (%.3f)", worst_k);
    channel1d_free(&s);
  }

  /* eq 41 as written (no dν_t/dy dφ/dy): reported beside the k-ε model's form */
  {
    struct channel1d_problem q = p;
    struct channel1d_model m41 = m;
    struct channel1d_solution s = {0};
    q.cells = 1600;
    m41.paper_diffusion = 1;
    TC_CHECK(channel1d_solve(&m41, &q, &s) == 0, "solve with eq 41's diffusion");
    printf("eq 41's diffusion: u_tau %.7f (%+.2f%% from the conservative form)\n", s.u_tau,
           100.0 * (s.u_tau / ut[4] - 1.0));
    TC_CHECK(fabs(s.u_tau / ut[4] - 1.0) < 0.03, "the two diffusion forms within 3%%");
    channel1d_free(&s);
  }

  /* the nodes on an SPH run's rows (cells of one spacing around them, the first cell's bottom
   * the offset wall): a steady solution, the bulk over the rows held when asked, and the same
   * limit as the node-centred grid as the rows refine (the wall layer vanishes either way) */
  {
    struct channel1d_problem q = p;
    struct channel1d_solution s = {0};
    q.cells = 0;
    int rows[3] = {1280, 2560, 5120};
    double ur[3];
    for (int g = 0; g < 3; ++g) {
      q.rows = rows[g];
      TC_CHECK(channel1d_solve(&m, &q, &s) == 0, "solve on %d rows", rows[g]);
      ur[g] = s.u_tau;
      TC_NEAR(s.y[1] - s.y[0], 2.0 * (q.delta - q.y_p) / (rows[g] - 1), 1e-12, "row spacing");
      channel1d_free(&s);
    }
    double lim = ur[2] + (ur[2] - ur[1]) * (ur[2] - ur[1]) / (ur[1] - ur[2] - (ur[0] - ur[1]));
    printf("rows 1280, 2560, 5120: u_tau %.7f %.7f %.7f, limit %.7f (%+.3f%% of the nodes')\n",
           ur[0], ur[1], ur[2], lim, 100.0 * (lim / limit - 1.0));
    TC_CHECK(fabs(lim / limit - 1.0) < 5e-4, "rows and nodes share the grid limit (%.2e)",
             lim / limit - 1.0);
    /* 20 and 21 rows: the centre plane between two rows and on one */
    for (int r = 20; r <= 21; ++r) {
      q.rows = r;
      q.bulk_over_rows = 1;
      TC_CHECK(channel1d_solve(&m, &q, &s) == 0, "solve on %d rows, the bulk over them", r);
      TC_NEAR(s.u_rows, 1.0, 1e-12, "the rows' mean velocity, %d rows", r);
      TC_CHECK(s.u_bulk < 1.0, "the bulk over [0, δ] under the rows' (%.4f)", s.u_bulk);
      double res = steady_residual(&m, &q, &s);
      TC_CHECK(res < 1e-6, "steady residual %.3g < 1e-6, %d rows", res, r);
      TC_NEAR(s.y[0], q.y_p, 1e-15, "the first row at y_p");
      printf("%d rows, the bulk over the rows: u_tau %.7f, bulk over [0, δ] %.5f\n", r, s.u_tau,
             s.u_bulk);
      channel1d_free(&s);
    }
    q.bulk_over_rows = 0;
    q.rows = 0;
    q.cells = 100;
    q.bulk_over_rows = 1;
    TC_CHECK(channel1d_solve(&m, &q, &s) != 0, "a bulk over the rows without rows is refused");
  }

  /* the SPH run's own momentum balance (offset_momentum): its fluid fills [y_w, δ], y_w = y_p −
   * Δ/2, and takes the wall's stress at y_w, so the total stress in the stream is 1/(1 − y_w/δ)
   * times the channel's at the same u_τ: a steady solution, and k, which in the stream follows
   * the local stress (k+ ≈ τ/(ρ u_τ² √C_μ) less what diffusion carries), over the plain rows' k
   * by that factor times the two u_τ's ratio squared: measured within 0.17% (40 rows) and 0.20%
   * (80) from y = 0.15 δ to the centre (below, the first rows' k is the wall function's in both,
   * 1.3% under the ratio on the first row at 80 rows), so a bound of 0.3% there */
  for (int r = 40; r <= 80; r *= 2) {
    struct channel1d_problem q = p;
    struct channel1d_solution a = {0}, b = {0};
    q.cells = 0;
    q.rows = r;
    q.bulk_over_rows = 1;
    TC_CHECK(channel1d_solve(&m, &q, &a) == 0, "solve on %d rows", r);
    q.offset_momentum = 1;
    TC_CHECK(channel1d_solve(&m, &q, &b) == 0, "solve on %d rows, the offset momentum", r);
    const double yw = q.y_p - 0.5 * (b.y[1] - b.y[0]);
    const double want = 1.0 / (1.0 - yw / q.delta) * (b.u_tau / a.u_tau) * (b.u_tau / a.u_tau);
    double worst = 0.0;
    for (int i = 0; i < b.nodes; ++i)
      if (b.y[i] >= 0.15 * q.delta) worst = fmax(worst, fabs(b.k[i] / a.k[i] / want - 1.0));
    printf("%d rows, the offset momentum (y_w %.4f): u_tau %.7f (%+.3f%%), k over the plain "
           "rows' within %.3f%% of the stress ratio\n",
           r, yw, b.u_tau, 100.0 * (b.u_tau / a.u_tau - 1.0), 100.0 * worst);
    TC_CHECK(worst < 3e-3, "k follows the stress (%.2e), %d rows", worst, r);
    TC_NEAR(b.u_rows, 1.0, 1e-12, "the rows' mean velocity, the offset momentum");
    double res = steady_residual(&m, &q, &b);
    TC_CHECK(res < 1e-6, "steady residual %.3g < 1e-6, %d rows, the offset momentum", res, r);
    channel1d_free(&a);
    channel1d_free(&b);
    q.bulk_over_rows = 0;
    TC_CHECK(channel1d_solve(&m, &q, &b) != 0, "the offset momentum without the rows' bulk");
  }

  /* the paper's backward differences (sec 5.1) and the finite volume's fluxes: other schemes for
   * the same model, first order as the default (the wall node's half cell; measured 0.98 and
   * 1.01), with the same grid limit (within 0.003%) */
  for (int scheme = 0; scheme < 2; ++scheme) {
    struct channel1d_problem q = p;
    struct channel1d_model ms = m;
    struct channel1d_solution s = {0};
    *(scheme == 0 ? &ms.backward : &ms.fv) = 1;
    double us[3];
    for (int g = 0; g < 3; ++g) {
      q.cells = 400 << g;
      TC_CHECK(channel1d_solve(&ms, &q, &s) == 0, "solve, %d cells", q.cells);
      us[g] = s.u_tau;
      channel1d_free(&s);
    }
    double o = log((us[0] - us[1]) / (us[1] - us[2])) / log(2.0);
    double lim = us[2] + (us[2] - us[1]) / (pow(2.0, o) - 1.0);
    printf("%s: u_tau %.7f %.7f %.7f at 400, 800, 1600 cells, order %.2f, limit %.7f (%+.3f%% of "
           "the default's)\n",
           scheme == 0 ? "backward differences" : "finite volume", us[0], us[1], us[2], o, lim,
           100.0 * (lim / limit - 1.0));
    TC_CHECK(o > 0.8 && o < 2.3, "observed order %.2f", o);
    TC_CHECK(fabs(lim / limit - 1.0) < 5e-4, "the same grid limit (%.2e)", lim / limit - 1.0);
  }

  /* the references of the SPH channel (cases/channel_ke.lua) are this solver's */
  if (argc > 1) {
    for (int r = 20; r <= 80; r *= 2) check_rows_file(&m, argv[1], r, 0);
    for (int r = 40; r <= 80; r *= 2) check_rows_file(&m, argv[1], r, 1);
    check_openfoam(argv[1]);
  }

  /* Leroy et al.'s wall law (eq 23: U/u_τ = ln(y u_τ/ν)/κ + 5.2, scaled by u_τ, not by
   * C_μ^¼ k_p^½): the first node sits on it exactly, the steady residual is the solver's, and
   * the stored references of cases/channel_usaw_ke.lua (e+ = 640 and Re_τ = 543.5) are its
   * solutions */
  {
    struct channel1d_model ml = m;
    ml.ustar_law = 1;
    ml.e_wall = exp(ml.kappa * 5.2);
    double yl = 11.0;
    for (int it = 0; it < 200; ++it) yl = log(ml.e_wall * yl) / ml.kappa;
    ml.y_plus_lam = yl;
    const double nus[2] = {1.5625e-3, 0.0018399264};
    const char *names[2] = {"channel1d_leroy640.csv", "channel1d_leroy543.csv"};
    for (int c = 0; c < 2; ++c) {
      struct channel1d_problem q = {
          .delta = 1.0, .nu = nus[c], .y_p = 0.025, .u_tau = 1.0, .cells = 3200};
      struct channel1d_solution s = {0};
      TC_CHECK(channel1d_solve(&ml, &q, &s) == 0, "solve with the u_tau law, nu %g", nus[c]);
      double law = log(q.y_p * q.u_tau / q.nu) / ml.kappa + 5.2;
      TC_NEAR(s.u[0] / q.u_tau, law, 1e-9, "first node on eq 23, nu %g", nus[c]);
      double res = steady_residual(&ml, &q, &s);
      TC_CHECK(res < 1e-6, "steady residual %.3g < 1e-6 (u_tau law)", res);
      printf("u_tau law, e+ %.1f: u+ at y_p %.4f, centre %.4f, k+ at y_p %.4f\n", q.u_tau / q.nu,
             law, s.u[s.nodes - 1], s.k[0]);
      if (argc > 1) {
        char path[1024];
        snprintf(path, sizeof path, "%s/%s", argv[1], names[c]);
        FILE *f = fopen(path, "r");
        TC_CHECK(f != NULL, "open %s", path);
        char line[1024];
        int row = 0, bad = 0;
        while (f != NULL && fgets(line, sizeof line, f)) {
          double y, yd, yplus, u, uplus, k;
          if (line[0] == '#' ||
              sscanf(line, "%lf,%lf,%lf,%lf,%lf,%lf", &y, &yd, &yplus, &u, &uplus, &k) != 6)
            continue;
          if (row < s.nodes)
            bad += fabs(u / s.u[row] - 1.0) > 1e-6 || fabs(k / s.k[row] - 1.0) > 1e-6;
          ++row;
        }
        if (f != NULL) fclose(f);
        TC_CHECK(row == s.nodes && bad == 0, "%s: %d of %d nodes differ from a solve now", path,
                 bad, row);
      }
      channel1d_free(&s);
    }
  }

  /* a bad problem is refused */
  {
    struct channel1d_problem q = p;
    struct channel1d_solution s = {0};
    q.cells = 100;
    q.y_p = 1.5;
    TC_CHECK(channel1d_solve(&m, &q, &s) != 0, "y_p beyond the centreline is refused");
  }
  return tc_finish("channel1d");
}
