/* field.c: the value a frame shows at each particle, and its automatic colour range.
 *
 * A field is a stored array (`p`, `rho`, ...), a component of one (`vel_x`), or derived: the
 * speed |vel|, and the vorticity, which no scheme stores and which is computed here on the host
 * from the particles. Vorticity by a corrected SPH gradient (Bonet & Lok 1999; the correction
 * makes it exact for a linear velocity field, also where the support is cut by a wall or a free
 * surface): with r_ij = x_i − x_j, ∇_i W_ij = F(r) r_ij (kernels/common/smoothing.h) and V_j the
 * particle volumes,
 *   M_i = Σ_j V_j (x_j − x_i) ⊗ ∇_i W_ij,   D_i = Σ_j V_j (v_j − v_i) ⊗ ∇_i W_ij,
 *   ∇v_i = D_i M_i⁻¹   (for v linear, v_j − v_i = G (x_j − x_i), so D_i = G M_i),
 *   ω_i = ∂v/∂x − ∂u/∂y = (∇v_i)_yx − (∇v_i)_xy,
 * summed over every particle within the support (wall vertex particles carry the wall velocity,
 * which gives the shear at a moving wall). M_i = I inside the fluid, diag(1/2, 1/2) on a straight
 * edge, det M_i = 0.6 (tr M_i / 2)² in a right-angled corner; where it is nearly singular
 * (det M_i <= 0.01 (tr M_i / 2)², neighbours almost on a line, or tr M_i <= 0.02, almost none)
 * the uncorrected ∇v_i = D_i is used. The smoothing function is Wendland C2
 * with h = 2 δr, δr = √(median V), support 2h (Leroy et al. 2014 eq 1): F(r) = −5 α t³ / h²,
 * t = 1 − r/2h, α = 7 / (4π h²). Neighbours come from a grid of square cells of the support's
 * size. Periodic images are not searched: near a periodic boundary the gradient is one-sided
 * (still exact for linear fields through M). The particles' sums run on OpenMP threads. */
#include "render.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define KIND_FLUID   0
#define KIND_INFLOW  3
#define KIND_OUTFLOW 4

/* ---- names ---- */

struct label {
  const char *name, *label;
};

/* Colour bar titles of the fields we know; others show their name. */
static const struct label labels[] = {
    {"speed", "speed |u| (m/s)"},
    {"vorticity", "vorticity ω (1/s)"},
    {"vel_x", "velocity u (m/s)"},
    {"vel_y", "velocity v (m/s)"},
    {"vel_z", "velocity w (m/s)"},
    {"p", "pressure p (Pa)"},
    {"rho", "density ρ (kg/m³)"},
    {"k", "turbulent kinetic energy k (m²/s²)"},
    {"eps", "dissipation ε (m²/s³)"},
    {"gamma", "wall renormalisation γ"},
    {"div_r", "divergence of position ∇·r"},
    {"free_surface", "free surface (1: on it)"},
    {"vol", "volume V (m²)"},
    {"kind", "particle kind"},
    {"pos_x", "x (m)"},
    {"pos_y", "y (m)"},
    {"pos_z", "z (m)"},
};

static void set_label(struct field_spec *f)
{
  for (size_t k = 0; k < sizeof labels / sizeof *labels; ++k) {
    if (strcmp(labels[k].name, f->name) == 0) {
      snprintf(f->label, sizeof f->label, "%s", labels[k].label);
      return;
    }
  }
  snprintf(f->label, sizeof f->label, "%s", f->name);
}

static int find_name(int narrays, const char *const *names, const char *name)
{
  for (int k = 0; k < narrays; ++k)
    if (strcmp(names[k], name) == 0) return k;
  return -1;
}

/* "speed, vorticity, vel_x, ...": every field the arrays give. */
static void list_fields(int narrays, const char *const *names, const int *ncomp, char *buf,
                        size_t size)
{
  size_t used = 0;
  buf[0] = '\0';
#define ADD(...)                                                                                   \
  do {                                                                                             \
    if (used < size) used += (size_t)snprintf(buf + used, size - used, __VA_ARGS__);               \
  } while (0)
  int vel = find_name(narrays, names, "vel");
  if (vel >= 0 && ncomp[vel] == 2) ADD("speed, vorticity, vel_x, vel_y");
  if (vel >= 0 && ncomp[vel] == 3) ADD("speed, vel_x, vel_y, vel_z"); /* (vorticity: 2-D) */
  for (int k = 0; k < narrays; ++k) {
    if (k == vel) continue;
    if (ncomp[k] == 1)
      ADD("%s%s", used ? ", " : "", names[k]);
    else if (ncomp[k] == 2)
      ADD("%s%s_x, %s_y", used ? ", " : "", names[k], names[k]);
    else if (ncomp[k] >= 3)
      ADD("%s%s_x, %s_y, %s_z", used ? ", " : "", names[k], names[k], names[k]);
  }
#undef ADD
}

