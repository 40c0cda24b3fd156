/* test_neighbours.c: the device cell-linked list returns exactly the brute-force neighbour sets
 * on random particle clouds, in 2-D and 3-D, with and without periodic axes, after reordering;
 * the reordering applies the permutation to every field but a temporary (pset_temporary), which
 * it leaves as it was and pset_find does not know; the sort's inverse index (grid_sort_inv) is
 * that of the reordered ids; the sort is deterministic and a second sort of sorted particles is
 * the identity; a particle outside the grid raises the flag. The loop in lanes (NEIGH_FOR_LANES)
 * gives the same sets, also in a set of three particles (fewer than its lanes). The prefix sum
 * (grid_scan_run) in one work-group and in three launches equals the host's on random counts. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "clsph_config.h"
#include "kern.h"
#include "pset.h"
#include "rng.h"
#include "smoothing.h"
#include "tcheck.h"

#define MAXN 256

struct cloud_case {
  const char *name;
  int dim;
  int periodic[3];
  double hi[3];
  double h; /* smoothing length; Wendland support 2h */
  size_t n;
  int outside; /* put particle 0 outside the box (non-periodic axes only) */
  int sub;     /* cells per support radius (0: the default) */
};

/* Is j a neighbour of i by brute force (minimum image on periodic axes)? Returns 1 inside,
 * 0 outside, -1 within the round-off band around the support radius (either answer is right). */
static int brute(const struct cloud_case *c, const real *p, size_t stride, size_t i, size_t j,
                 double support)
{
  double r2 = 0.0;
  for (int a = 0; a < c->dim; ++a) {
    double d = (double)p[i * stride + (size_t)a] - (double)p[j * stride + (size_t)a];
    if (c->periodic[a]) d -= c->hi[a] * round(d / c->hi[a]);
    r2 += d * d;
  }
  double band = (CLSPH_DOUBLE ? 1e-12 : 1e-5) * support * support;
  if (r2 < support * support - band) return 1;
  if (r2 > support * support + band) return 0;
  return -1;
}

static int cmp_uint(const void *a, const void *b)
{
  cl_uint x = *(const cl_uint *)a, y = *(const cl_uint *)b;
  return (x > y) - (x < y);
}

/* grid_scan_run on random counts, in one work-group (at most GRID_SCAN_GROUP_MAX items) and in
 * three launches (more), against the host's exclusive prefix sum */
static void check_scan(const struct dev *dev, cl_program prog, const char *name)
{
  const cl_uint sizes[2] = {1000u, GRID_SCAN_GROUP_MAX + 4321u};
  struct grid_scan sc;
  memset(&sc, 0, sizeof sc);
  if (grid_scan_create(prog, &sc)) {
    TC_CHECK(0, "%s: scan kernels", name);
    return;
  }
  for (int k = 0; k < 2; ++k) {
    const cl_uint m = sizes[k];
    cl_uint *cnt = calloc(m, sizeof *cnt), *got = calloc(m, sizeof *got);
    cl_mem d_c = NULL, d_b = NULL, d_s = NULL;
    struct rng r;
    rng_seed(&r, 99 + m);
    for (cl_uint i = 0; i < m; ++i) cnt[i] = (cl_uint)(rng_uniform(&r) * 7.0);
    int bad = -1;
    if (cnt && got && !kern_buffer(dev, m * sizeof(cl_uint), cnt, &d_c, "counts") &&
        !kern_buffer(dev, ((m + 63) / 64 + 1) * sizeof(cl_uint), NULL, &d_b, "blocks") &&
        !kern_buffer(dev, m * sizeof(cl_uint), NULL, &d_s, "starts") &&
        !grid_scan_run(&sc, dev, m, d_c, d_b, d_s, NULL) &&
        !kern_read(dev, d_s, m * sizeof(cl_uint), got)) {
      bad = 0;
      cl_uint a = 0;
      for (cl_uint i = 0; i < m; ++i) {
        bad += got[i] != a;
        a += cnt[i];
      }
    }
    TC_CHECK(bad == 0, "%s: prefix sum of %u counts (%s) equals the host's (%d wrong)", name, m,
             m <= GRID_SCAN_GROUP_MAX ? "one work-group" : "three launches", bad);
    kern_release(&d_c);
    kern_release(&d_b);
    kern_release(&d_s);
    free(cnt);
    free(got);
  }
  grid_scan_destroy(&sc);
}

/* A device's neighbour lists (count, list: MAXN a particle, current indices) against brute force,
 * in original ids; returns the pairs listed. */
