/* channel1d.h: the fully developed turbulent channel under the standard k-ε model with the
 * step-wise wall function, across the half channel (Wang, Sun & Hu, sec 5.1, eq 41): the 1-D
 * reference that the wcsph-riemann RANS channel is compared with. The wall model sits at the
 * distance y_p from the wall (eqs 10-14); the centreline is a symmetry plane. */
#ifndef CLSPH_CHANNEL1D_H
#define CLSPH_CHANNEL1D_H

/** The model's constants (Launder & Spalding; the wall function of eq 11). */
struct channel1d_model {
  double c_mu, c1, c2, sigma_k, sigma_eps;
  double kappa, e_wall; /* the log law u+ = ln(E y+)/κ (eq 11) */
  double y_plus_lam;    /* below it u+ = y+ (eq 11: 11.225) */
  int paper_diffusion; /* 1: (ν + ν_t/σ) d²φ/dy², as eq 41 writes it; 0: d/dy((ν + ν_t/σ) dφ/dy) */
  /* the wall function's velocity scale: 0 u_k = C_μ^¼ k_p^½ (Wang, Sun & Hu eq 12: τ_w =
   * ρ U u_k / u+(y_p u_k/ν)); 1 the friction velocity itself (Leroy et al. 2014 eq 23: U/u_τ =
   * u+(y_p u_τ/ν), the production at y_p τ_w u_τ/(κ y_p)); ε_p stays eq 14's in both */
  int ustar_law;
  /* 1: a cell-centred finite volume's discretisation on the same nodes (OpenFOAM's Gauss linear):
   * the momentum flux through each face with the two nodes' mean ν_t, and the production from
   * the central difference of u (the mirror beyond the centre plane); 0: the momentum equation
   * integrated by the trapezoidal rule and the production from its exact local du/dy */
  int fv;
  /* 1: the paper's finite differences (sec 5.1): du/dy by the backward difference, in the
   * momentum equation (u_i = u_{i−1} + Δ u_τ² (1 − y_i/δ)/(ν + ν_t,i)) and in the production */
  int backward;
};

/** The problem: the half channel [0, delta], the wall model at y_p, driven either to the bulk
 *  velocity u_bulk (u_tau <= 0) or by the friction velocity u_tau (the pressure gradient
 *  u_tau²/delta). */
struct channel1d_problem {
  double delta, nu, y_p;
  double u_bulk; /* the mean of u over [0, delta], the wall-function profile below y_p included */
  double u_tau;  /* > 0: given; then u_bulk is a result */
  int cells;     /* nodes y_p + i (delta − y_p)/cells, i = 0..cells */
  /* rows > 0 (instead of cells): the nodes are the particle rows of an SPH channel of `rows`
   * rows across the full height 2 δ with its first row at y_p (the boundary offset of sec 4.4),
   * y_p + i Δ, Δ = 2 (δ − y_p)/(rows − 1): the centre plane is a node for odd rows and lies
   * midway between the last node and its mirror for even rows */
  int rows;
  /* with rows: u_bulk is the mean of u over the rows (what an SPH run's flow-rate control holds
   * on its particles), not over [0, δ] */
  int bulk_over_rows;
  /* with bulk_over_rows: the momentum balance of the SPH run's fluid, which fills [y_w, δ] only
   * (y_w = y_p − Δ/2, the offset wall of sec 4.4) and takes the wall model's stress at y_w: the
   * total stress u_τ² (δ − y)/(δ − y_w) instead of the channel's u_τ² (δ − y)/δ, whose layer
   * below y_w the pressure gradient also drives */
  int offset_momentum;
};

/** The solution on the nodes, and the scalars. */
struct channel1d_solution {
  int nodes;
  double *y, *u, *k, *eps, *nu_t;
  double u_tau, u_bulk, y_plus_p; /* y_plus_p: eq 10 at the first node */
  double u_rows;                  /* the mean of u over the nodes (rows), the centre's half */
  int iterations;
  double residual; /* the largest relative change of u, k, ε over the last iteration */
};

/** @brief The standard constants: C_μ 0.09, C1 1.44, C2 1.92, σ_k 1, σ_ε 1.3, κ 0.41,
 *  E 9.793 and the switch at y+ = 11.225 (the pair the paper's eq 11 takes from FLUENT). */
struct channel1d_model channel1d_standard(void);

/** @brief Solve to a steady state (pseudo-time with the linearised sources of eqs 28-30).
 *  Returns 0, or −1 with a message on stderr (bad input, no convergence, no memory). */
int channel1d_solve(const struct channel1d_model *m, const struct channel1d_problem *p,
                    struct channel1d_solution *s);

/** @brief u from the wall function at distance y from the wall (y <= y_p), the first node's k. */
double channel1d_wall_u(const struct channel1d_model *m, double nu, double u_tau, double k_p,
                        double y);

void channel1d_free(struct channel1d_solution *s);

#endif /* CLSPH_CHANNEL1D_H */
