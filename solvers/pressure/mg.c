/* mg.c: set-up and V-cycle of the aggregation multigrid preconditioner (see mg.h, mg.cl). */
#include "mg.h"

#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "clsph_config.h"
#include "log.h"

/* Jacobi damping: 2/3 is the classic choice for the 5-point Laplacian; on the particle
 * Laplacian (about 50 neighbours) 0.7 gave the fewest BiCGStab iterations of 0.5-0.9. */
#define MG_OMEGA 0.7

enum clsph_status mg_create(const struct dev *dev, cl_program prog, size_t cap, struct mg *out)
{
  enum clsph_status st = CLSPH_OK;
  struct mg mg;
  memset(&mg, 0, sizeof mg);
  mg.dev = dev;
  mg.omega = MG_OMEGA;
  mg.cap = cap > 0 ? cap : 1;
  struct {
    cl_kernel *k;
    const char *name;
  } ks[] = {{&mg.k_aggregate, "mg_aggregate"},
            {&mg.k_ap_csr, "mg_ap_csr"},
            {&mg.k_restrict_csr, "mg_restrict_csr"},
            {&mg.k_galerkin_ap, "mg_galerkin_ap"},
            {&mg.k_galerkin, "mg_galerkin"},
            {&mg.k_weights, "mg_weights"},
            {&mg.k_setup_block, "mg_setup_block"},
            {&mg.k_down_csr, "mg_down_csr"},
            {&mg.k_up_csr, "mg_up_csr"},
            {&mg.k_down, "mg_down"},
            {&mg.k_up, "mg_up"},
            {&mg.k_block, "mg_block"},
            {&mg.k_coarsest, "mg_coarsest"}};
  for (size_t i = 0; i < sizeof ks / sizeof *ks; ++i)
    CLSPH_TRY(prog_kernel(prog, ks[i].name, ks[i].k));
  /* the block's work-group: as wide as the kernel allows, at most 256 items */
  size_t wg = 0;
  CLSPH_CL_TRY(clGetKernelWorkGroupInfo(mg.k_block, dev->id, CL_KERNEL_WORK_GROUP_SIZE, sizeof wg,
                                        &wg, NULL));
  mg.block_wg = wg < 256 ? (wg > 0 ? wg : 1) : 256;
  CLSPH_CL_TRY(clGetKernelWorkGroupInfo(mg.k_setup_block, dev->id, CL_KERNEL_WORK_GROUP_SIZE,
                                        sizeof wg, &wg, NULL));
  mg.setup_wg = wg < 256 ? (wg > 0 ? wg : 1) : 256;
  CLSPH_CL_TRY(clGetKernelWorkGroupInfo(mg.k_coarsest, dev->id, CL_KERNEL_WORK_GROUP_SIZE,
                                        sizeof wg, &wg, NULL));
  mg.coarse_wg = wg < MG_COARSE_WG ? (wg > 0 ? wg : 1) : MG_COARSE_WG;
  const cl_uint zero = 0;
  CLSPH_TRY(kern_buffer(dev, sizeof zero, &zero, &mg.d_flag, "multigrid coarsest flag"));
  const cl_uint zeros[MG_MAX_LEVELS + 1] = {0};
  CLSPH_TRY(kern_buffer(dev, sizeof zeros, zeros, &mg.d_nlist, "multigrid level counts"));
  mg.live1 = UINT_MAX;
  CLSPH_TRY(kern_buffer(dev, mg.cap * sizeof(cl_uint), NULL, &mg.d_agg, "multigrid aggregates"));
  CLSPH_TRY(kern_buffer(dev, mg.cap * sizeof(cl_uint), NULL, &mg.d_cell, "multigrid cells"));
  CLSPH_TRY(kern_buffer(dev, mg.cap * sizeof(real), NULL, &mg.d_dw, "multigrid vector"));
  CLSPH_TRY(kern_buffer(dev, mg.cap * sizeof(real), NULL, &mg.d_res, "multigrid vector"));
  CLSPH_TRY(kern_buffer(dev, mg.cap * sizeof(real), NULL, &mg.d_t, "multigrid vector"));
  *out = mg;
  memset(&mg, 0, sizeof mg);
done:
  mg_destroy(&mg);
  return st;
}