static long check_lists(const struct cloud_case *c, size_t n, size_t stride, double support,
                        const real *pos0, const cl_uint *id, const cl_uint *cnt,
                        const cl_uint *list, cl_uint *want, int four)
{
  long missing = 0, extra = 0, pairs = 0;
  int overflow = 0;
  for (size_t a = 0; a < n; ++a) {
    if (c->outside && id[a] == 0) continue; /* clamped into an edge cell: not a real position */
    overflow |= cnt[a] > MAXN;
    size_t m = cnt[a] < MAXN ? cnt[a] : MAXN;
    for (size_t q = 0; q < m; ++q) want[q] = id[list[a * MAXN + q]];
    qsort(want, m, sizeof *want, cmp_uint);
    pairs += (long)m;
    size_t q = 0;
    for (size_t b = 0; b < n; ++b) {
      if (c->outside && b == 0) continue;
      while (q < m && want[q] < b) ++q, ++extra; /* device listed a non-existent index */
      int in = q < m && want[q] == b;
      int bf = brute(c, pos0, stride, id[a], b, support);
      if (in) ++q;
      if (bf == 1 && !in) ++missing;
      if (bf == 0 && in) ++extra;
    }
    extra += (long)(m - q);
  }
  TC_CHECK(!overflow, "%s: test list width %d suffices", c->name, MAXN);
  TC_CHECK(missing == 0 && extra == 0,
           "%s: neighbour sets %s equal brute force (%ld pairs; %ld missing, %ld extra)", c->name,
           four ? "in lanes" : "one at a time", pairs, missing, extra);
  return pairs;
}