enum clsph_status field_find(const char *name, int narrays, const char *const *names,
                             const int *ncomp, struct field_spec *out)
{
  enum clsph_status st = CLSPH_OK;
  struct field_spec f;
  char list[1024];
  memset(&f, 0, sizeof f);
  CLSPH_CHECK(strlen(name) > 0 && strlen(name) < RENDER_NAME, CLSPH_E_INPUT,
              "field name '%s' is empty or too long", name);
  snprintf(f.name, sizeof f.name, "%s", name);
  int vel = find_name(narrays, names, "vel");
  int has_vel = vel >= 0 && ncomp[vel] >= 2;
  const int k = find_name(narrays, names, name);
  const size_t len = strlen(name);
  if (has_vel && strcmp(name, "speed") == 0) {
    f.how = FIELD_SPEED;
    snprintf(f.array, sizeof f.array, "vel");
  } else if (has_vel && strcmp(name, "vorticity") == 0) {
    f.how = FIELD_VORTICITY;
    f.is_signed = 1;
    snprintf(f.array, sizeof f.array, "vel");
  } else if (k >= 0 && ncomp[k] == 1) {
    f.how = strcmp(name, "kind") == 0 ? FIELD_KIND : FIELD_SCALAR;
    snprintf(f.array, sizeof f.array, "%s", name);
  } else if (len > 2 && name[len - 2] == '_' &&
             (name[len - 1] == 'x' || name[len - 1] == 'y' || name[len - 1] == 'z')) {
    char base[RENDER_NAME];
    snprintf(base, sizeof base, "%.*s", (int)(len - 2), name);
    const int b = find_name(narrays, names, base);
    const int comp = name[len - 1] - 'x';
    if (b >= 0 && ncomp[b] >= 2 && comp < ncomp[b]) {
      f.how = FIELD_COMPONENT;
      f.comp = comp;
      f.is_signed = 1;
      snprintf(f.array, sizeof f.array, "%s", base);
    }
  }
  if (f.array[0] == '\0') {
    list_fields(narrays, names, ncomp, list, sizeof list);
    CLSPH_CHECK(0, CLSPH_E_INPUT, "unknown field '%s'; fields: %s", name, list);
  }
  set_label(&f);
  *out = f;
done:
  return st;
}

const struct render_array *field_array(const struct render_input *in, const char *name)
{
  for (int k = 0; k < in->narrays; ++k)
    if (strcmp(in->arrays[k].name, name) == 0) return &in->arrays[k];
  return NULL;
}

int field_drawn(const struct field_spec *f, int kind)
{
  return f->how == FIELD_KIND || kind == KIND_FLUID || kind == KIND_INFLOW || kind == KIND_OUTFLOW;
}

/* ---- values ---- */

enum clsph_status field_values(const struct field_spec *f, const struct render_input *in,
                               double *out)
{
  enum clsph_status st = CLSPH_OK;
  const struct render_array *a = field_array(in, f->array);
  const size_t n = in->n;
  CLSPH_CHECK(a != NULL, CLSPH_E_INPUT, "field '%s' needs the array '%s', which is missing",
              f->name, f->array);
  const size_t nc = (size_t)a->ncomp;
  switch (f->how) {
  case FIELD_SCALAR:
  case FIELD_KIND:
    for (size_t i = 0; i < n; ++i) out[i] = a->v[i * nc];
    break;
  case FIELD_COMPONENT:
    for (size_t i = 0; i < n; ++i) out[i] = a->v[i * nc + (size_t)f->comp];
    break;
  case FIELD_SPEED: /* (a 3-D slice's velocities keep their three components) */
    for (size_t i = 0; i < n; ++i)
      out[i] = hypot(hypot(a->v[i * nc], a->v[i * nc + 1]), nc > 2 ? a->v[i * nc + 2] : 0.0);
    break;
  case FIELD_VORTICITY: {
    const struct render_array *pos = field_array(in, "pos"), *vol = field_array(in, "vol");
    CLSPH_CHECK(pos != NULL && vol != NULL && nc == 2 && pos->ncomp == 2, CLSPH_E_INPUT,
                "vorticity needs pos and vel (2 components) and vol");
    CLSPH_TRY(field_vorticity(n, pos->v, a->v, vol->v, out));
    break;
  }
  }
done:
  return st;
}

/* The k-th smallest of a[0 .. n-1] (0-based; a is reordered): quickselect with median-of-three
 * pivots, deterministic. */