static void release_levels(struct mg *mg)
{
  cl_mem *ms[] = {&mg->d_S,    &mg->d_nb, &mg->d_pnb,   &mg->d_par, &mg->d_cdw,
                  &mg->d_live, &mg->d_b,  &mg->d_t_c,   &mg->d_x,   &mg->d_info,
                  &mg->d_M,    &mg->d_AP, &mg->d_dense, &mg->d_list};
  for (size_t i = 0; i < sizeof ms / sizeof *ms; ++i) kern_release(ms[i]);
  mg->nlevels = 0;
  mg->grid = NULL;
}

/* Cell a + offset o of a level's stencil (radius R), wrapped on a periodic axis: its id, or
 * MG_NONE outside the grid (mg_neighbour in mg.cl). */
static cl_uint stencil_cell(const struct mg_level *v, const int a[3], int o, const int periodic[3])
{
  const int w = 2 * v->R + 1;
  const int off[3] = {o % w - v->R, (o / w) % w - v->R, v->W > w * w ? o / (w * w) - v->R : 0};
  int b[3];
  for (int ax = 0; ax < 3; ++ax) {
    const int n = v->n.s[ax];
    b[ax] = a[ax] + off[ax];
    if (b[ax] >= 0 && b[ax] < n) continue;
    if (!periodic[ax]) return MG_NONE;
    b[ax] = ((b[ax] % n) + n) % n;
  }
  return (cl_uint)(b[0] + v->n.s[0] * (b[1] + v->n.s[1] * b[2]));
}

/* The stencils' neighbour cells (nb), their parents on the next level (pnb) and each cell's parent
 * (par), for levels 1 .. nlevels laid out as d_S (so entries) and the vectors (vo). */
static enum clsph_status tables(struct mg *mg, const struct grid *g, size_t so, size_t vo)
{
  enum clsph_status st = CLSPH_OK;
  cl_uint *nb = malloc(so * sizeof *nb), *pnb = malloc(so * sizeof *pnb);
  cl_uint *par = malloc(vo * sizeof *par);
  const int periodic[3] = {g->spec.periodic[0], g->spec.periodic[1],
                           g->spec.dim == 3 ? g->spec.periodic[2] : 0};
  CLSPH_CHECK(nb && pnb && par, CLSPH_E_NOMEM, "out of memory for the multigrid tables");
  for (int l = 1; l <= mg->nlevels; ++l) {
    const struct mg_level *v = &mg->lv[l], *c = l < mg->nlevels ? &mg->lv[l + 1] : NULL;
    const int *n = v->n.s;
    for (int I = 0; I < n[3]; ++I) {
      const int a[3] = {I % n[0], (I / n[0]) % n[1], I / (n[0] * n[1])};
      par[v->vo + (size_t)I] =
          c ? (cl_uint)(a[0] / 2 + c->n.s[0] * (a[1] / 2 + c->n.s[1] * (a[2] / 2))) : MG_NONE;
      for (int o = 0; o < v->W; ++o) {
        const size_t k = v->so + (size_t)I * (size_t)v->W + (size_t)o;
        const cl_uint J = stencil_cell(v, a, o, periodic);
        nb[k] = J;
        pnb[k] = J;
        if (J == MG_NONE || !c) {
          pnb[k] = MG_NONE;
          continue;
        }
        const int b[3] = {(int)J % n[0], ((int)J / n[0]) % n[1], (int)J / (n[0] * n[1])};
        pnb[k] = (cl_uint)(b[0] / 2 + c->n.s[0] * (b[1] / 2 + c->n.s[1] * (b[2] / 2)));
      }
    }
  }
  CLSPH_TRY(kern_buffer(mg->dev, so * sizeof *nb, nb, &mg->d_nb, "multigrid tables"));
  CLSPH_TRY(kern_buffer(mg->dev, so * sizeof *pnb, pnb, &mg->d_pnb, "multigrid tables"));
  CLSPH_TRY(kern_buffer(mg->dev, vo * sizeof *par, par, &mg->d_par, "multigrid tables"));
done:
  free(par);
  free(pnb);
  free(nb);
  return st;
}

/* The levels of a grid: its cells, then halved along every axis of more than one cell until at
 * most MG_COARSEST cells are left; their stencils and vectors one after the other. */
