/* mg.h: the aggregation multigrid preconditioner of the pressure solve (kernels/common/mg.cl):
 * geometric aggregates (the neighbour-grid cells, then blocks of 2 x 2 (x 2) cells), Galerkin
 * coarse operators built on the device once per solve, one damped-Jacobi sweep before and after
 * each coarse correction (a V(1,1) cycle, one launch a level and the small levels in one), and the
 * coarsest level (at most MG_COARSEST cells) solved exactly by a dense inverse computed on the
 * device, in one work-group (mg_coarsest): the set-up waits for nothing. Its stored coefficients
 * are float in both builds (MG_REAL_SIZE), its vectors real. Used through psolve
 * (precond = "multigrid"); it needs the stored rows (csr.cl) and unknowns that are particles sorted
 * by a grid (struct psolve_op's grid). */
#ifndef CLSPH_MG_H
#define CLSPH_MG_H

#include "grid.h"
#include "kern.h"
#include "prog.h"

#define MG_MAX_LEVELS 24
/* The coarsest level has at most MG_COARSEST cells: its dense inverse (m² reals) is computed at
 * every solve, on the device in one work-group of at most MG_COARSE_WG items (mg_coarsest). 64
 * against 256: 8.1 iterations per step instead of 6.9 on the 60² cavity, in less time. */
#define MG_COARSEST  64
#define MG_COARSE_WG 64 /* MG_COARSE_WG in mg.cl */
/* Coarse levels of at most MG_BLOCK cells run in one work-group launch (mg_block); level 1 too
 * where at most MG_BLOCK of its cells held fluid at the last solve and it has at most
 * MG_BLOCK_CELLS cells (the block passes over the empty ones: a free-surface flow's air) */
#define MG_BLOCK       4096
#define MG_BLOCK_CELLS 32768
#define MG_INFO        8           /* ints a level in the block's table (MG_INFO in mg.cl) */
#define MG_NONE        0xffffffffu /* no cell (MG_NONE in mg.cl) */
/* The stored coefficients of the preconditioner (the fine rows' copy, A P, the coarse stencils)
 * are float in both builds (mreal in mg.cl): the cycle is bound by memory */
#define MG_REAL_SIZE sizeof(cl_float)

struct mg_level {
  cl_int4 n; /* cells per axis, .s[3] = total */
  int R, W;  /* stencil radius and width */
  size_t so; /* offset of its stencil (n.s[3] x W reals) in d_S */
  size_t vo; /* offset of its vectors (n.s[3] reals) in d_cdw, d_b, d_x */
};

struct mg {
  const struct dev *dev;
  double omega; /* Jacobi damping */
  cl_kernel k_aggregate, k_ap_csr, k_galerkin_ap, k_galerkin, k_weights, k_setup_block, k_down_csr,
      k_restrict_csr, k_up_csr, k_down, k_up, k_block, k_coarsest;
  size_t block_wg;         /* work-group size of mg_block */
  size_t setup_wg;         /* and of mg_setup_block */
  size_t coarse_wg;        /* and of mg_coarsest */
  size_t cap;              /* fine unknowns the buffers hold */
  cl_mem d_agg, d_cell;    /* fine level: aggregate (or none), cell of each unknown */
  cl_mem d_dw, d_t, d_res; /* fine level: ω/diag, first sweep, residual after it */
  cl_mem d_AP;             /* fine rows of (A + ε diag A) P against level-1 cells (their cells:
                            * level 1's d_nb) */
  const struct grid *grid; /* the grid the levels were sized for */
  int nlevels;             /* coarse levels 1 .. nlevels (lv[0] unused) */
  int l0;                  /* the first level of the single-work-group block (mg_setup) */
  struct mg_level lv[MG_MAX_LEVELS + 1];
  cl_mem d_S;                    /* every coarse level's stencil */
  cl_mem d_nb, d_pnb;            /* every stencil entry's cell and that cell's parent (as d_S) */
  cl_mem d_par;                  /* every coarse cell's parent (as the vectors) */
  cl_mem d_cdw, d_b, d_t_c, d_x; /* every coarse level's ω/diag, right-hand side, first
                                  * sweep, solution */
  cl_mem d_live;                 /* every coarse cell: bit 0 where its row has a nonzero, bit 1
                                  * where the block passes over it (uchar; mg_weights) */
  cl_mem d_list;                 /* every coarse level's cells that the block passes over (as the
                                  * vectors; their count in d_nlist) */
  cl_mem d_info;                 /* the block's level table */
  size_t m;                      /* unknowns of the coarsest level */
  cl_mem d_M;                    /* its dense inverse */
  cl_mem d_dense;                /* mg_coarsest's work: A, its copy and the inverse in kreal */
  cl_mem d_flag;                 /* mg_coarsest: 1 when the coarsest operator stayed singular */
  cl_uint h_flag;                /* its queued read (valid after the solve's first wait) */
  cl_mem d_nlist;                /* per level the cells listed in d_list; level 1's: those that
                                  * hold fluid (mg_weights) */
  cl_uint h_live1;               /* its queued read (valid after the solve's first wait) */
  cl_uint live1;                 /* the last set-up's count (UINT_MAX: none yet) */
  int live1_read;                /* a set-up has queued the read of h_live1 */
  int l0_cells;                  /* the block's first level by the levels' cells alone */
  int warned_singular;           /* the singular-coarsest warning was given */
};

/** @brief Kernels (from a program built with PSOLVE_SOURCES) and fine-level vectors for cap
 *  unknowns. */
enum clsph_status mg_create(const struct dev *dev, cl_program prog, size_t cap, struct mg *out);
/** @brief Build the hierarchy for the operator stored in (row, col, val) over the n particles
 *  sorted by g: A + eps diag(A), dinv its inverse diagonal; valm (as long as val, MG_REAL_SIZE
 *  an entry) gets the cycle's copy of val. */
enum clsph_status mg_setup(struct mg *mg, const struct grid *g, size_t n, cl_mem row, cl_mem col,
                           cl_mem val, cl_mem valm, double eps, cl_mem dinv);
/** @brief After the solve's first blocking read: warn once when the last set-up found the coarsest
 *  operator singular (its Jacobi fallback). */
void mg_report(struct mg *mg);
/** @brief z = M⁻¹ r: one V(1,1) cycle from z = 0 (valm: mg_setup's copy of the values), as part of
 * Krylov iteration k whose state is `state` (krylov.cl: the kernels do nothing once the solve ended
 * before k). The kernel that made r has made d_t = d_dw ∘ r, the first sweep from zero. */
enum clsph_status mg_apply(struct mg *mg, size_t n, cl_mem row, cl_mem col, cl_mem valm, double eps,
                           cl_mem r, cl_mem z, cl_mem state, cl_uint k);
/** @brief The cycle after its fine level down: where the kernel that made r has also made the
 *  fine residual d_res = r − A d_t (mg.cl's mg_begin_down, mg_s_down), the rest of mg_apply. */
enum clsph_status mg_apply_coarse(struct mg *mg, size_t n, cl_mem z, cl_mem state, cl_uint k);
/** @brief Release (safe on a zeroed struct). */
void mg_destroy(struct mg *mg);

#endif /* CLSPH_MG_H */