static double select_kth(double *a, size_t n, size_t k)
{
  size_t lo = 0, hi = n - 1;
  while (hi > lo) {
    size_t mid = lo + (hi - lo) / 2;
    double x = a[lo], y = a[mid], z = a[hi];
    double pivot = x < y ? (y < z ? y : (x < z ? z : x)) : (x < z ? x : (y < z ? z : y));
    size_t i = lo, j = hi;
    while (i <= j) {
      while (a[i] < pivot) ++i;
      while (a[j] > pivot) --j;
      if (i <= j) {
        double t = a[i];
        a[i] = a[j];
        a[j] = t;
        ++i;
        if (j == 0) break;
        --j;
      }
    }
    if (k <= j)
      hi = j;
    else if (k >= i)
      lo = i;
    else
      return a[k];
  }
  return a[k];
}

enum clsph_status field_vorticity(size_t n, const double *pos, const double *vel, const double *vol,
                                  double *out)
{
  enum clsph_status st = CLSPH_OK;
  double *tmp = NULL;
  size_t *start = NULL, *order = NULL, *cell = NULL;
  if (n == 0) goto done;
  tmp = malloc(n * sizeof *tmp);
  cell = malloc(n * sizeof *cell);
  order = malloc(n * sizeof *order);
  CLSPH_CHECK(tmp != NULL && cell != NULL && order != NULL, CLSPH_E_NOMEM,
              "out of memory for the vorticity of %zu particles", n);
  /* the spacing from the median volume; h = 2 δr, support 2h */
  memcpy(tmp, vol, n * sizeof *tmp);
  double dr = sqrt(fabs(select_kth(tmp, n, n / 2)));
  CLSPH_CHECK(dr > 0.0 && isfinite(dr), CLSPH_E_INPUT,
              "vorticity: the particle volumes give no spacing (median volume %g)", dr * dr);
  const double h = 2.0 * dr, support = 2.0 * h, support2 = support * support;
  const double alpha = 7.0 / (4.0 * 3.14159265358979323846 * h * h), f0 = -5.0 * alpha / (h * h);
  /* the cell grid over the particles' box (capped at 4n cells: a far stray particle widens the
   * cells, which costs time, not correctness) */
  double lo[2] = {HUGE_VAL, HUGE_VAL}, hi[2] = {-HUGE_VAL, -HUGE_VAL};
  for (size_t i = 0; i < n; ++i) {
    for (int a = 0; a < 2; ++a) {
      double x = pos[2 * i + a];
      if (!isfinite(x)) continue;
      lo[a] = fmin(lo[a], x);
      hi[a] = fmax(hi[a], x);
    }
  }
  if (!(hi[0] >= lo[0])) lo[0] = hi[0] = lo[1] = hi[1] = 0.0;
  double cs = support;
  size_t nc[2];
  for (;;) {
    nc[0] = (size_t)((hi[0] - lo[0]) / cs) + 1;
    nc[1] = (size_t)((hi[1] - lo[1]) / cs) + 1;
    if ((double)nc[0] * (double)nc[1] <= 4.0 * (double)n + 16.0) break;
    cs *= 2.0;
  }
  const size_t ncells = nc[0] * nc[1];
  start = calloc(ncells + 1, sizeof *start);
  CLSPH_CHECK(start != NULL, CLSPH_E_NOMEM, "out of memory for the vorticity grid");
  for (size_t i = 0; i < n; ++i) {
    double x = pos[2 * i], y = pos[2 * i + 1];
    size_t cx = isfinite(x) ? (size_t)((x - lo[0]) / cs) : 0;
    size_t cy = isfinite(y) ? (size_t)((y - lo[1]) / cs) : 0;
    cell[i] = (cy < nc[1] ? cy : nc[1] - 1) * nc[0] + (cx < nc[0] ? cx : nc[0] - 1);
    ++start[cell[i] + 1];
  }
  for (size_t c = 0; c < ncells; ++c) start[c + 1] += start[c];
  {
    size_t *fill = malloc(ncells * sizeof *fill);
    CLSPH_CHECK(fill != NULL, CLSPH_E_NOMEM, "out of memory for the vorticity grid");
    memcpy(fill, start, ncells * sizeof *fill);
    for (size_t i = 0; i < n; ++i) order[fill[cell[i]]++] = i; /* stable: i ascending per cell */
    free(fill);
  }
  /* the sums: each particle's own, in a fixed order (threads change nothing in the result) */
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < n; ++i) {
    const double xi = pos[2 * i], yi = pos[2 * i + 1], ui = vel[2 * i], vi = vel[2 * i + 1];
    double m[2][2] = {{0.0, 0.0}, {0.0, 0.0}}, d[2][2] = {{0.0, 0.0}, {0.0, 0.0}};
    const size_t cx = cell[i] % nc[0], cy = cell[i] / nc[0];
    for (size_t y = cy > 0 ? cy - 1 : 0; y <= cy + 1 && y < nc[1]; ++y) {
      for (size_t x = cx > 0 ? cx - 1 : 0; x <= cx + 1 && x < nc[0]; ++x) {
        const size_t c = y * nc[0] + x;
        for (size_t s = start[c]; s < start[c + 1]; ++s) {
          const size_t j = order[s];
          const double rx = xi - pos[2 * j], ry = yi - pos[2 * j + 1];
          const double r2 = rx * rx + ry * ry;
          if (j == i || !(r2 < support2)) continue;
          const double t = 1.0 - 0.5 * sqrt(r2) / h;
          const double fr = f0 * t * t * t * vol[j]; /* V_j F(r) */
          const double gx = fr * rx, gy = fr * ry;   /* V_j ∇_i W_ij */
          const double du = vel[2 * j] - ui, dv = vel[2 * j + 1] - vi;
          m[0][0] -= rx * gx; /* x_j − x_i = −r_ij */
          m[0][1] -= rx * gy;
          m[1][0] -= ry * gx;
          m[1][1] -= ry * gy;
          d[0][0] += du * gx;
          d[0][1] += du * gy;
          d[1][0] += dv * gx;
          d[1][1] += dv * gy;
        }
      }
    }
    const double det = m[0][0] * m[1][1] - m[0][1] * m[1][0], tr = m[0][0] + m[1][1];
    double dvdx = d[1][0], dudy = d[0][1];
    if (tr > 0.02 && det > 0.0025 * tr * tr) { /* ∇v = D M⁻¹; M⁻¹ = [m11 −m01; −m10 m00] / det */
      dvdx = (d[1][0] * m[1][1] - d[1][1] * m[1][0]) / det;
      dudy = (-d[0][0] * m[0][1] + d[0][1] * m[0][0]) / det;
    }
    out[i] = dvdx - dudy;
  }