static enum clsph_status size_levels(struct mg *mg, const struct grid *g)
{
  enum clsph_status st = CLSPH_OK;
  const int dim = g->spec.dim, sub = g->spec.sub > 0 ? g->spec.sub : GRID_SUB_DEFAULT;
  cl_int info[(MG_MAX_LEVELS + 1) * MG_INFO];
  release_levels(mg);
  memset(info, 0, sizeof info);
  int n[3] = {g->n[0], g->n[1], dim == 3 ? g->n[2] : 1};
  size_t so = 0, vo = 0;
  mg->l0_cells = 0;
  for (int l = 1;; ++l) {
    CLSPH_CHECK(l <= MG_MAX_LEVELS, CLSPH_E_INPUT, "multigrid: more than %d levels", MG_MAX_LEVELS);
    struct mg_level *v = &mg->lv[l];
    const size_t cells = (size_t)n[0] * (size_t)n[1] * (size_t)n[2];
    v->R = l == 1 ? sub : 1;
    const int w = 2 * v->R + 1;
    v->W = dim == 2 ? w * w : w * w * w;
    for (int a = 0; a < 3; ++a) v->n.s[a] = n[a];
    v->n.s[3] = (cl_int)cells;
    v->so = so;
    v->vo = vo;
    so += cells * (size_t)v->W;
    vo += cells;
    const cl_int row[MG_INFO] = {n[0], n[1],          n[2],          (cl_int)cells,
                                 v->W, (cl_int)v->so, (cl_int)v->vo, 0};
    memcpy(info + MG_INFO * l, row, sizeof row);
    if (mg->l0_cells == 0 && cells <= MG_BLOCK) mg->l0_cells = l;
    mg->nlevels = l;
    if (cells <= MG_COARSEST || (n[0] == 1 && n[1] == 1 && n[2] == 1)) break;
    for (int a = 0; a < 3; ++a) n[a] = (n[a] + 1) / 2;
  }
  CLSPH_CHECK(so < 0x7fffffffu, CLSPH_E_INPUT, "multigrid: %zu stencil entries are too many", so);
  if (mg->l0_cells == 0) mg->l0_cells = mg->nlevels;
  mg->l0 = mg->l0_cells;
  CLSPH_TRY(kern_buffer(mg->dev, so * MG_REAL_SIZE, NULL, &mg->d_S, "multigrid stencils"));
  CLSPH_TRY(tables(mg, g, so, vo));
  cl_mem *vs[] = {&mg->d_cdw, &mg->d_b, &mg->d_t_c, &mg->d_x};
  for (size_t i = 0; i < sizeof vs / sizeof *vs; ++i)
    CLSPH_TRY(kern_buffer(mg->dev, vo * sizeof(real), NULL, vs[i], "multigrid vectors"));
  CLSPH_TRY(kern_buffer(mg->dev, vo * sizeof(cl_uchar), NULL, &mg->d_live, "multigrid vectors"));
  CLSPH_TRY(kern_buffer(mg->dev, vo * sizeof(cl_uint), NULL, &mg->d_list, "multigrid vectors"));
  CLSPH_TRY(kern_buffer(mg->dev, sizeof info, info, &mg->d_info, "multigrid levels"));
  CLSPH_TRY(kern_buffer(mg->dev, mg->cap * (size_t)mg->lv[1].W * MG_REAL_SIZE, NULL, &mg->d_AP,
                        "multigrid fine-to-coarse operator"));
  const struct mg_level *c = &mg->lv[mg->nlevels];
  mg->m = (size_t)c->n.s[3];
  CLSPH_TRY(kern_buffer(mg->dev, mg->m * mg->m * sizeof(real), NULL, &mg->d_M,
                        "multigrid coarsest inverse"));
  /* mg_coarsest's work in kreal: double where the device has it (krylov.cl) */
  const size_t kr = CLSPH_DOUBLE || mg->dev->fp64 ? sizeof(double) : sizeof(float);
  CLSPH_TRY(
      kern_buffer(mg->dev, 3 * mg->m * mg->m * kr, NULL, &mg->d_dense, "multigrid coarsest work"));
  mg->grid = g;
done:
  return st;
}

/* The coarsest level's dense inverse, on the device (mg_coarsest in mg.cl: an empty cell is an
 * identity row, a singular operator is reinforced, then Jacobi); its flag comes to the host with
 * the solve's first wait (mg_report). */
static enum clsph_status coarsest(struct mg *mg)
{
  enum clsph_status st = CLSPH_OK;
  const struct mg_level *c = &mg->lv[mg->nlevels];
  const cl_uint so = (cl_uint)c->so, m = (cl_uint)mg->m;
  CLSPH_TRY(KERN_SET(mg->k_coarsest, KARG(c->n), KARG(c->R), KARG(c->W), KARG(so), KARG(m),
                     KARG(mg->d_S), KARG(mg->d_dense), KARG(mg->d_M), KARG(mg->d_flag)));
  CLSPH_TRY(kern_launch_wg(mg->dev, mg->k_coarsest, mg->coarse_wg, mg->coarse_wg, NULL));
  CLSPH_TRY(kern_read_nb(mg->dev, mg->d_flag, 0, sizeof mg->h_flag, &mg->h_flag));
done:
  return st;
}

