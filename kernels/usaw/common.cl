/* common.cl (USAW schemes): the USAW operators of Leroy et al. 2014 over particles b ∈ P (fluid and
 * vertex particles) and segments s, shared by the stages of the scheme.
 *   G+_a{A} = (1/γ_a) Σ_b V_b (A_a + A_b) ∇w_ab − (1/γ_a) Σ_s (A_a + A_s) ∇γ_as      (5)
 *   G−_a{A} = −(1/γ_a) Σ_b V_b A_ab ∇w_ab + (1/γ_a) Σ_s A_as ∇γ_as                  (8)
 *   D_a{A}  = −(1/γ_a) Σ_b V_b A_ab · ∇w_ab + (1/γ_a) Σ_s A_as · ∇γ_as              (9)
 * with A_ab = A_a − A_b, ∇w_ab = ∇_a w(r_a − r_b) = F(r) r_ab. A segment's value is the mean of
 * its two vertex particles' (Ferrand et al. 2013); its vertices are found through inv[] (the
 * current index of each original particle index). Kinds: 0 fluid, 1 vertex. */
#define ISPH_FLUID  0u
#define ISPH_VERTEX 1u
#define ISPH_PI     R(3.14159265358979323846)

/* The arguments every stage passes for the segments. */
#define USAW_SEG_ARGS                                                                              \
  const struct grid g_seg, __global const uint *seg_start, __global const realv *seg_a,            \
      __global const realv *seg_b, __global const realv *seg_n, __global const uint *seg_v1,       \
      __global const uint *seg_v2, __global const uint *inv

/* The particle arguments every stage passes. */
#define USAW_PART_ARGS                                                                             \
  const uint n, const struct grid g, __global const uint *cell_start, __global const realv *pos,   \
      __global const real *vol, __global const uint *kind, __global const real *gam

/* Position on a periodic axis wrapped into [lo, lo + len). */
real isph_wrap(real x, real lo, real len)
{
  real t = x - lo;
  t -= len * floor(t / len);
  if (t >= len) t -= len; /* round-off of the line above */
  return lo + t;
}