static void run_case(const struct dev *dev, const char *src, const struct cloud_case *c)
{
  static const char *const sources[] = {GRID_SOURCES, NULL};
  const size_t n = c->n, stride = c->dim == 2 ? 2 : 4;
  struct smoothing sm;
  struct prog_opts o = {0};
  struct grid g;
  struct pset ps;
  struct rng r;
  cl_program prog = NULL;
  cl_kernel k = NULL, k4 = NULL;
  cl_mem d_flags = NULL, d_count = NULL, d_list = NULL, d_inv = NULL;
  int i_pos = 0, i_id = 0, i_tag = 0, i_temp = 0;
  cl_uint *inv = calloc(n, sizeof *inv);
  real *temp = calloc(n, sizeof *temp);
  real *pos0 = calloc(n * stride, sizeof *pos0), *pos = calloc(n * stride, sizeof *pos);
  real *tag0 = calloc(n, sizeof *tag0), *tag = calloc(n, sizeof *tag);
  cl_uint *id0 = calloc(n, sizeof *id0), *id = calloc(n, sizeof *id);
  cl_uint *perm = calloc(n, sizeof *perm), *perm2 = calloc(n, sizeof *perm2);
  cl_uint *cnt = calloc(n, sizeof *cnt), *list = calloc(n * MAXN, sizeof *list);
  cl_uint *want = calloc(MAXN, sizeof *want), *start = NULL, flags = 0;
  const cl_uint zero = 0;

  memset(&g, 0, sizeof g);
  pset_init(&ps, n, n);
  rng_seed(&r, 1234 + n);
  for (size_t i = 0; i < n; ++i) {
    for (int a = 0; a < c->dim; ++a)
      pos0[i * stride + (size_t)a] = (real)(c->hi[a] * rng_uniform(&r));
    id0[i] = (cl_uint)i;
    tag0[i] = (real)(0.5 + (double)i);
  }
  if (c->outside) pos0[0] = (real)(-0.1 * c->hi[0]);

  struct grid_spec spec = {.dim = c->dim};
  for (int a = 0; a < 3; ++a) {
    spec.hi[a] = c->hi[a];
    spec.periodic[a] = c->periodic[a];
  }
  spec.sub = c->sub;
  if (smoothing_make(SMOOTHING_WENDLAND_C2, c->dim, c->h, &sm) != CLSPH_OK) goto fail;
  spec.support = sm.support;
  spec.sm = sm;
  if (grid_define(&spec, &o) || smoothing_define(&sm, &o) ||
      prog_build_extra(dev, sources, "tests/cl/neighbours_test.cl", src, &o, &prog) ||
      prog_kernel(prog, "test_neigh_list", &k) || prog_kernel(prog, "test_neigh_lanes", &k4) ||
      grid_create(dev, prog, &spec, n, &g))
    goto fail;
  check_scan(dev, prog, c->name);
  start = calloc(g.ncells + 1, sizeof *start);
  if (kern_buffer(dev, sizeof zero, &zero, &d_flags, "flags") ||
      kern_buffer(dev, n * sizeof(cl_uint), NULL, &d_count, "count") ||
      kern_buffer(dev, n * MAXN * sizeof(cl_uint), NULL, &d_list, "list") ||
      kern_buffer(dev, n * sizeof(cl_uint), NULL, &d_inv, "inverse") ||
      pset_add(&ps, dev, "pos", stride * sizeof(real), pos0, &i_pos) ||
      pset_add(&ps, dev, "id", sizeof(cl_uint), id0, &i_id) ||
      pset_add(&ps, dev, "temp", sizeof(real), tag0, &i_temp) ||
      pset_add(&ps, dev, "tag", sizeof(real), tag0, &i_tag))
    goto fail;
  pset_temporary(&ps, i_temp);

  /* sort with the inverse of the ids, keep the permutation, reorder */
  if (grid_sort_inv(&g, dev, n, pset_mem(&ps, i_pos), NULL, d_flags, pset_mem(&ps, i_id), d_inv) ||
      kern_read(dev, d_inv, n * sizeof(cl_uint), inv) ||
      kern_read(dev, g.d_perm, n * sizeof(cl_uint), perm) ||
      kern_read(dev, g.d_start, (g.ncells + 1) * sizeof(cl_uint), start) ||
      pset_reorder(&ps, &g, dev) ||
      kern_read(dev, pset_mem(&ps, i_pos), n * stride * sizeof(real), pos) ||
      kern_read(dev, pset_mem(&ps, i_id), n * sizeof(cl_uint), id) ||
      kern_read(dev, pset_mem(&ps, i_tag), n * sizeof(real), tag) ||
      kern_read(dev, pset_mem(&ps, i_temp), n * sizeof(real), temp) ||
      kern_read(dev, d_flags, sizeof flags, &flags))
    goto fail;
  int bad_inv = 0, bad_temp = 0;
  for (size_t k2 = 0; k2 < n; ++k2) {
    bad_inv += id[k2] >= n || inv[id[k2]] != k2;
    bad_temp += temp[k2] != tag0[k2];
  }
  TC_CHECK(bad_inv == 0, "%s: inv[id[k]] = k after the sort (%d wrong)", c->name, bad_inv);
  TC_CHECK(bad_temp == 0 && pset_find(&ps, "temp") == -1 && pset_find(&ps, "tag") == i_tag,
           "%s: the temporary left as it was (%d moved) and unknown to pset_find", c->name,
           bad_temp);

  /* the permutation, and every field reordered by it */
  int bad_field = 0, bad_perm = 0, bad_order = 0;
  memcpy(perm2, perm, n * sizeof *perm);
  qsort(perm2, n, sizeof *perm2, cmp_uint);
  for (size_t i = 0; i < n; ++i) bad_perm += perm2[i] != i;
  for (size_t k2 = 0; k2 < n; ++k2) {
    size_t o2 = perm[k2] < n ? perm[k2] : 0;
    bad_field += id[k2] != perm[k2] || tag[k2] != tag0[o2] ||
                 memcmp(&pos[k2 * stride], &pos0[o2 * stride], stride * sizeof(real)) != 0;
  }
  for (size_t cc = 0; cc < g.ncells; ++cc) {
    bad_order += start[cc] > start[cc + 1];
    for (cl_uint a = start[cc] + 1; a < start[cc + 1]; ++a) bad_order += perm[a - 1] >= perm[a];
  }
  TC_CHECK(bad_perm == 0, "%s: perm is a permutation (%d wrong)", c->name, bad_perm);
  TC_CHECK(bad_field == 0, "%s: pos, id and tag reordered by perm (%d wrong)", c->name, bad_field);
  TC_CHECK(start[g.ncells] == n && bad_order == 0,
           "%s: cell table covers all %zu particles, each cell in old-index order (%d wrong)",
           c->name, n, bad_order);
  TC_CHECK(((flags & 4u) != 0) == (c->outside != 0), "%s: escaped flag %s", c->name,
           c->outside ? "raised" : "clear");

  /* neighbour sets against brute force, in original ids: the loop one at a time (NEIGH_FOR, as
   * neigh_next) and in lanes (NEIGH_FOR4) */
  cl_uint np = (cl_uint)n, maxn = MAXN;
  cl_mem d_pos = pset_mem(&ps, i_pos);
  long pairs = 0;
  for (int four = 0; four < 2; ++four) {
    cl_kernel kl = four ? k4 : k;
    if (KERN_SET(kl, KARG(np), KARG(g.geom), KARG(g.d_start), KARG(d_pos), KARG(maxn),
                 KARG(d_count), KARG(d_list)) ||
        kern_launch(dev, kl, n, NULL) || kern_read(dev, d_count, n * sizeof(cl_uint), cnt) ||
        kern_read(dev, d_list, n * MAXN * sizeof(cl_uint), list))
      goto fail;
    pairs = check_lists(c, n, stride, sm.support, pos0, id, cnt, list, want, four);
  }
  /* a second sort of sorted particles is the identity; sorting the original again repeats perm */
  int not_identity = 0, not_repeat = 0;
  if (grid_sort(&g, dev, n, pset_mem(&ps, i_pos), NULL, d_flags) ||
      kern_read(dev, g.d_perm, n * sizeof(cl_uint), perm2))
    goto fail;
  for (size_t i = 0; i < n; ++i) not_identity += perm2[i] != i;
  if (kern_write(dev, pset_mem(&ps, i_pos), n * stride * sizeof(real), pos0) ||
      grid_sort(&g, dev, n, pset_mem(&ps, i_pos), NULL, d_flags) ||
      kern_read(dev, g.d_perm, n * sizeof(cl_uint), perm2))
    goto fail;
  for (size_t i = 0; i < n; ++i) not_repeat += perm2[i] != perm[i];
  TC_CHECK(not_identity == 0, "%s: re-sorting sorted particles is the identity (%d moved)", c->name,
           not_identity);
  TC_CHECK(not_repeat == 0, "%s: sorting is deterministic (%d differ)", c->name, not_repeat);
  printf("%-28s %zu particles, %zu cells, %.1f neighbours per particle\n", c->name, n, g.ncells,
         (double)pairs / (double)n);
  goto done;
fail:
  TC_CHECK(0, "%s: set-up and device calls succeed", c->name);
done:
  kern_release(&d_inv);
  kern_release(&d_list);
  kern_release(&d_count);
  kern_release(&d_flags);
  pset_destroy(&ps);
  grid_destroy(&g);
  if (k4 != NULL) clReleaseKernel(k4);
  if (k != NULL) clReleaseKernel(k);
  if (prog != NULL) clReleaseProgram(prog);
  prog_opts_free(&o);
  free(start);
  free(inv);
  free(temp);
  free(want);
  free(list);
  free(cnt);
  free(perm2);
  free(perm);
  free(id);
  free(id0);
  free(tag);
  free(tag0);
  free(pos);
  free(pos0);
}