void mg_report(struct mg *mg)
{
  if (mg->h_flag != 0u && !mg->warned_singular) {
    log_warn("multigrid: the coarsest operator (%zu cells) is singular; Jacobi on that level",
             mg->m);
    mg->warned_singular = 1;
  }
  mg->h_flag = 0u;
}

enum clsph_status mg_setup(struct mg *mg, const struct grid *g, size_t n, cl_mem row, cl_mem col,
                           cl_mem val, cl_mem valm, double eps, cl_mem dinv)
{
  enum clsph_status st = CLSPH_OK;
  CLSPH_CHECK(n <= mg->cap, CLSPH_E_INPUT, "multigrid: %zu unknowns exceed %zu", n, mg->cap);
  CLSPH_CHECK(g->sorted == n, CLSPH_E_INPUT,
              "multigrid: the operator has %zu unknowns but its grid sorts %zu particles", n,
              g->sorted);
  if (mg->grid != g || mg->lv[1].n.s[3] != (cl_int)g->ncells) CLSPH_TRY(size_levels(mg, g));
  const cl_uint ncells = (cl_uint)g->ncells, nn = (cl_uint)n;
  const real e = (real)eps, omega = (real)mg->omega;
  /* fine level: aggregates, damped inverse diagonal */
  CLSPH_TRY(KERN_SET(mg->k_aggregate, KARG(ncells), KARG(g->d_start), KARG(row), KARG(val),
                     KARG(mg->d_agg), KARG(mg->d_cell)));
  CLSPH_TRY(kern_launch(mg->dev, mg->k_aggregate, ncells, NULL));
  CLSPH_TRY(KERN_SET(mg->k_ap_csr, KARG(nn), KARG(mg->lv[1].n), KARG(row), KARG(col), KARG(val),
                     KARG(mg->d_agg), KARG(mg->d_cell), KARG(e), KARG(mg->d_AP), KARG(valm),
                     KARG(omega), KARG(dinv), KARG(mg->d_dw)));
  CLSPH_TRY(kern_launch(mg->dev, mg->k_ap_csr, n, NULL)); /* and dw = ω dinv */
  /* The block starts at level 1 where the last solve's level 1 held at most MG_BLOCK cells with
   * fluid (its read has completed: the solve waited for its state after it), else where the
   * levels' cells fit. In the wedge dam break (δr = 0.01 m: 14,500 level-1 cells, about 1,600
   * with water) that saves 3 of the cycle's 6 launches for the same device time on 2 cores. */
  if (mg->live1_read) mg->live1 = mg->h_live1;
  mg->l0 = mg->live1 <= MG_BLOCK && mg->lv[1].n.s[3] <= MG_BLOCK_CELLS ? 1 : mg->l0_cells;
  const cl_uint zero = 0u;
  CLSPH_TRY(
      kern_fill(mg->dev, mg->d_nlist, &zero, sizeof zero, (MG_MAX_LEVELS + 1) * sizeof(cl_uint)));
  /* Galerkin operators, level by level */
  struct mg_level *v = &mg->lv[1];
  CLSPH_TRY(KERN_SET(mg->k_galerkin_ap, KARG(ncells), KARG(g->d_start), KARG(mg->d_agg),
                     KARG(mg->d_AP), KARG(mg->d_S)));
  CLSPH_TRY(kern_launch(mg->dev, mg->k_galerkin_ap, ncells, NULL));
  /* the levels that fit the block in one work-group (mg_setup_block), the others a launch each:
   * on the 40² cavity 1 launch a solve instead of 5, whose 96 µs of device time the one core of
   * the block's work-group takes 140 to 200 µs for on the 2-core CPU; whole runs of the cavity to
   * t = 1 s took 0.99 (60²) and 1.005 (40²) of the time with a launch a level (medians of 7 and
   * 5 interleaved pairs) */
  const int lb = mg->l0_cells;
  for (int l = 1; l < lb; ++l) {
    v = &mg->lv[l];
    const cl_uint cells = (cl_uint)v->n.s[3], so = (cl_uint)v->so, vo = (cl_uint)v->vo;
    const cl_int W = v->W;
    if (l > 1) {
      const struct mg_level *f = &mg->lv[l - 1];
      const cl_int Rf = f->R;
      const cl_uint sf = (cl_uint)f->so;
      CLSPH_TRY(KERN_SET(mg->k_galerkin, KARG(f->n), KARG(Rf), KARG(sf), KARG(v->n), KARG(so),
                         KARG(mg->d_S)));
      CLSPH_TRY(kern_launch(mg->dev, mg->k_galerkin, cells, NULL));
    }
    /* the members of the level (its live cells and the parents of the finer level's members),
     * listed for the block; the others' vectors zeroed */
    const cl_int ll = l;
    const cl_int4 none = {{0, 0, 0, 0}};
    const cl_int4 nf = l > 1 ? mg->lv[l - 1].n : none;
    const cl_uint fo = l > 1 ? (cl_uint)mg->lv[l - 1].vo : 0u;
    CLSPH_TRY(KERN_SET(mg->k_weights, KARG(cells), KARG(W), KARG(so), KARG(mg->d_S), KARG(omega),
                       KARG(vo), KARG(mg->d_cdw), KARG(mg->d_live), KARG(ll), KARG(v->n), KARG(nf),
                       KARG(fo), KARG(mg->d_list), KARG(mg->d_nlist), KARG(mg->d_b),
                       KARG(mg->d_t_c), KARG(mg->d_x)));
    CLSPH_TRY(kern_launch(mg->dev, mg->k_weights, cells, NULL));
  }
  if (lb <= mg->nlevels) {
    const cl_int blb = lb, bL = mg->nlevels;
    CLSPH_TRY(KERN_SET(mg->k_setup_block, KARG(blb), KARG(bL), KARG(mg->d_info), KARG(mg->d_S),
                       KARG(omega), KARG(mg->d_cdw), KARG(mg->d_live), KARG(mg->d_list),
                       KARG(mg->d_nlist), KARG(mg->d_b), KARG(mg->d_t_c), KARG(mg->d_x)));
    CLSPH_TRY(kern_launch_wg(mg->dev, mg->k_setup_block, mg->setup_wg, mg->setup_wg, NULL));
  }
  CLSPH_TRY(kern_read_nb(mg->dev, mg->d_nlist, sizeof(cl_uint), sizeof mg->h_live1, &mg->h_live1));
  mg->live1_read = 1;
  CLSPH_TRY(coarsest(mg));
done:
  return st;
}

