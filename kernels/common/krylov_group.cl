/* krylov_group.cl: the whole BiCGStab solve of a small system in one work-group and one launch
 * (solvers/pressure/psolve.c, scheme option solver_group_max).
 *
 * A solve of a few thousand unknowns costs little arithmetic, and the iteration of krylov.cl
 * spends it in 11 launches an iteration with the multigrid (the 30² cavity: about 100 launches
 * a step, each of 5-25 µs on PoCL, most of them waiting on the one before): the launches, not the
 * sums, set its time, and on a GPU more so. Here one work-group runs every iteration, its
 * barriers standing where the launches stood: the same algorithm (van der Vorst 1992, with the
 * preconditioner on the right), the same stopping and breakdown tests as kr_begin, kr_s and
 * kr_end_iteration, the breakdown restarts done here rather than by the host, and the state
 * written once at the end (KR_DONE, KR_REASON, KR_RNORM; KR_RESTARTS the restarts). Its dot
 * products are per-item sums in kreal that the first item adds up, so they do not match the
 * multi-launch partial sums to the bit: a solve may end an iteration apart. The host starts it
 * after kr_start, which has set the state (or ended the solve at iteration 0). */
#define KR_RESTARTS 16  /* breakdown restarts of a one-group solve (PSOLVE_STATE in psolve.h) */
#define KR_GROUP_WG 256 /* items of the one-group solve at most (PSOLVE_GROUP_WG in psolve.h) */

/* The multigrid's arguments (mg.c's buffers, levels 1 .. L all in the block; its ε, meps, may
 * differ from the operator's: psolve.c's reinforcement) */
#define KR_MG_PARAMS                                                                               \
  const real meps, __global const mreal *valm, __global const real *dw, __global real *mt,         \
      __global real *mres, __global const uint *agg, __global const mreal *AP, const int L,        \
      __global const int *info, const uint m, __global const real *M, __global const mreal *S,     \
      __global const uint *nb, __global const uint *pnb, __global const uint *par,                 \
      __global const uchar *live, __global const real *cdw, __global real *cb, __global real *ct,  \
      __global real *cx, __global const uint *start, __global const uint *list,                    \
      __global const uint *nlist

/* The phases of the solve. The kernel is one loop over phases with one barrier, at the end of
 * each: a phase's work is vector loops and the tests, whose branches hold no barrier. PoCL forms
 * the regions between barriers at compile time, and a first version with the barriers inside
 * the tests and in nested loops (tree sums, the levels) was still compiling after 10 minutes. */
#define KG_BEGIN    0  /* kr_begin: the tests; ρ', β, p = r + β (p − ω v), the first sweep */
#define KG_MRES     1  /* multigrid: the fine residual after the first sweep */
#define KG_RESTRICT 2  /* multigrid: level 1's b and t */
#define KG_DOWN     3  /* multigrid: level lvl down to lvl + 1 */
#define KG_COARSEST 4  /* multigrid: the coarsest level's dense inverse */
#define KG_UP       5  /* multigrid: level lvl up */
#define KG_UPFINE   6  /* multigrid: the fine level up: p̂ or ŝ */
#define KG_V        7  /* v = A p̂, (r0, v) */
#define KG_S        8  /* kr_s: α, s = r − α v, (s, s), the first sweep */
#define KG_T        9  /* t = A ŝ, (t, s), (t, t) */
#define KG_END      10 /* kr_end_iteration: ω, x, r = s − ω t, (r, r), (r0, r) */
#define KG_RESTART  11 /* r0 = r, p = v = 0 after a vanishing ω */
#define KG_SUM      12 /* the first item adds the items' partial sums up */
#define KG_DONE     13

/* The iterations 1 .. max_it of the solve that kr_start began (one work-group of KR_GROUP_WG
 * items at most, one launch). x: the initial guess, then the solution; r, r0: the residual and
 * its shadow (kr_start); p, v, s, t, ph (p̂), sh (ŝ): work vectors; the operator A + ε diag A
 * from the stored rows; mg = 1: the multigrid preconditioner, else Jacobi (dinv). */