int main(int argc, char **argv)
{
  struct dev dev;
  if (argc != 2) {
    printf("usage: test_neighbours NEIGHBOURS_TEST_CL\n");
    return 1;
  }
  tc_open_device(&dev);
  char *src = tc_read_text(argv[1]);
  const struct cloud_case cases[] = {
      {"2-D walls", 2, {0, 0, 0}, {1.0, 0.7, 0}, 0.025, 4000, 0, 0},
      {"2-D periodic x", 2, {1, 0, 0}, {1.0, 0.7, 0}, 0.025, 4000, 0, 0},
      {"2-D periodic x and y", 2, {1, 1, 0}, {0.62, 0.7, 0}, 0.03, 4000, 0, 0},
      {"2-D periodic, 5 cells", 2, {1, 1, 0}, {0.255, 0.26, 0}, 0.05, 300, 0, 0},
      {"2-D periodic, 3 big cells", 2, {1, 1, 0}, {0.305, 0.31, 0}, 0.05, 400, 0, 1},
      {"2-D walls, 3 cells/support", 2, {0, 0, 0}, {1.0, 0.7, 0}, 0.025, 4000, 0, 3},
      {"2-D one particle outside", 2, {0, 0, 0}, {1.0, 1.0, 0}, 0.025, 3000, 1, 0},
      {"2-D three particles", 2, {0, 0, 0}, {0.2, 0.2, 0}, 0.05, 3, 0, 0},
      {"3-D walls", 3, {0, 0, 0}, {1.0, 0.8, 0.6}, 0.06, 4000, 0, 0},
      {"3-D periodic x, y, z", 3, {1, 1, 1}, {1.0, 0.8, 0.6}, 0.06, 4000, 0, 0},
      {"3-D periodic x, big cells", 3, {1, 0, 0}, {1.0, 0.8, 0.6}, 0.06, 4000, 0, 1},
  };
  for (size_t i = 0; i < sizeof cases / sizeof *cases; ++i) run_case(&dev, src, &cases[i]);
  free(src);
  dev_close(&dev);
  return tc_finish("test_neighbours");
}