/* The V(1,1) cycle (mg.cl): the fine level down, the stencil levels above the block down, the
 * block (the small levels down, the coarsest, up again), the levels above it up, the fine level
 * up: 3 launches, and 1 + 2 (l0 − 1) more where the block starts above level 1 (mg_setup); 2 and
 * 1 + 2 (l0 − 1) in mg_apply_coarse. */
enum clsph_status mg_apply(struct mg *mg, size_t n, cl_mem row, cl_mem col, cl_mem valm, double eps,
                           cl_mem r, cl_mem z, cl_mem state, cl_uint k)
{
  enum clsph_status st = CLSPH_OK;
  const cl_uint nn = (cl_uint)n;
  const real e = (real)eps;
  /* the fine t = dw ∘ r (the first sweep from zero) came with r (psolve_precond_apply) */
  CLSPH_TRY(KERN_SET(mg->k_down_csr, KARG(nn), KARG(row), KARG(col), KARG(valm), KARG(e),
                     KARG(mg->d_t), KARG(r), KARG(mg->d_res), KARG(k), KARG(state)));
  CLSPH_TRY(kern_launch(mg->dev, mg->k_down_csr, n, NULL));
  CLSPH_TRY(mg_apply_coarse(mg, n, z, state, k));
done:
  return st;
}

