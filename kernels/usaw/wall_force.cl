/* wall_force.cl (USAW schemes): the velocity gradient at the wall vertices, for the viscous part
 * of the force of the fluid on a wall (Leroy et al. 2014 eqs 69-70). At vertex particle a,
 *   G−_a{u} = −(1/γ_a) Σ_b V_b (u_a − u_b) ⊗ ∇w_ab + (1/γ_a) Σ_s (u_a − u_s) ⊗ ∇γ_as       (8)
 * with (A ⊗ ∇)_ij = A_i ∂_j, so G_ij ≈ ∂u_i/∂x_j, ∇w_ab = F(r) r_ab, r_ab = r_a − r_b, u_s the
 * mean of the segment's vertex velocities. The kernel writes the rate of strain
 * ∇u + ∇uᵀ as three reals per particle (xx, xy, yy) for vertex particles (fluid entries are left
 * as they are); the host takes a segment's as the mean of its two vertices' (eq 70). */
__kernel void usaw_vertex_strain(USAW_PART_ARGS, USAW_SEG_ARGS, __global const realv *vel,
                                 __global real *strain)
{
  const uint i = get_global_id(0);
  if (i >= n || kind[i] != ISPH_VERTEX) return;
  const realv x = pos[i], u = vel[i];
  realv gx = (realv)(R(0.0)), gy = (realv)(R(0.0)); /* ∇u_x and ∇u_y (rows of G) */
  struct neigh_iter it;
  NEIGH_FOR(it, g, cell_start, x, j) {
    realv r = x - (pos[j] + it.shift);
    real r2 = dot(r, r);
    if (r2 >= g.sm.support2 || j == i || kind[j] > ISPH_VERTEX) continue;
    const realv gw = smoothing_f(g.sm, sqrt(r2)) * r, du = u - vel[j];
    gx -= vol[j] * du.x * gw;
    gy -= vol[j] * du.y * gw;
  }
  NEIGH_FOR(it, g_seg, seg_start, x, s) {
    const realv a = seg_a[s] + it.shift, b = seg_b[s] + it.shift;
    const realv gg = usaw_grad_gamma_seg(g.sm, x, a, b, seg_n[s]);
    const realv du = u - R(0.5) * (vel[inv[seg_v1[s]]] + vel[inv[seg_v2[s]]]);
    gx += du.x * gg;
    gy += du.y * gg;
  }
  gx /= gam[i];
  gy /= gam[i];
  strain[3 * i] = R(2.0) * gx.x;
  strain[3 * i + 1] = gx.y + gy.x;
  strain[3 * i + 2] = R(2.0) * gy.y;
}