done:
  free(start);
  free(order);
  free(cell);
  free(tmp);
  return st;
}

double field_spacing(const struct field_spec *f, size_t n, const double *vol, const double *kind)
{
  double *tmp = malloc((n > 0 ? n : 1) * sizeof *tmp), dr = 0.0;
  size_t m = 0;
  if (tmp == NULL) return 0.0;
  for (size_t i = 0; i < n; ++i)
    if (field_drawn(f, (int)kind[i]) && vol[i] > 0.0 && isfinite(vol[i])) tmp[m++] = vol[i];
  if (m > 0) dr = sqrt(select_kth(tmp, m, m / 2));
  free(tmp);
  return dr;
}

/* ---- colour range ---- */

size_t field_percentiles(const struct field_spec *f, size_t n, const double *v, const double *kind,
                         double *lo, double *hi)
{
  double *tmp = malloc((n > 0 ? n : 1) * sizeof *tmp);
  size_t m = 0;
  if (tmp != NULL) {
    for (size_t i = 0; i < n; ++i)
      if (field_drawn(f, (int)kind[i]) && isfinite(v[i])) tmp[m++] = v[i];
  }
  if (m > 0) {
    /* entries ⌊0.005 (m − 1)⌋ and ⌈0.995 (m − 1)⌉: the extremes for fewer than 200 values */
    size_t klo = (size_t)floor(0.005 * (double)(m - 1));
    size_t khi = (size_t)ceil(0.995 * (double)(m - 1));
    *lo = select_kth(tmp, m, klo);
    *hi = select_kth(tmp, m, khi);
  }
  free(tmp);
  return m;
}

void field_range_rules(const struct field_spec *f, enum colormap_kind map, int have, double *lo,
                       double *hi)
{
  double a = have ? *lo : 0.0, b = have ? *hi : 1.0;
  if (f->how == FIELD_SPEED) a = 0.0;
  if (map == COLORMAP_COOLWARM) {
    b = fmax(fabs(a), fabs(b));
    a = -b;
  }
  if (!(b > a)) { /* flat: a range around the value */
    double c = 0.5 * (a + b), w = c != 0.0 ? 0.1 * fabs(c) : 1.0;
    a = f->how == FIELD_SPEED && c == 0.0 ? 0.0 : c - w;
    b = c + w;
  }
  *lo = a;
  *hi = b;
}

void field_auto_range(const struct field_spec *f, enum colormap_kind map, size_t n, const double *v,
                      const double *kind, double *lo, double *hi)
{
  const int have = field_percentiles(f, n, v, kind, lo, hi) > 0;
  field_range_rules(f, map, have, lo, hi);
}