enum clsph_status mg_apply_coarse(struct mg *mg, size_t n, cl_mem z, cl_mem state, cl_uint k)
{
  enum clsph_status st = CLSPH_OK;
  const cl_uint nn = (cl_uint)n, ncells = (cl_uint)mg->grid->ncells;
  const int L = mg->nlevels, l0 = mg->l0;
  if (l0 > 1) { /* level 1 (offset 0) outside the block: its b and t here */
    CLSPH_TRY(KERN_SET(mg->k_restrict_csr, KARG(ncells), KARG(mg->grid->d_start), KARG(mg->d_agg),
                       KARG(mg->d_res), KARG(mg->d_cdw), KARG(mg->d_b), KARG(mg->d_t_c), KARG(k),
                       KARG(state)));
    CLSPH_TRY(kern_launch(mg->dev, mg->k_restrict_csr, ncells, NULL));
  }
  for (int l = 1; l < l0; ++l) { /* large stencil levels down */
    const struct mg_level *f = &mg->lv[l], *c = &mg->lv[l + 1];
    const cl_int W = f->W;
    const cl_uint sf = (cl_uint)f->so, fo = (cl_uint)f->vo, co = (cl_uint)c->vo;
    CLSPH_TRY(KERN_SET(mg->k_down, KARG(f->n), KARG(W), KARG(sf), KARG(fo), KARG(c->n), KARG(co),
                       KARG(mg->d_S), KARG(mg->d_nb), KARG(mg->d_live), KARG(mg->d_cdw),
                       KARG(mg->d_b), KARG(mg->d_t_c), KARG(mg->d_x), KARG(k), KARG(state)));
    CLSPH_TRY(kern_launch(mg->dev, mg->k_down, (size_t)c->n.s[3], NULL));
  }
  {
    const cl_int bl0 = l0, bL = L;
    const cl_uint m = (cl_uint)mg->m;
    CLSPH_TRY(KERN_SET(mg->k_block, KARG(bl0), KARG(bL), KARG(mg->d_info), KARG(m), KARG(mg->d_M),
                       KARG(mg->d_S), KARG(mg->d_nb), KARG(mg->d_pnb), KARG(mg->d_par),
                       KARG(mg->d_live), KARG(mg->d_cdw), KARG(mg->d_b), KARG(mg->d_t_c),
                       KARG(mg->d_x), KARG(mg->grid->d_start), KARG(mg->d_agg), KARG(mg->d_res),
                       KARG(mg->d_list), KARG(mg->d_nlist), KARG(k), KARG(state)));
    CLSPH_TRY(kern_launch_wg(mg->dev, mg->k_block, mg->block_wg, mg->block_wg, NULL));
  }
  for (int l = l0 - 1; l >= 1; --l) { /* large stencil levels up */
    const struct mg_level *v = &mg->lv[l], *c = &mg->lv[l + 1];
    const cl_uint cells = (cl_uint)v->n.s[3];
    const cl_int W = v->W;
    const cl_uint so = (cl_uint)v->so, vo = (cl_uint)v->vo, co = (cl_uint)c->vo;
    CLSPH_TRY(KERN_SET(mg->k_up, KARG(cells), KARG(W), KARG(so), KARG(vo), KARG(co), KARG(mg->d_S),
                       KARG(mg->d_pnb), KARG(mg->d_par), KARG(mg->d_cdw), KARG(mg->d_t_c),
                       KARG(mg->d_x), KARG(k), KARG(state)));
    CLSPH_TRY(kern_launch(mg->dev, mg->k_up, cells, NULL));
  }
  CLSPH_TRY(KERN_SET(mg->k_up_csr, KARG(nn), KARG(mg->d_agg), KARG(mg->d_AP), KARG(mg->d_nb),
                     KARG(mg->d_dw), KARG(mg->d_t), KARG(mg->d_res), KARG(mg->d_x), KARG(z),
                     KARG(k), KARG(state)));
  CLSPH_TRY(kern_launch(mg->dev, mg->k_up_csr, n, NULL));
done:
  return st;
}

void mg_destroy(struct mg *mg)
{
  release_levels(mg);
  cl_kernel *ks[] = {&mg->k_aggregate, &mg->k_ap_csr,  &mg->k_restrict_csr, &mg->k_galerkin_ap,
                     &mg->k_galerkin,  &mg->k_weights, &mg->k_setup_block,  &mg->k_down_csr,
                     &mg->k_up_csr,    &mg->k_down,    &mg->k_up,           &mg->k_block,
                     &mg->k_coarsest};
  for (size_t i = 0; i < sizeof ks / sizeof *ks; ++i) {
    if (*ks[i] != NULL) clReleaseKernel(*ks[i]);
    *ks[i] = NULL;
  }
  cl_mem *ms[] = {&mg->d_agg, &mg->d_cell, &mg->d_dw,   &mg->d_res,
                  &mg->d_t,   &mg->d_flag, &mg->d_nlist};
  for (size_t i = 0; i < sizeof ms / sizeof *ms; ++i) kern_release(ms[i]);
}