__kernel void kr_solve_group(const uint n, const uint max_it, const real noise, const real tiny,
                             const int mg, __global kreal *st, __global const uint *row,
                             __global const uint *col, __global const real *val, const real eps,
                             __global const real *dinv, __global real *x, __global real *r,
                             __global real *r0, __global real *p, __global real *v,
                             __global real *s, __global real *t, __global real *ph,
                             __global real *sh, KR_MG_PARAMS)
{
  __local kreal ra[KR_GROUP_WG], rb[KR_GROUP_WG], rs[2];
  const uint lid = get_local_id(0), ls = get_local_size(0);
  if (kr_over(st, 1u)) return; /* kr_start ended it (every item reads the same state) */
  const kreal bnorm = st[KR_BNORM], stop = st[KR_STOP], atol = st[KR_ATOL];
  kreal r0norm = st[KR_R0NORM], rel = st[KR_RNORM];
  kreal rho_o = KR(1.0), alpha_o = KR(1.0), omega_o = KR(1.0); /* ρ, α, ω of the last iteration */
  kreal rr = KR(0.0), rho = KR(0.0), r0v = KR(0.0), ss = KR(0.0), ts = KR(0.0), tt = KR(0.0);
  kreal alpha = KR(0.0);
  int ended = 0, reason = 0, restarts = 0, restarted_at = -1;
  int which = 0; /* the vector being preconditioned: 0 p (into p̂), 1 s (into ŝ) */
  int lvl = 0, phase = KG_SUM, after = KG_BEGIN;
  int collect = KG_END; /* whose sums the phase after KG_SUM reads: (r, r) and (r0, r) */
  uint k = 1, end_k = 0;
  /* (r, r) and (r0, r) of the start */
  kreal a = KR(0.0), b = KR(0.0);
  for (uint i = lid; i < n; i += ls) {
    a += (kreal)r[i] * r[i];
    b += (kreal)r0[i] * r[i];
  }
  ra[lid] = a;
  rb[lid] = b;
  barrier(CLK_LOCAL_MEM_FENCE);
  while (phase != KG_DONE) {
    int next = KG_DONE;
    if (phase == KG_SUM) {
      if (lid == 0) {
        kreal sa = KR(0.0), sb = KR(0.0);
        for (uint j = 0; j < ls; ++j) {
          sa += ra[j];
          sb += rb[j];
        }
        rs[0] = sa;
        rs[1] = sb;
      }
      next = after;
    } else {
      if (collect == KG_END) { /* the sums of the phase before KG_SUM */
        rr = rs[0];
        rho = rs[1];
      } else if (collect == KG_V) {
        r0v = rs[0];
      } else if (collect == KG_S) {
        ss = rs[0];
      } else if (collect == KG_T) {
        ts = rs[0];
        tt = rs[1];
      }
      collect = -1;
      a = b = KR(0.0);
      if (phase == KG_BEGIN) {
        /* the residual of k − 1 ends the solve if small or not finite (after the last
         * iteration, k = max_it + 1, that test alone); a vanishing ρ' restarts from r */
        const kreal rn = sqrt(rr);
        rel = rn / bnorm;
        int go = 0, restart = 0;
        if (!isfinite(rr) || rn <= stop) {
          ended = 1;
          end_k = k - 1;
          reason = !isfinite(rr) ? -3 : (rn <= atol ? 2 : 1);
        } else if (k > max_it) {
          /* the limit: still running, as a batch that fell short */
        } else if (!isfinite(rho)) {
          ended = 1;
          end_k = k;
          reason = -3;
        } else if (fabs(rho) <= (kreal)noise * (r0norm < KR(0.0) ? rn : r0norm) * rn) {
          if (restarted_at == (int)k - 1) { /* twice in a row */
            ended = 1;
            end_k = k;
            reason = -2;
          } else {
            restart = 1;
            restarted_at = (int)k;
            ++restarts;
          }
        } else {
          go = 1;
        }
        if (restart) { /* r0 = r, p = v = 0, ρ = α = ω = 1: iteration k again */
          for (uint i = lid; i < n; i += ls) {
            r0[i] = r[i];
            p[i] = R(0.0);
            v[i] = R(0.0);
          }
          rho_o = alpha_o = omega_o = KR(1.0);
          rho = rr;
          r0norm = KR(-1.0);
          next = KG_BEGIN;
        }
        if (go) {
          const real beta = (real)((rho / rho_o) * (alpha_o / omega_o)), om = (real)omega_o;
          rho_o = rho;
          if (r0norm < KR(0.0)) r0norm = rn;
          for (uint i = lid; i < n; i += ls) {
            const real w = r[i] + beta * (p[i] - om * v[i]);
            p[i] = w;
            if (mg)
              mt[i] = dw[i] * w;
            else
              ph[i] = dinv[i] * w;
          }
          which = 0;
          next = mg ? KG_MRES : KG_V;
        }
      } else if (phase == KG_MRES) {
        __global const real *yv = which ? s : p;
        for (uint i = lid; i < n; i += ls)
          mres[i] =
              yv[i] - mg_row_dot(meps * valm[row[i]] * mt[i], row[i], row[i + 1], col, valm, mt);
        next = KG_RESTRICT;
      } else if (phase == KG_RESTRICT) {
        mg_block_restrict(info, list, nlist, start, agg, mres, cdw, cb, ct);
        lvl = 1;
        next = L > 1 ? KG_DOWN : KG_COARSEST;
      } else if (phase == KG_DOWN) {
        mg_block_down(info, lvl, list, nlist, S, nb, live, cdw, cb, ct, cx);
        ++lvl;
        next = lvl < L ? KG_DOWN : KG_COARSEST;
      } else if (phase == KG_COARSEST) {
        mg_block_coarsest(info, L, m, M, cb, cx);
        lvl = L - 1;
        next = lvl >= 1 ? KG_UP : KG_UPFINE;
      } else if (phase == KG_UP) {
        mg_block_up(info, lvl, list, nlist, S, pnb, par, cdw, ct, cx);
        --lvl;
        next = lvl >= 1 ? KG_UP : KG_UPFINE;
      } else if (phase == KG_UPFINE) {
        __global real *z = which ? sh : ph;
        for (uint i = lid; i < n; i += ls) z[i] = mg_up_row(agg, AP, nb, dw, mt, mres, cx, i);
        next = which ? KG_T : KG_V;
      } else if (phase == KG_V) {
        for (uint i = lid; i < n; i += ls) {
          const real yi =
              blas1_row_dot(eps * val[row[i]] * ph[i], row[i], row[i + 1], col, val, ph);
          v[i] = yi;
          a += (kreal)r0[i] * yi;
        }
        collect = KG_V;
        after = KG_S;
        next = KG_SUM;
      } else if (phase == KG_S) {
        if (!isfinite(r0v) || r0v == KR(0.0)) {
          ended = 1;
          end_k = k;
          reason = r0v == KR(0.0) ? -2 : -3;
        } else {
          alpha = rho_o / r0v; /* ρ of this iteration */
          const real al = (real)alpha;
          for (uint i = lid; i < n; i += ls) {
            const real w = r[i] - al * v[i];
            s[i] = w;
            a += (kreal)w * w;
            if (mg)
              mt[i] = dw[i] * w;
            else
              sh[i] = dinv[i] * w;
          }
          which = 1;
          collect = KG_S;
          after = mg ? KG_MRES : KG_T;
          next = KG_SUM;
        }
      } else if (phase == KG_T) {
        for (uint i = lid; i < n; i += ls) {
          const real yi =
              blas1_row_dot(eps * val[row[i]] * sh[i], row[i], row[i + 1], col, val, sh);
          t[i] = yi;
          a += (kreal)yi * s[i];
          b += (kreal)yi * yi;
        }
        collect = KG_T;
        after = KG_END;
        next = KG_SUM;
      } else if (phase == KG_END) {
        const kreal sn = sqrt(ss);
        const real al = (real)alpha;
        if (sn <= stop) { /* a small s: x += α p̂, the end */
          for (uint i = lid; i < n; i += ls) x[i] += al * ph[i];
          ended = 1;
          end_k = k;
          reason = 1;
          rel = sn / bnorm;
        } else if (!isfinite(ts) || !isfinite(tt)) {
          ended = 1;
          end_k = k;
          reason = -3;
        } else {
          const kreal omega = tt > KR(0.0) ? ts / tt : KR(0.0);
          const real w = (real)omega;
          for (uint i = lid; i < n; i += ls) {
            x[i] += al * ph[i] + w * sh[i];
            const real ri = s[i] - w * t[i];
            r[i] = ri;
            a += (kreal)ri * ri;
            b += (kreal)r0[i] * ri;
          }
          alpha_o = alpha;
          omega_o = omega;
          ++k;
          collect = KG_END;
          /* a vanishing ω: restart from this residual */
          after = fabs(omega) <= (kreal)tiny ? KG_RESTART : KG_BEGIN;
          next = KG_SUM;
        }
      } else if (phase == KG_RESTART) {
        for (uint i = lid; i < n; i += ls) {
          r0[i] = r[i];
          p[i] = R(0.0);
          v[i] = R(0.0);
        }
        ++restarts;
        rho_o = alpha_o = omega_o = KR(1.0);
        rho = rr;
        r0norm = KR(-1.0);
        next = KG_BEGIN;
      }
      ra[lid] = a;
      rb[lid] = b;
    }
    phase = next;
    barrier(CLK_GLOBAL_MEM_FENCE | CLK_LOCAL_MEM_FENCE);
  }
  if (lid == 0) {
    st[KR_DONE] = ended ? (kreal)end_k : KR_BIG;
    st[KR_REASON] = (kreal)reason;
    st[KR_RNORM] = rel;
    st[KR_RESTARTS] = (kreal)restarts;
  }
}
