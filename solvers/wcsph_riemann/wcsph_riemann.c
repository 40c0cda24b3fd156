/* wcsph_riemann.c: Riemann-solver weakly-compressible SPH with the transport-velocity correction
 * and dual-criteria time stepping (Wang, Sun & Hu, sec 2.3-3.2 and 2.5: Zhang, Hu & Adams 2017
 * for the Riemann solver, Zhang, Rezavand & Hu 2020 for the time stepping), on dummy-particle
 * walls. One step of the time loop is one advection step (eq 27):
 *   Δt_ad = CFL_ad min(h / max(|v|max, U), h² / ν),  CFL_ad = 0.25,
 * U the scene's velocity scale (solvers/sound/sound.c), which bounds the first steps of a flow
 * that starts at rest. It
 *   1. builds the configuration: neighbour list, correction matrices B (eq 20), the density
 *      re-initialisation (config.cl);
 *   2. computes the viscous and body accelerations, the transport-velocity correction
 *      (TVF/LTVF, eqs 25-26, 33-34) and the ARD indicator (eq 42) (advection.cl);
 *   3. holds n_ac = ⌈Δt_ad/Δt_ac⌉ equal acoustic sub-steps, Δt_ac = CFL_ac h/(c0 + |v|max),
 *      CFL_ac = 0.6: pressure relaxation (eqs 16-19), continuity (eq 15), positions, in position
 *      Verlet (acoustic.cl).
 * The loop counts advection steps (sim->step); the acoustic sub-steps go into sim->substeps.
 * Options:
 *   sound_speed          c0, m/s (default 10 U)
 *   background_pressure  p_bg, Pa, added to the pressure in the pressure force only (the field
 *                        p is the gauge pressure; acoustic.cl); default 0
 *   transport_velocity   "limited" (LTVF, eqs 33-34; the default), "full" (eq 25) or "off"
 *   surface_transport    the surface rows, which the transport correction leaves alone in a
 *                        free-surface flow (advection.cl): "off" (the default in 2-D),
 *                        "tangential" (the correction less its part along ∇σ) or "pairs" (pairs
 *                        closer than dr pushed apart; the default of a 3-D free-surface flow).
 *                        Not the paper's: without either, the thin tongue of the 3-D dam break
 *                        (cases/dam_break.lua dim=3, n = 20) clustered before the impact; with
 *                        "tangential" it runs through but the tongue's tip, whose tangent points
 *                        into the air, is pushed ahead (the front at t* = 1 0.86 H past the
 *                        gate against 0.79 with "pairs", which keeps every pair 0.46 dr apart)
 *   ard                  1: adaptive Riemann-eddy dissipation (sec 3.1), 0: off (default)
 *   density              "free_surface" (ρ = max(ρ, ρ_sum) each advection step; the default
 *                        under gravity), "summation" (ρ = ρ_sum; the default otherwise) or
 *                        "continuity" (no re-initialisation; see read_options for when)
 *   wall_dissipation     "limited" (the fluid pairs' limiter; default) or "full" (sec 4.3)
 *   wall_pressure        "mirror" (the dummy shows i's pressure along the wall; the default of a
 *                        laminar scene) or "gradient" (extrapolated along the wall with i's
 *                        pressure gradient over its fluid neighbours: config.cl,
 *                        wcr_wall_pressure_grad; the default under the k-ε model)
 *   wall_shear           under the k-ε model, where the wall model reads the log law for the
 *                        wall's shear stress (eq 12) on each P_ext particle: "y_p" (at y_p for
 *                        every one, sec 4.4's constant y_p; the default), "distance" (at the
 *                        particle's own distance from the wall, with the boundary offset, and
 *                        eq 39's force over its sum on the lattice: turbulence.cl says why) or
 *                        "first_row" (at y_p on the first row, P, alone, each particle taking
 *                        τ_w over its share of the wall, which the first dummy layer hands out
 *                        by the kernel; no other particle takes the wall's stress or the
 *                        dummies' no-slip drag, the P_ext rows above nor those beyond R that
 *                        the dummies still reach, so that the stress crosses the first row's
 *                        upper face whole, as in the 1-D solver's first cell: turbulence.cl)
 *   velocity_gradient    under the k-ε model, the velocity gradient of the production and the
 *                        reconstructed dissipation: "kernel" (eqs 22 and 40, the paper's; the
 *                        default) or "log" (next to a wall, in the log law's coordinate, and
 *                        without eq 40's compensation: turbulence.cl says why)
 *   turbulent_diffusion  under the k-ε model, the diffusion sums of k and ε (eqs 23-24):
 *                        "harmonic" (the pairs' harmonic mean of D over the fluid neighbours,
 *                        the paper's; the default) or "log_mirror" (the pairs' logarithmic mean
 *                        of D, and the wall's mirror images of the first rows' neighbours:
 *                        turbulence.cl says why)
 *   offset_layer         under the k-ε model with a boundary offset (y_p > dr/2, sec 4.4), the
 *                        layer of fluid between the wall and the offset boundary: "none" (no
 *                        fluid there, the paper's; the default) or "body_force" (the layer's
 *                        body force along the wall passes to the first row above it, so that
 *                        the wall's τ_w holds the layer: advection.cl). Without it the flow
 *                        between the offset walls takes the whole wall stress τ_w: in a channel
 *                        driven by a body force the stress in the stream stands
 *                        1/(1 − (y_p − dr/2)/δ) over the channel's at the same τ_w (2.6% and
 *                        3.9% at 40 and 80 rows across, y_p = 0.05 δ), and k, which follows the
 *                        stress, as much (cases/channel_ke.lua). The layer's share of a pressure
 *                        gradient is not passed on: the first row's ∇p, noise-dominated, gave
 *                        that row a random tangential force that raised k on the rows by 20%
 *   wall_pressure_force  under the k-ε model, the pressure force of a dummy particle on a fluid
 *                        one: "corrected" (eq 19 with i's correction matrix B_i, the paper's;
 *                        the default) or "normal" (along the dummy's wall normal, but for the
 *                        share of its pressure that ∇p along the wall gives it: config.cl,
 *                        wcr_wall_push). A uniform pressure's pairs have a part along the wall
 *                        where the first row is not a lattice over the dummies': in the channel
 *                        at N_f = 40 a push of 1% of τ_w on the fluid, which lowers the drive
 *                        that holds U_b; with "normal" the walls' friction is the drive within
 *                        0.2%, and u_τ from either +1.5% of the grid limit (the drive's +1.0%
 *                        with the push; cases/channel_ke.lua, README)
 *   momentum_dissipation "riemann" (eq 19's dissipative term between fluid pairs; the default of
 *                        a laminar scene or one with ARD), "reconstructed" (the jump less
 *                        ½ (∇v_i + ∇v_j) r_ij with the k-ε model's velocity gradients; the
 *                        default under the model without ARD; acoustic.cl says why) or "off"
 *   outlet               a natural exit's pressure: "characteristic" (default; see open_layers)
 *                        or "fixed" (p = 0: the paper's zero-pressure outlet, which reflects
 *                        sound)
 *   advection_cfl, acoustic_cfl  CFL_ad (0.25) and CFL_ac (0.6)
 *   walls, wall_layers   as for every scheme (dummy walls, 3 layers: the support is 2.6 dr).
 *   gate, gate_speed, gate_start, gate_stop  a wall group lifted against gravity (solvers/gate):
 *                        its dummies move once per acoustic sub-step; the wall's acceleration
 *                        does not enter the dummies' pressure (impulsive at the start and stop).
 * Room for the k-ε model (its own issue): the viscosity enters the viscous sums as µ̃_ij, and
 * config.cl measures every fluid particle's distance to the nearest dummy particle (field
 * wall_dist), which picks out the wall-adjacent layers of the wall model. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../scheme.h"
#include "clsph_config.h"
#include "gate.h"
#include "open.h"
#include "kepsilon.h"
#include "sim.h"
#include "sound.h"

enum { WCR_TVF_OFF = 0, WCR_TVF_FULL = 1, WCR_TVF_LIMITED = 2 };
enum { WCR_REINIT_OFF = 0, WCR_REINIT_SUM = 1, WCR_REINIT_FREE = 2 };

struct wcr {
  int f_rho, f_p, f_drho, f_ard, f_wall, f_wdist, f_wnormal;
  cl_uint maxn;                   /* neighbour list stride */
  cl_mem d_nlist, d_ncount;       /* neighbour list of the advection step */
  cl_mem d_bmat, d_sigma;         /* B (4 reals) and the normalised kernel sum */
  cl_mem d_prior, d_shift, d_acc; /* a_prior, the TVF correction, dv/dt of a sub-step */
  cl_mem d_partial, d_force, d_mask, d_none;
  cl_mem d_gradp; /* ∇p of the near-wall particles (wall_pressure = "gradient") */
  real *h_partial, *h_force;
  size_t cap;
  cl_kernel k_config, k_count, k_adv, k_drift, k_mom, k_cont, k_force, k_lattice;
  double c0, p_bg, mass, sigma0, lambda, u_scale;
  double cfl_ad, cfl_ac, tvf_alpha;
  int tvf, ard, wall_full, cont_riemann, outlet_fixed, mom_diss, wall_pgrad, shear_dist;
  int grad_log;     /* velocity_gradient = "log" (turbulence.cl) */
  int diff_log;     /* turbulent_diffusion = "log_mirror" (turbulence.cl) */
  int carry;        /* offset_layer = "body_force" (advection.cl) */
  int wall_pnormal; /* wall_pressure_force = "normal" (acoustic.cl) */
  int tvf_surface;  /* 1: the correction's tangential part in the surface rows (advection.cl) */
  cl_uint reinit;
  double vmax;               /* the fluid's largest speed at the last max_dt, m/s */
  int configured;            /* the list and B have been made ... */
  unsigned long sorted;      /* ... in the particles' order after this many sorts (sim->sorts) */
  struct open_sections open; /* inflow and outflow sections (solvers/open), nsec = 0: none */
  double *exit_p, *exit_rho; /* per section: the exits' p and ρ of this advection step */
  double ubar0; /* the natural exits' outflow speed at the start (open_initial_outflow), m/s */
  /* the k-ε model (turbulence.cl), when the scene declares turbulence { } */
  int turb;
  struct kepsilon ke; /* k, epsilon, nu_t and the update's buffers (solvers/kepsilon) */
  int f_yplus;
  cl_mem d_frame, d_wallv, d_grad;
  cl_mem d_logf; /* velocity_gradient = "log": the wall's normal and y per particle */
  cl_mem d_row1; /* wall_shear = "first_row": D_b of the first dummy layer (turbulence.cl) */
  cl_kernel k_twall, k_ttrans, k_tupd, k_logf, k_row1;
  double y_p, w_s;  /* the wall model's distance and weight */
  double wscale;    /* eq 39's force over its lattice sum (wall_shear = "distance"; else 1) */
  struct gate gate; /* a lifted wall group (solvers/gate), e.g. the Lobovsky dam break's gate */
  /* the walls' force record (force.cl) of the scene's force groups: per fluid particle and
   * group, the reactions of its wall pairs over the last step (field f_rec, nrec groups) */
  int f_rec;
  cl_uint nrec, nwall_map;
  cl_mem d_wgroup; /* per wall (scene walls): 1 + its force group, 0: not recorded */
  long rec_steps;  /* steps recorded here (a restart finds its record in the checkpoint) */
};

static const char *const sources[] = {OPEN_SOURCES,
                                      GATE_SOURCES,
                                      "common/lattice.cl",
                                      "wcsph_riemann/config.cl",
                                      "wcsph_riemann/advection.cl",
                                      "wcsph_riemann/acoustic.cl",
                                      "wcsph_riemann/force.cl",
                                      "common/kepsilon.cl",          /* empty unless KE_ON */
                                      "wcsph_riemann/turbulence.cl", /* empty unless WCR_TURB */
                                      NULL};
static const char *const turbulence_models[] = {"k-epsilon", NULL};
static const char *const options[] = {"sound_speed",
                                      "background_pressure",
                                      "transport_velocity",
                                      "ard",
                                      "density",
                                      "wall_dissipation",
                                      "wall_pressure",
                                      "momentum_dissipation",
                                      "wall_shear",
                                      "velocity_gradient",
                                      "turbulent_diffusion",
                                      "offset_layer",
                                      "wall_pressure_force",
                                      "outlet",
                                      "continuity",
                                      "transport_coefficient",
                                      "surface_transport",
                                      "advection_cfl",
                                      "acoustic_cfl",
                                      "walls",
                                      "wall_layers",
                                      "gate",
                                      "gate_speed",
                                      "gate_start",
                                      "gate_stop",
                                      NULL};

static const struct scene_option *option(const struct scene *s, const char *key)
{
  for (int i = 0; i < s->noptions; ++i)
    if (strcmp(s->options[i].key, key) == 0) return &s->options[i];
  return NULL;
}

/* a text option among `names` (NULL-terminated): its index, or `fallback` when not given */
static enum clsph_status option_choice(const struct scene *s, const char *key,
                                       const char *const *names, int fallback, int *out)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene_option *o = option(s, key);
  *out = fallback;
  if (o == NULL) goto done;
  char list[160] = "";
  size_t used = 0;
  for (int k = 0; names[k] != NULL; ++k) {
    if (!o->is_number && strcmp(o->text, names[k]) == 0) {
      *out = k;
      goto done;
    }
    used += (size_t)snprintf(list + used, used < sizeof list ? sizeof list - used : 0, "%s\"%s\"",
                             k ? ", " : "", names[k]);
  }
  CLSPH_CHECK(0, CLSPH_E_INPUT, "%s: wcsph-riemann option %s must be one of %s", s->case_path, key,
              list);
done:
  return st;
}

/* a text option of the k-ε model among `names`: its index (0, the default, when not given);
 * any other choice in a laminar scene is refused, `what` saying what it sets */
static enum clsph_status turb_choice(const struct scene *s, const char *key,
                                     const char *const *names, const char *what, int *out)
{
  enum clsph_status st = CLSPH_OK;
  CLSPH_TRY(option_choice(s, key, names, 0, out));
  CLSPH_CHECK(*out == 0 || s->turb.on, CLSPH_E_INPUT,
              "%s: wcsph-riemann option %s = \"%s\" belongs to the k-ε model (turbulence { "
              "model = \"k-epsilon\" }): %s; a laminar scene has none: drop it",
              s->case_path, key, names[*out], what);
done:
  return st;
}

static enum clsph_status option_number(const struct scene *s, const char *key, double lo, double hi,
                                       const char *what, double *v)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene_option *o = option(s, key);
  if (o == NULL) goto done;
  CLSPH_CHECK(o->is_number && o->number >= lo && o->number <= hi, CLSPH_E_INPUT,
              "%s: wcsph-riemann option %s must be %s, from %g to %g", s->case_path, key, what, lo,
              hi);
  *v = o->number;
done:
  return st;
}

/* the options, with the checks on the sound speed and the two time steps; `verbose`: log what
 * was chosen (once, from create; define reads them first to choose the switches) */
static enum clsph_status read_options(const struct sim *sim, struct wcr *w, int verbose)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *sc = sim->scene;
  static const char *const tvf_names[] = {"off", "full", "limited", NULL};
  static const char *const dens_names[] = {"continuity", "summation", "free_surface", NULL};
  static const char *const wall_names[] = {"limited", "full", NULL};
  const int gravity = hypot(hypot(sc->gravity[0], sc->gravity[1]), sc->gravity[2]) > 0.0;
  int reinit = 0;
  CLSPH_TRY(option_choice(sc, "transport_velocity", tvf_names, WCR_TVF_LIMITED, &w->tvf));
  /* the density's default: re-set by summation without a free surface, to max(ρ, ρ_sum) under
   * one. Summation makes the pressure c0² (ρ_sum − ρ0) a function of the particles' positions,
   * and c0² times their disorder is a pressure error that grows with c0: behind the square
   * cylinder (cases/square_cylinder.lua, Re = 20, H/40) C_D was 3.44 at c0 = 10 U0 and 4.70 at
   * 20 U0 with it, 2.79 and 2.84 with the continuity equation alone (Breuer 2.40; at H/80 2.72
   * and 2.44), which that case therefore chooses. But the summation is the better in the
   * lid-driven cavity (u RMS against Ghia at 50², Re = 100: 0.0048 U against 0.015 U) and in the
   * Poiseuille channel between an entry and an exit (cases/poiseuille_open.lua, dr = 0.1,
   * c0 = 30: u RMS 0.6% against 3.5%, the bulk pressure gradient 1.1% low against 8.8%). */
  CLSPH_TRY(option_choice(sc, "density", dens_names, gravity ? WCR_REINIT_FREE : WCR_REINIT_SUM,
                          &reinit));
  w->reinit = (cl_uint)reinit;
  CLSPH_TRY(option_choice(sc, "wall_dissipation", wall_names, 0, &w->wall_full));
  static const char *const wallp_names[] = {"mirror", "gradient", NULL};
  /* the gradient under the k-ε model: the mirror's wall-adjacent row feels 0.78 of a pressure
   * gradient along the wall, and the wall model's rows are where separation starts (HCD channel,
   * N_f = 40: u RMS off OpenFOAM's at x = 9.5 0.137 → 0.085 U_b; README's wall_pressure) */
  CLSPH_TRY(option_choice(sc, "wall_pressure", wallp_names, sc->turb.on ? 1 : 0, &w->wall_pgrad));
  static const char *const cont_names[] = {"plain", "riemann", NULL};
  CLSPH_TRY(option_choice(sc, "continuity", cont_names, 1, &w->cont_riemann));
  static const char *const outlet_names[] = {"characteristic", "fixed", NULL};
  CLSPH_TRY(option_choice(sc, "outlet", outlet_names, 0, &w->outlet_fixed));
  double ard = 0.0;
  CLSPH_TRY(option_number(sc, "ard", 0.0, 1.0, "1 (on) or 0 (off)", &ard));
  CLSPH_CHECK(ard == 0.0 || ard == 1.0, CLSPH_E_INPUT,
              "%s: wcsph-riemann option ard must be 1 (on) or 0 (off)", sc->case_path);
  w->ard = ard == 1.0;
  static const char *const mom_names[] = {"off", "riemann", "reconstructed", NULL};
  CLSPH_TRY(option_choice(sc, "momentum_dissipation", mom_names, sc->turb.on && !w->ard ? 2 : 1,
                          &w->mom_diss));
  CLSPH_CHECK(!(w->ard && w->mom_diss != 1), CLSPH_E_INPUT,
              "%s: wcsph-riemann option momentum_dissipation = \"%s\" contradicts ard = 1, which "
              "turns the same dissipation into a viscosity (eq 32): drop one of them",
              sc->case_path, mom_names[w->mom_diss]);
  CLSPH_CHECK(w->mom_diss != 2 || sc->turb.on, CLSPH_E_INPUT,
              "%s: wcsph-riemann option momentum_dissipation = \"reconstructed\" needs the "
              "velocity gradient of the k-ε model (turbulence { model = \"k-epsilon\" }); a "
              "laminar scene takes \"riemann\" or \"off\"",
              sc->case_path);
  static const char *const shear_names[] = {"y_p", "distance", "first_row", NULL};
  CLSPH_TRY(turb_choice(sc, "wall_shear", shear_names, "where its wall model reads the log law",
                        &w->shear_dist));
  static const char *const grad_names[] = {"kernel", "log", NULL};
  CLSPH_TRY(turb_choice(sc, "velocity_gradient", grad_names, "its velocity gradient next to a wall",
                        &w->grad_log));
  static const char *const diff_names[] = {"harmonic", "log_mirror", NULL};
  CLSPH_TRY(
      turb_choice(sc, "turbulent_diffusion", diff_names, "its diffusion of k and ε", &w->diff_log));
  static const char *const carry_names[] = {"none", "body_force", NULL};
  CLSPH_TRY(turb_choice(sc, "offset_layer", carry_names,
                        "its wall model's layer below the offset boundary", &w->carry));
  static const char *const pforce_names[] = {"corrected", "normal", NULL};
  CLSPH_TRY(turb_choice(sc, "wall_pressure_force", pforce_names,
                        "the direction of the walls' pressure force next to its wall model",
                        &w->wall_pnormal));
  static const char *const surf_names[] = {"off", "tangential", "pairs", NULL};
  /* "pairs" in a 3-D free-surface flow, off otherwise (the 2-D runs' validated default) */
  const int surf_default =
      sc->dim == 3 && w->tvf != WCR_TVF_OFF && reinit == WCR_REINIT_FREE ? 2 : 0;
  CLSPH_TRY(option_choice(sc, "surface_transport", surf_names, surf_default, &w->tvf_surface));
  CLSPH_CHECK(!w->tvf_surface || (w->tvf != WCR_TVF_OFF && reinit == WCR_REINIT_FREE),
              CLSPH_E_INPUT,
              "%s: wcsph-riemann option surface_transport = \"%s\" needs the transport "
              "velocity (transport_velocity \"limited\" or \"full\") and a free surface "
              "(density = \"free_surface\", the default under gravity)",
              sc->case_path, surf_names[w->tvf_surface]);
  w->tvf_alpha = 0.2; /* eq 25 */
  /* 0.5 blew the 30² cavity up at its ninth step: the correction overshoots */
  CLSPH_TRY(option_number(sc, "transport_coefficient", 0.0, 0.3, "α of eq 25", &w->tvf_alpha));
  w->cfl_ad = 0.25;
  w->cfl_ac = 0.6;
  /* at most the paper's 0.25: the neighbour lists' skin covers the moves of such a step */
  CLSPH_TRY(option_number(sc, "advection_cfl", 1e-3, 0.25, "a CFL number", &w->cfl_ad));
  /* beyond c0 Δt = h the Riemann sub-step outruns the support */
  CLSPH_TRY(option_number(sc, "acoustic_cfl", 1e-3, 1.0, "a CFL number", &w->cfl_ac));
  CLSPH_TRY(option_number(sc, "background_pressure", 0.0, 1e12, "a pressure in Pa", &w->p_bg));
  CLSPH_TRY(gate_read(sc, "wcsph-riemann", &w->gate));
  /* the sound speed: 10 U by default, and the Mach number it implies */
  struct sound_scale vs;
  sound_velocity_scale(sc, &sim->geom, &vs);
  w->u_scale = vs.u;
  const struct scene_option *o = option(sc, "sound_speed");
  w->c0 = 10.0 * vs.u;
  if (o != NULL) {
    CLSPH_CHECK(o->is_number && o->number > 0.0 && isfinite(o->number), CLSPH_E_INPUT,
                "%s: wcsph-riemann option sound_speed must be a positive speed (m/s)",
                sc->case_path);
    w->c0 = o->number;
  }
  CLSPH_CHECK(w->c0 > 0.0, CLSPH_E_INPUT,
              "%s: wcsph-riemann needs a sound speed: nothing drives the flow (no gravity, moving "
              "wall, inflow, flow-rate control nor initial velocity): set the scheme option "
              "sound_speed (m/s), about 10 times the largest speed expected",
              sc->case_path);
  /* density varies as the square of the Mach number: 1% at U/c0 = 0.1, 9% at 0.3 */
  const double mach = vs.u / w->c0;
  CLSPH_CHECK(mach <= 0.3, CLSPH_E_INPUT,
              "%s: wcsph-riemann option sound_speed = %g m/s is too low for the scene's velocity "
              "scale U = %g m/s (%s): Mach U/c0 = %.3g lets the density vary by about %.0f%%; a "
              "weakly-compressible flow needs Mach 0.1 or less (c0 >= %g m/s)",
              sc->case_path, w->c0, vs.u, vs.what, mach, 100.0 * mach * mach, 10.0 * vs.u);
  if (verbose && mach > 0.1)
    log_warn("%s: wcsph-riemann: Mach U/c0 = %.3g (U = %g m/s from %s, c0 = %g m/s): density "
             "varies by about %.1f%%",
             sc->case_path, mach, vs.u, vs.what, w->c0, 100.0 * mach * mach);
  /* the dual criteria: an advection step must hold at least one acoustic step at the velocity
   * scale, Δt_ad/Δt_ac = (CFL_ad/CFL_ac)(c0 + U)/U >= 1 */
  if (vs.u > 0.0) {
    const double ratio = (w->cfl_ad / w->cfl_ac) * (w->c0 + vs.u) / vs.u;
    CLSPH_CHECK(ratio >= 1.0, CLSPH_E_INPUT,
                "%s: wcsph-riemann options advection_cfl = %g and acoustic_cfl = %g make the "
                "advection step %.3g times the acoustic step at U = %g m/s, c0 = %g m/s: the "
                "dual-criteria scheme needs an advection step at least as long (raise "
                "advection_cfl or lower acoustic_cfl)",
                sc->case_path, w->cfl_ad, w->cfl_ac, ratio, vs.u, w->c0);
  }
  if (verbose)
    log_info("wcsph-riemann: c0 = %.4g m/s (%s; U = %.4g m/s from %s, Mach %.3g), background "
             "pressure %.4g Pa, transport velocity %s%s%s, ARD %s, density %s, walls' "
             "dissipation %s, fluid pairs' momentum dissipation %s%s%s%s%s%s%s",
             w->c0, o != NULL ? "option sound_speed" : "10 U", vs.u, vs.what, mach, w->p_bg,
             tvf_names[w->tvf], w->tvf_surface ? " (surface rows: " : "",
             w->tvf_surface ? (w->tvf_surface == 1 ? "tangential)" : "pairs)") : "",
             w->ard ? "on" : "off", dens_names[reinit], wall_names[w->wall_full],
             mom_names[w->mom_diss],
             w->wall_pgrad ? ", walls' pressure extrapolated along them with ∇p" : "",
             w->shear_dist == 1   ? ", the wall model's shear at each particle's distance"
             : w->shear_dist == 2 ? ", the wall model's shear on the first row only"
                                  : "",
             w->grad_log ? ", the velocity gradient in the log law's coordinate by the walls" : "",
             w->diff_log ? ", k and ε diffused with the log mean and the walls' mirror" : "",
             w->carry ? ", the offset layer's body force on the first row" : "",
             w->wall_pnormal ? ", the walls' pressure force along their normal" : "");
done:
  return st;
}

/* the skin of the neighbour list for an advection step dt at speed v: twice the farthest a
 * particle goes, with 10% for the speeds gained during the step, at most what the grid's cells
 * cover (2.2 CFL_ad h max(cfl, 1) at CFL_ad = 0.25: WCR_SKIN of the support, scheme_ops) */
#define WCR_SKIN 0.275
static double list_skin(const struct sim *sim, double v, double dt)
{
  const double most = WCR_SKIN * fmax(sim->scene->cfl, 1.0) * sim->sm.support;
  return fmin(2.2 * v * dt, most);
}

/* the stride of the neighbour list: twice the neighbours of a full list radius (support and the
 * largest skin) on the lattice (π q², q = radius/dr: 35 at h = 1.3 dr), and 8, to a multiple of
 * 4. In 3-D 1.6 times the ball's (4/3) π q³ (153 at h = 1.3 dr): the list is most of a 3-D
 * particle's memory (twice the 2-D margin would be 1.3 KB a particle), and a fluid compressed by
 * 1% holds 3% more neighbours; a list that overflows stops the run with its flag. */
static long list_stride(const struct sim *sim)
{
  const double q = (sim->sm.support + list_skin(sim, HUGE_VAL, 1.0)) / sim->scene->dr;
  const double pi = 3.141592653589793;
  const double fill = sim->scene->dim == 3 ? 1.6 * 4.0 / 3.0 * pi * q * q * q : 2.0 * pi * q * q;
  return 4 * (((long)ceil(fill) + 8 + 3) / 4);
}

static enum clsph_status wcr_define(const struct sim *sim, struct prog_opts *o)
{
  enum clsph_status st = CLSPH_OK;
  struct wcr w;
  memset(&w, 0, sizeof w);
  /* the options decide the switches; read_options reports a bad one here, before the build */
  CLSPH_TRY(read_options(sim, &w, 0));
  CLSPH_TRY(prog_opts_define_int(o, "WCR_MAXN", list_stride(sim)));
  CLSPH_TRY(prog_opts_define_int(o, "WCR_ARD", w.ard));
  CLSPH_TRY(prog_opts_define_int(o, "WCR_WALL_FULL", w.wall_full));
  CLSPH_TRY(prog_opts_define_int(o, "WCR_WALL_PGRAD", w.wall_pgrad));
  CLSPH_TRY(prog_opts_define_int(o, "WCR_MOM_DISS", w.mom_diss));
  CLSPH_TRY(prog_opts_define_int(o, "WCR_CONT_RIEMANN", w.cont_riemann));
  CLSPH_TRY(prog_opts_define_int(o, "WCR_WALL_CONT_NORMAL", w.reinit == WCR_REINIT_OFF));
  CLSPH_TRY(prog_opts_define_int(o, "WCR_TURB", sim->scene->turb.on));
  CLSPH_TRY(prog_opts_define_int(o, "WCR_SHEAR_DIST", w.shear_dist == 1));
  CLSPH_TRY(prog_opts_define_int(o, "WCR_SHEAR_ROW1", w.shear_dist == 2));
  CLSPH_TRY(prog_opts_define_int(o, "WCR_GRAD_LOG", w.grad_log));
  CLSPH_TRY(prog_opts_define_int(o, "WCR_OFFSET_LAYER", w.carry));
  CLSPH_TRY(prog_opts_define_int(o, "WCR_WALL_PNORMAL", w.wall_pnormal));
  CLSPH_TRY(prog_opts_define_int(o, "WCR_KE_DIFF", w.diff_log));
  CLSPH_TRY(prog_opts_define_int(o, "KE_ON", sim->scene->turb.on));
  CLSPH_TRY(prog_opts_define_int(o, "WCR_GATE", w.gate.on));
  CLSPH_TRY(prog_opts_define_int(o, "WCR_TVF_SURFACE", w.tvf_surface));
  CLSPH_TRY(prog_opts_define_int(o, "WCR_REC", sim->scene->dim == 2 ? sim->scene->nforces : 0));
  CLSPH_TRY(open_define(sim, o)); /* the sections (solvers/open) */
done:
  return st;
}

/* a field from the geometry's per-particle doubles, or zero */
static enum clsph_status add_field(struct sim *sim, const char *name, const real *init, int out,
                                   int *f)
{
  enum clsph_status st = CLSPH_OK;
  CLSPH_TRY(pset_add(&sim->ps, sim->dev, name, sizeof(real), init, f));
  pset_describe(&sim->ps, *f, PF_REAL, 1, out);
done:
  return st;
}

static void wcr_destroy(void *state);

/* The walls' force record (force.cl): a field of 4 reals per force group (pressure x, y,
 * viscous x, y) that the step's kernels fill, and the map from the scene's walls to the groups.
 * A group named twice records once, under its first name. */
static enum clsph_status record_create(struct sim *sim, struct wcr *w)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *sc = sim->scene;
  const cl_uint nw = (cl_uint)(sc->nwalls > 0 ? sc->nwalls : 1);
  cl_uint *map = calloc(nw, sizeof *map);
  CLSPH_CHECK(map != NULL, CLSPH_E_NOMEM, "out of memory");
  for (int k = 0; k < sc->nwalls; ++k)
    for (int g = 0; g < sc->nforces && map[k] == 0; ++g)
      if (strcmp(sc->walls[k].group, sc->forces[g]) == 0) map[k] = (cl_uint)g + 1u;
  w->nrec = (cl_uint)sc->nforces;
  w->nwall_map = nw;
  CLSPH_TRY(kern_buffer(sim->dev, nw * sizeof *map, map, &w->d_wgroup, "wall force groups"));
  CLSPH_TRY(
      pset_add(&sim->ps, sim->dev, "wall_record", w->nrec * 4 * sizeof(real), NULL, &w->f_rec));
  pset_describe(&sim->ps, w->f_rec, PF_REAL, (int)(4 * w->nrec), 0);
done:
  free(map);
  return st;
}

/* The k-ε model's fields (k, epsilon, nu_t, y_plus: outputs), buffers and kernels; a laminar
 * scene makes none of them. The initial k and ε are the declared ones everywhere; ν_t starts
 * from them (eq 6), or from nu_t through a delay. */
static enum clsph_status turb_create(struct sim *sim, struct wcr *w)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene_turbulence *t = &sim->scene->turb;
  const size_t cap = sim->ps.cap;
  real *zeros = NULL;
  CLSPH_CHECK(t->wall_law < 0, CLSPH_E_INPUT,
              "%s:%d: turbulence: wall_law belongs to the USAW schemes' wall law (Leroy et al. eq "
              "23); wcsph-riemann's wall model (Wang, Sun & Hu eqs 10-11) sits at y_p: drop it",
              sim->scene->case_path, t->line);
  CLSPH_CHECK(t->production < 0, CLSPH_E_INPUT,
              "%s:%d: turbulence: production belongs to the USAW schemes' model (Leroy et al. eq "
              "20); wcsph-riemann's production is Wang, Sun & Hu's: drop it",
              sim->scene->case_path, t->line);
  w->turb = 1;
  w->y_p = t->y_p > 0.0 ? t->y_p : 0.5 * sim->scene->dr;
  CLSPH_CHECK(!w->carry || w->y_p >= 0.5 * sim->scene->dr, CLSPH_E_INPUT,
              "%s:%d: turbulence: y_p = %g is under half the particle spacing (dr = %g), so there "
              "is no layer below the first row for wcsph-riemann's offset_layer = \"body_force\": "
              "raise y_p (the boundary offset is y_p - dr/2) or drop the option",
              sim->scene->case_path, t->line, w->y_p, sim->scene->dr);
  w->w_s = isnan(t->wall_weight) ? (w->ard ? 0.5 : 0.1) : t->wall_weight; /* sec 4.3 */
  CLSPH_TRY(kepsilon_create(sim, t->delay > 0.0 ? t->nu_t_delay : (double)NAN, &w->ke));
  CLSPH_TRY(add_field(sim, "y_plus", NULL, 1, &w->f_yplus));
  CLSPH_TRY(kern_buffer(sim->dev, cap * 4 * sizeof(real), NULL, &w->d_frame, "wall frames"));
  /* zero until the model starts (after its delay): the dissipation then takes the plain jump */
  zeros = calloc(cap * 4, sizeof *zeros);
  CLSPH_CHECK(zeros != NULL, CLSPH_E_NOMEM, "out of memory");
  CLSPH_TRY(kern_buffer(sim->dev, cap * 4 * sizeof(real), zeros, &w->d_grad, "velocity gradients"));
  CLSPH_TRY(kern_buffer(sim->dev, cap * 2 * sizeof(real), NULL, &w->d_wallv, "wall stresses"));
  CLSPH_TRY(prog_kernel(sim->prog, "wcr_turb_wall", &w->k_twall));
  CLSPH_TRY(prog_kernel(sim->prog, "wcr_turb_transport", &w->k_ttrans));
  CLSPH_TRY(prog_kernel(sim->prog, "wcr_turb_update", &w->k_tupd));
  if (w->grad_log) {
    CLSPH_TRY(kern_buffer(sim->dev, cap * 4 * sizeof(real), NULL, &w->d_logf, "log frames"));
    CLSPH_TRY(prog_kernel(sim->prog, "wcr_log_frame", &w->k_logf));
  }
  if (w->shear_dist == 2) {
    CLSPH_TRY(kern_buffer(sim->dev, cap * sizeof(real), NULL, &w->d_row1, "first-row densities"));
    CLSPH_TRY(prog_kernel(sim->prog, "wcr_row1_density", &w->k_row1));
  }
done:
  free(zeros);
  return st;
}

static enum clsph_status wcr_create(struct sim *sim, void **state)
{
  enum clsph_status st = CLSPH_OK;
  struct wcr *w = calloc(1, sizeof *w);
  const struct geom *geo = &sim->geom;
  const struct scene *sc = sim->scene;
  struct pset *ps = &sim->ps;
  real *buf = NULL;
  cl_uint *ubuf = NULL;
  CLSPH_CHECK(w != NULL, CLSPH_E_NOMEM, "wcsph-riemann: out of memory");
  CLSPH_TRY(read_options(sim, w, 1));
  for (size_t i = 0; i < geo->n; ++i)
    CLSPH_CHECK(geo->kind[i] != KIND_VERTEX, CLSPH_E_UNSUPPORTED,
                "%s: wcsph-riemann has no semi-analytical walls: its walls are dummy particles "
                "(particle kind %d)",
                sc->case_path, geo->kind[i]);
  w->maxn = (cl_uint)list_stride(sim);
  const size_t dim = (size_t)sc->dim, stride = dim == 3 ? 4 : 2;             /* realv */
  const double vol0 = dim == 3 ? sc->dr * sc->dr * sc->dr : sc->dr * sc->dr; /* dr^DIM */
  w->mass = sc->rho0 * vol0;
  w->cap = ps->cap;
  /* fields: ρ and p from the hydrostatic state under gravity (or fill { pressure/density }),
   * dρ/dt (carried from one step's last sub-step to the next's first), the wall each dummy
   * particle belongs to, the distance to the wall, the ARD indicator */
  buf = calloc(stride * geo->n + 1, sizeof *buf);
  ubuf = calloc(geo->n + 1, sizeof *ubuf);
  CLSPH_CHECK(buf != NULL && ubuf != NULL, CLSPH_E_NOMEM, "out of memory");
  const double gn = hypot(hypot(sc->gravity[0], sc->gravity[1]), sc->gravity[2]);
  double up[3] = {0.0, 0.0, 0.0}, ztop = -HUGE_VAL;
  for (size_t a = 0; a < dim && gn > 0.0; ++a) up[a] = -sc->gravity[a] / gn;
  for (size_t i = 0; i < geo->nfluid; ++i) {
    double z = 0.5 * sc->dr;
    for (size_t a = 0; a < dim; ++a) z += up[a] * geo->x[dim * i + a];
    ztop = fmax(ztop, z);
  }
  for (size_t i = 0; i < geo->n; ++i) {
    double z = 0.0;
    for (size_t a = 0; a < dim; ++a) z += up[a] * geo->x[dim * i + a];
    double ph = geo->kind[i] == KIND_FLUID && gn > 0.0 ? sc->rho0 * gn * (ztop - z) : 0.0;
    if (i < geo->nfluid && isfinite(geo->rho0[i]))
      ph = w->c0 * w->c0 * (geo->rho0[i] - sc->rho0);
    else if (i < geo->nfluid && isfinite(geo->p0[i]))
      ph = geo->p0[i];
    buf[i] = (real)(sc->rho0 + ph / (w->c0 * w->c0));
    buf[geo->n + i] = (real)ph;
  }
  CLSPH_TRY(add_field(sim, "rho", buf, 1, &w->f_rho));
  CLSPH_TRY(add_field(sim, "p", buf + geo->n, 1, &w->f_p));
  /* volumes: m/ρ for the fluid, dr^DIM for the dummy particles */
  for (size_t i = 0; i < geo->n; ++i)
    buf[i] = geo->kind[i] == KIND_FLUID ? (real)(w->mass / (double)buf[i]) : (real)vol0;
  CLSPH_TRY(kern_write(sim->dev, pset_mem(ps, sim->f_vol), geo->n * sizeof(real), buf));
  CLSPH_TRY(add_field(sim, "drho", NULL, 0, &w->f_drho));
  /* wall_dist: the depth of a dummy particle behind its wall; a fluid particle's distance from
   * the nearest wall (config.cl); wall_normal: a dummy particle's normal into the fluid */
  for (size_t i = 0; i < geo->n; ++i) buf[i] = (real)geo->dist[i];
  CLSPH_TRY(add_field(sim, "wall_dist", buf, 1, &w->f_wdist));
  /* (the padding of a 3-D real4 stays 0: every length and dot product reads it) */
  memset(buf, 0, (stride * geo->n + 1) * sizeof *buf);
  for (size_t i = 0; i < geo->n; ++i)
    for (size_t a = 0; a < dim; ++a) buf[stride * i + a] = (real)geo->normal[dim * i + a];
  CLSPH_TRY(pset_add(ps, sim->dev, "wall_normal", stride * sizeof(real), buf, &w->f_wnormal));
  pset_describe(ps, w->f_wnormal, PF_REAL, (int)stride, 0);
  w->f_ard = -1;
  if (w->ard) CLSPH_TRY(add_field(sim, "ard", NULL, 1, &w->f_ard));
  w->ke.f_k = w->ke.f_eps = w->ke.f_nut = w->f_yplus = -1;
  if (sc->turb.on) CLSPH_TRY(turb_create(sim, w));
  for (size_t i = 0; i < geo->n; ++i)
    ubuf[i] =
        geo->kind[i] == KIND_DUMMY && geo->group[i] >= 0 ? (cl_uint)geo->group[i] : 0xffffffffu;
  CLSPH_TRY(pset_add(ps, sim->dev, "wall", sizeof(cl_uint), ubuf, &w->f_wall));
  pset_describe(ps, w->f_wall, PF_UINT, 1, 0);
  w->f_rec = -1;
  if (dim == 2 && sc->nforces > 0) CLSPH_TRY(record_create(sim, w));
  CLSPH_TRY(gate_check(sim, &w->gate, "wcsph-riemann"));
  CLSPH_TRY(gate_create(sim, &w->gate));
  /* the entry and exit layers: their velocity in a field of their own (the fluid's vel is the
   * scheme's state; the layers' geometry velocity u_in or the exit profile goes to "open_u") */
  CLSPH_TRY(open_create(sim, -1, &w->open));
  if (w->open.nsec > 0) {
    w->exit_p = calloc(2 * w->open.nsec, sizeof *w->exit_p);
    CLSPH_CHECK(w->exit_p != NULL, CLSPH_E_NOMEM, "out of memory");
    w->exit_rho = w->exit_p + w->open.nsec;
    w->ubar0 = open_initial_outflow(sim);
  }
  /* the advection step's buffers (the particles' current order; remade every step) */
  const size_t cap = ps->cap, rv = stride * sizeof(real), groups = sim_reduce_groups(cap);
  const size_t rm = (dim == 3 ? 8 : 4) * sizeof(real); /* B: wcr_mat (config.cl) */
  CLSPH_TRY(
      kern_buffer(sim->dev, cap * w->maxn * sizeof(cl_uint), NULL, &w->d_nlist, "neighbour list"));
  CLSPH_TRY(kern_buffer(sim->dev, cap * sizeof(cl_uint), NULL, &w->d_ncount, "neighbour counts"));
  CLSPH_TRY(kern_buffer(sim->dev, cap * rm, NULL, &w->d_bmat, "correction B"));
  CLSPH_TRY(kern_buffer(sim->dev, cap * sizeof(real), NULL, &w->d_sigma, "kernel sums"));
  CLSPH_TRY(kern_buffer(sim->dev, cap * rv, NULL, &w->d_prior, "prior acceleration"));
  CLSPH_TRY(kern_buffer(sim->dev, cap * rv, NULL, &w->d_shift, "transport correction"));
  CLSPH_TRY(kern_buffer(sim->dev, cap * rv, NULL, &w->d_acc, "acceleration"));
  CLSPH_TRY(kern_buffer(sim->dev, (groups + 1) * sizeof(real), NULL, &w->d_partial, "partials"));
  CLSPH_TRY(kern_buffer(sim->dev, sizeof(real), NULL, &w->d_none, "placeholder"));
  if (w->wall_pgrad) { /* zero until the first sub-step: a force output at t = 0 reads it */
    const real zero = (real)0.0;
    CLSPH_TRY(kern_buffer(sim->dev, cap * rv, NULL, &w->d_gradp, "wall pressure gradient"));
    CLSPH_TRY(kern_fill(sim->dev, w->d_gradp, &zero, sizeof zero, cap * rv));
  }
  w->h_partial = calloc(groups + 1, sizeof *w->h_partial);
  CLSPH_CHECK(w->h_partial != NULL, CLSPH_E_NOMEM, "out of memory");
  const char *names[] = {"wcr_config",   "wcr_count_pairs", "wcr_advection",  "wcr_drift",
                         "wcr_momentum", "wcr_continuity",  "wcr_wall_force", "lattice_sums"};
  cl_kernel *ks[] = {&w->k_config, &w->k_count, &w->k_adv,   &w->k_drift,
                     &w->k_mom,    &w->k_cont,  &w->k_force, &w->k_lattice};
  for (size_t k = 0; k < sizeof ks / sizeof *ks; ++k)
    CLSPH_TRY(prog_kernel(sim->prog, names[k], ks[k]));
  /* sigma0: the kernel sum of a full support on the lattice */
  const real dr = (real)sc->dr;
  const struct smooth_dev smd = smoothing_dev(&sim->sm);
  CLSPH_TRY(KERN_SET(w->k_lattice, KARG(smd), KARG(dr), KARG(w->d_partial)));
  CLSPH_TRY(kern_launch(sim->dev, w->k_lattice, 1, NULL));
  CLSPH_TRY(kern_read(sim->dev, w->d_partial, 2 * sizeof(real), w->h_partial));
  w->sigma0 = (double)w->h_partial[0];
  w->lambda = (double)w->h_partial[1];
  CLSPH_CHECK(w->sigma0 > 0.5 && w->sigma0 < 1.5 && w->lambda > 0.5 && w->lambda < 1.5,
              CLSPH_E_INPUT,
              "%s: wcsph-riemann: the kernel sum of the lattice is %g and its Laplacian's %g, not "
              "about 1: the smoothing length (h_over_dr) is too small for the particle spacing",
              sc->case_path, w->sigma0, w->lambda);
  w->wscale = 1.0;
  if (w->turb && w->shear_dist == 2)
    log_info("wcsph-riemann: the wall model's shear on the first row only, τ_w over each "
             "particle's share of the wall from the first dummy layer");
  if (w->turb && w->shear_dist == 1) { /* eq 39's lattice sum (turbulence.cl) */
    cl_kernel k = NULL;
    const real rext = (real)(2.0 * sim->sm.h - sc->dr);
    st = prog_kernel(sim->prog, "wcr_wall_shear_sum", &k);
    if (st == CLSPH_OK) st = KERN_SET(k, KARG(smd), KARG(dr), KARG(rext), KARG(w->d_partial));
    if (st == CLSPH_OK) st = kern_launch(sim->dev, k, 1, NULL);
    if (st == CLSPH_OK) st = kern_read(sim->dev, w->d_partial, sizeof(real), w->h_partial);
    if (k != NULL) clReleaseKernel(k);
    CLSPH_TRY(st);
    const double sum = (double)w->h_partial[0];
    CLSPH_CHECK(sum > 0.5 && sum < 1.5, CLSPH_E_INPUT,
                "%s: wcsph-riemann: eq 39's wall shear sums to %g of the stress on the lattice, "
                "not about 1: the smoothing length (h_over_dr) is too small for the spacing",
                sc->case_path, sum);
    w->wscale = 1.0 / sum;
    log_info("wcsph-riemann: the wall model's shear at each particle's distance, eq 39 over its "
             "lattice sum %.4f",
             sum);
  }
  *state = w;
  w = NULL;
done:
  free(buf);
  free(ubuf);
  wcr_destroy(w); /* on failure: what was made so far */
  return st;
}

#define ARG(k, i, x) CLSPH_TRY(kern_set_at((k), (i)++, KARG(x)))

/* 1. the configuration (config.cl): list, B, kernel sums, and the density re-set with `reinit` */
static enum clsph_status configure(struct sim *sim, struct wcr *w, cl_uint reinit, double skin)
{
  enum clsph_status st = CLSPH_OK;
  const real rlist2 = (real)((sim->sm.support + skin) * (sim->sm.support + skin));
  struct pset *ps = &sim->ps;
  const cl_uint n = (cl_uint)ps->n;
  const real dr = (real)sim->scene->dr, s0 = (real)w->sigma0, rho0 = (real)sim->scene->rho0;
  cl_mem pos = pset_mem(ps, sim->f_pos), vol = pset_mem(ps, sim->f_vol);
  cl_mem kind = pset_mem(ps, sim->f_kind), rho = pset_mem(ps, w->f_rho);
  cl_mem wd = pset_mem(ps, w->f_wdist);
  CLSPH_TRY(KERN_SET(w->k_config, KARG(n), KARG(sim->grid.geom), KARG(sim->grid.d_start), KARG(pos),
                     KARG(vol), KARG(kind), KARG(rlist2), KARG(dr), KARG(s0), KARG(rho0),
                     KARG(reinit), KARG(w->d_nlist), KARG(w->d_ncount), KARG(w->d_bmat),
                     KARG(w->d_sigma), KARG(rho), KARG(wd), KARG(sim->d_flags)));
  CLSPH_TRY(kern_launch(sim->dev, w->k_config, ps->n, NULL));
  w->configured = 1;
  w->sorted = sim->sorts;
done:
  return st;
}

/* the wall model of the P_ext particles (turbulence.cl: frames, τ_w, ∂U/∂n, y+) */
static enum clsph_status turb_wall(struct sim *sim, struct wcr *w)
{
  enum clsph_status st = CLSPH_OK;
  struct pset *ps = &sim->ps;
  const cl_uint n = (cl_uint)ps->n;
  const real yp = (real)w->y_p, nu = (real)sim->scene->nu;
  const real r_ext = (real)(2.0 * sim->sm.h - sim->scene->dr);
  const real shift = (real)(w->y_p - sim->scene->dr); /* wcr_turb_wall: the offset less dr/2 */
  cl_mem pos = pset_mem(ps, sim->f_pos), vel = pset_mem(ps, sim->f_vel);
  cl_mem kind = pset_mem(ps, sim->f_kind), wd = pset_mem(ps, w->f_wdist);
  cl_mem wn = pset_mem(ps, w->f_wnormal), k = pset_mem(ps, w->ke.f_k);
  cl_mem yplus = pset_mem(ps, w->f_yplus);
  CLSPH_TRY(KERN_SET(w->k_twall, KARG(n), KARG(sim->grid.geom), KARG(pos), KARG(vel), KARG(kind),
                     KARG(wd), KARG(wn), KARG(w->d_nlist), KARG(w->d_ncount), KARG(k), KARG(yp),
                     KARG(nu), KARG(r_ext), KARG(shift), KARG(w->d_frame), KARG(w->d_wallv),
                     KARG(yplus)));
  CLSPH_TRY(kern_launch(sim->dev, w->k_twall, ps->n, NULL));
  if (w->shear_dist == 2) { /* "first_row": the first dummy layer's D_b (turbulence.cl) */
    const real dr = (real)sim->scene->dr;
    cl_mem vol = pset_mem(ps, sim->f_vol);
    CLSPH_TRY(KERN_SET(w->k_row1, KARG(n), KARG(sim->grid.geom), KARG(sim->grid.d_start), KARG(pos),
                       KARG(vol), KARG(kind), KARG(wd), KARG(dr), KARG(w->d_row1)));
    CLSPH_TRY(kern_launch(sim->dev, w->k_row1, ps->n, NULL));
  }
done:
  return st;
}

/* 1b. the k-ε model (turbulence.cl): the wall model, k and ε over dt, ν_t. Until the scene's
 * delay the model waits: k and ε stay, ν_t is the delay's and the walls are the laminar ones. */
static enum clsph_status turbulence(struct sim *sim, struct wcr *w, double dt)
{
  enum clsph_status st = CLSPH_OK;
  struct pset *ps = &sim->ps;
  const struct scene *sc = sim->scene;
  const cl_uint n = (cl_uint)ps->n;
  const cl_uint active = sim->time >= sc->turb.delay;
  const real yp = (real)w->y_p, nu = (real)sc->nu, rdt = (real)dt, ilam = (real)(1.0 / w->lambda);
  const real r_ext = (real)(2.0 * sim->sm.h - sc->dr), r_p = (real)sc->dr, ws = (real)w->w_s;
  const real nu_fixed = (real)sc->turb.nu_t_delay;
  cl_mem wn = pset_mem(ps, w->f_wnormal), logf = w->grad_log ? w->d_logf : w->d_none;
  cl_mem pos = pset_mem(ps, sim->f_pos), vel = pset_mem(ps, sim->f_vel);
  cl_mem vol = pset_mem(ps, sim->f_vol), kind = pset_mem(ps, sim->f_kind);
  cl_mem wd = pset_mem(ps, w->f_wdist);
  cl_mem k = pset_mem(ps, w->ke.f_k), eps = pset_mem(ps, w->ke.f_eps),
         nut = pset_mem(ps, w->ke.f_nut);
  if (active) {
    CLSPH_TRY(turb_wall(sim, w));
    if (w->grad_log) { /* the walls' frames of the log coordinate (turbulence.cl) */
      const real shift = (real)(w->y_p - sc->dr), ymin = (real)(0.5 * w->y_p);
      CLSPH_TRY(KERN_SET(w->k_logf, KARG(n), KARG(sim->grid.geom), KARG(pos), KARG(kind), KARG(wn),
                         KARG(w->d_nlist), KARG(w->d_ncount), KARG(shift), KARG(ymin),
                         KARG(w->d_logf)));
      CLSPH_TRY(kern_launch(sim->dev, w->k_logf, ps->n, NULL));
    }
    CLSPH_TRY(KERN_SET(w->k_ttrans, KARG(n), KARG(sim->grid.geom), KARG(pos), KARG(vel), KARG(vol),
                       KARG(kind), KARG(wd), KARG(w->d_nlist), KARG(w->d_ncount), KARG(k),
                       KARG(eps), KARG(nut), KARG(w->d_frame), KARG(w->d_wallv), KARG(rdt),
                       KARG(nu), KARG(ilam), KARG(yp), KARG(r_ext), KARG(r_p), KARG(ws),
                       KARG(w->ke.d_knew), KARG(w->ke.d_enew), KARG(w->ke.d_clips), KARG(w->d_grad),
                       KARG(logf)));
    CLSPH_TRY(kern_launch(sim->dev, w->k_ttrans, ps->n, NULL));
  }
  CLSPH_TRY(KERN_SET(w->k_tupd, KARG(n), KARG(kind), KARG(w->ke.d_knew), KARG(w->ke.d_enew),
                     KARG(active), KARG(nu_fixed), KARG(k), KARG(eps), KARG(nut),
                     KARG(w->ke.d_nut2)));
  CLSPH_TRY(kern_launch(sim->dev, w->k_tupd, ps->n, NULL));
  CLSPH_TRY(kepsilon_step_end(sim, &w->ke)); /* the largest ν_t, the clip counts */
done:
  return st;
}

/* 2. a_prior, the transport-velocity correction, the ARD indicator (advection.cl) */
static enum clsph_status advection(struct sim *sim, struct wcr *w)
{
  enum clsph_status st = CLSPH_OK;
  struct pset *ps = &sim->ps;
  const struct scene *sc = sim->scene;
  const cl_uint n = (cl_uint)ps->n;
  const double h = sim->sm.h;
  const real mu = (real)(sc->rho0 * sc->nu), rho0 = (real)sc->rho0, c0 = (real)w->c0;
  const real rh = (real)h, rdr = (real)sc->dr, ilam = (real)(1.0 / w->lambda);
  double body[3];
  for (int a = 0; a < 3; ++a) body[a] = sc->gravity[a] + sim->body_force[a];
  const struct realv_arg accel = dev_realv(sc->dim, body);
  /* eq 25: α h², α = 0.2; eq 33: m h², m = 1000 (0: the full correction) */
  const real tvf_a = w->tvf == WCR_TVF_OFF ? 0 : (real)(w->tvf_alpha * h * h);
  const real tvf_m = w->tvf == WCR_TVF_LIMITED ? (real)(1000.0 * h * h) : 0;
  /* in free-surface flows, only away from the surface (advection.cl) */
  const real bulk = w->reinit == WCR_REINIT_FREE ? (real)0.8 : 0;
  cl_mem ard = w->f_ard >= 0 ? pset_mem(ps, w->f_ard) : w->d_none;
  cl_mem pos = pset_mem(ps, sim->f_pos), vel = pset_mem(ps, sim->f_vel);
  cl_mem vol = pset_mem(ps, sim->f_vol), kind = pset_mem(ps, sim->f_kind);
  cl_mem rho = pset_mem(ps, w->f_rho), wd = pset_mem(ps, w->f_wdist);
  cl_mem wn = pset_mem(ps, w->f_wnormal);
  /* the k-ε model's eddy viscosity and wall shear stress (turbulence.cl), once it is active */
  cl_mem nut = w->turb ? pset_mem(ps, w->ke.f_nut) : w->d_none;
  cl_mem frame = w->turb ? w->d_frame : w->d_none, wallv = w->turb ? w->d_wallv : w->d_none;
  const real r_ext = (real)(2.0 * h - sc->dr);
  const cl_uint wmodel = w->turb && sim->time >= sc->turb.delay;
  const real wsc = (real)w->wscale, mass = (real)w->mass;
  /* offset_layer = "body_force": the layer's mass under a first-row particle over the
   * particle's, (y_p − dr/2)/dr (advection.cl) */
  const real layer = w->carry ? (real)((w->y_p - 0.5 * sc->dr) / sc->dr) : (real)0;
  cl_mem wall = pset_mem(ps, w->f_wall);
  cl_mem rec = w->f_rec >= 0 ? pset_mem(ps, w->f_rec) : w->d_none;
  cl_mem wgroup = w->f_rec >= 0 ? w->d_wgroup : w->d_none;
  cl_mem row1 = w->d_row1 != NULL ? w->d_row1 : w->d_none;
  CLSPH_TRY(KERN_SET(
      w->k_adv, KARG(n), KARG(sim->grid.geom), KARG(pos), KARG(vel), KARG(vol), KARG(kind),
      KARG(rho), KARG(wd), KARG(wn), KARG(w->d_nlist), KARG(w->d_ncount), KARG(w->d_bmat),
      KARG(w->d_sigma), KARG(rdr), KARG(mu), KARG(ilam), KARGV(accel), KARG(tvf_a), KARG(tvf_m),
      KARG(bulk), KARG(rho0), KARG(c0), KARG(rh), KARG(w->d_prior), KARG(w->d_shift), KARG(ard),
      KARG(nut), KARG(frame), KARG(wallv), KARG(r_ext), KARG(wmodel), KARG(wsc), KARG(wall),
      KARG(rec), KARG(wgroup), KARG(w->nwall_map), KARG(mass), KARG(layer), KARG(row1)));
  CLSPH_TRY(kern_launch(sim->dev, w->k_adv, ps->n, NULL));
done:
  return st;
}

/* the drift: v += dt_v acc, r += dt_x v (+ the TVF correction), ρ += dt_rho dρ/dt, V, p */
static enum clsph_status drift(struct sim *sim, struct wcr *w, double dt_v, double dt_x,
                               double dt_rho, cl_uint use_shift)
{
  enum clsph_status st = CLSPH_OK;
  struct pset *ps = &sim->ps;
  const cl_uint n = (cl_uint)ps->n;
  const real a = (real)dt_v, b = (real)dt_x, c = (real)dt_rho, mass = (real)w->mass;
  const real rho0 = (real)sim->scene->rho0, c0 = (real)w->c0;
  const real surface = w->reinit == WCR_REINIT_FREE ? (real)0.95 : 0;
  cl_mem kind = pset_mem(ps, sim->f_kind), pos = pset_mem(ps, sim->f_pos);
  cl_mem vel = pset_mem(ps, sim->f_vel), rho = pset_mem(ps, w->f_rho);
  cl_mem drho = pset_mem(ps, w->f_drho), vol = pset_mem(ps, sim->f_vol);
  cl_mem p = pset_mem(ps, w->f_p);
  CLSPH_TRY(KERN_SET(w->k_drift, KARG(n), KARG(sim->grid.geom), KARG(kind), KARG(a), KARG(b),
                     KARG(c), KARG(w->d_acc), KARG(use_shift), KARG(w->d_shift), KARG(w->d_sigma),
                     KARG(surface), KARG(mass), KARG(rho0), KARG(c0), KARG(pos), KARG(vel),
                     KARG(rho), KARG(drho), KARG(vol), KARG(p), KARG(sim->d_flags)));
  CLSPH_TRY(kern_launch(sim->dev, w->k_drift, ps->n, NULL));
done:
  return st;
}

/* dv/dt (eq 19), then dρ/dt (eq 15) from v + dt dv/dt; the walls' record takes rec_w of the
 * sub-step's wall pairs */
static enum clsph_status relax(struct sim *sim, struct wcr *w, double dt, double rec_w)
{
  enum clsph_status st = CLSPH_OK;
  struct pset *ps = &sim->ps;
  const struct scene *sc = sim->scene;
  const cl_uint n = (cl_uint)ps->n;
  const real rho0 = (real)sc->rho0, c0 = (real)w->c0, mu = (real)(sc->rho0 * sc->nu);
  const real h = (real)sim->sm.h, rdt = (real)dt, pbg = (real)w->p_bg;
  const struct realv_arg grav = dev_realv(sc->dim, sc->gravity);
  cl_mem pos = pset_mem(ps, sim->f_pos), vel = pset_mem(ps, sim->f_vel);
  cl_mem vol = pset_mem(ps, sim->f_vol), kind = pset_mem(ps, sim->f_kind);
  cl_mem rho = pset_mem(ps, w->f_rho), p = pset_mem(ps, w->f_p);
  cl_mem drho = pset_mem(ps, w->f_drho), wn = pset_mem(ps, w->f_wnormal);
  cl_mem tk = w->turb ? pset_mem(ps, w->ke.f_k) : w->d_none;
  cl_mem nut = w->turb ? pset_mem(ps, w->ke.f_nut) : w->d_none;
  cl_mem grad = w->turb ? w->d_grad : w->d_none;
  cl_mem gradp = w->wall_pgrad ? w->d_gradp : w->d_none;
  cl_mem gate = w->gate.on ? pset_mem(ps, w->gate.f_gate) : w->d_none;
  cl_mem wall = pset_mem(ps, w->f_wall);
  cl_mem rec = w->f_rec >= 0 ? pset_mem(ps, w->f_rec) : w->d_none;
  cl_mem wgroup = w->f_rec >= 0 ? w->d_wgroup : w->d_none;
  const real rw = (real)rec_w;
  CLSPH_TRY(KERN_SET(w->k_mom, KARG(n), KARG(sim->grid.geom), KARG(pos), KARG(vel), KARG(vol),
                     KARG(kind), KARG(rho), KARG(p), KARG(w->d_nlist), KARG(w->d_ncount),
                     KARG(w->d_bmat), KARG(w->d_prior), KARG(rho0), KARG(c0), KARG(pbg), KARG(mu),
                     KARG(h), KARG(w->d_acc), KARG(tk), KARG(nut), KARG(wn), KARGV(grav),
                     KARG(grad), KARG(gradp), KARG(gate), KARG(wall), KARG(rec), KARG(wgroup),
                     KARG(w->nwall_map), KARG(rw)));
  CLSPH_TRY(kern_launch(sim->dev, w->k_mom, ps->n, NULL));
  CLSPH_TRY(KERN_SET(w->k_cont, KARG(n), KARG(sim->grid.geom), KARG(pos), KARG(vel), KARG(w->d_acc),
                     KARG(rdt), KARG(vol), KARG(kind), KARG(rho), KARG(p), KARG(w->d_nlist),
                     KARG(w->d_ncount), KARG(w->d_prior), KARG(wn), KARG(rho0), KARG(c0),
                     KARGV(grav), KARG(drho), KARG(gate)));
  CLSPH_TRY(kern_launch(sim->dev, w->k_cont, ps->n, NULL));
done:
  return st;
}

/* pairs in the fluid's lists (the pairs of one sum over the fluid) */
static enum clsph_status count_pairs(struct sim *sim, struct wcr *w, double *pairs)
{
  enum clsph_status st = CLSPH_OK;
  const cl_uint n = (cl_uint)sim->ps.n;
  const size_t groups = sim_reduce_groups(sim->ps.n);
  cl_mem kind = pset_mem(&sim->ps, sim->f_kind);
  CLSPH_TRY(KERN_SET(w->k_count, KARG(n), KARG(kind), KARG(w->d_ncount), KARG(w->d_partial)));
  CLSPH_TRY(kern_launch_wg(sim->dev, w->k_count, groups * 64, 64, NULL));
  CLSPH_TRY(kern_read(sim->dev, w->d_partial, groups * sizeof(real), w->h_partial));
  double c = 0.0;
  for (size_t g = 0; g < groups; ++g) c += (double)w->h_partial[g];
  *pairs = c;
done:
  return st;
}

/* The exits' ρ and p for an advection step (solvers/open). A zero-pressure outlet (p = 0, the
 * gauge pressure; outlet = "fixed") reflects sound: a channel between a velocity entry and
 * such an exit rings like a pipe closed at one end (period 4 L/c0), and the Riemann solver damps
 * it little. Behind the square cylinder (cases/square_cylinder.lua, Re = 100, H/40, 32 D long,
 * c0 = 10 U0) the channel's mean speed swung by ±40% for 10 D/U0 while the entries and exits
 * traded particles out of step, until the exit's waiting particles piled up (t = 9). The
 * default outlet = "characteristic" lets a plane wave leave: the incoming characteristic
 * p − ρ0 c0 u_n is set to its undisturbed value, so that the exit's pressure is
 *   p_exit = ρ0 c0 (⟨u_n⟩ − ū),  ρ_exit = ρ0 + p_exit/c0²,
 * ⟨u_n⟩ the mean speed out of the fluid in the exit's first row and ū the speed that carries
 * out what the entries' prescribed profiles let in (less what prescribed exits let out) over
 * the natural exits' width, as they let it in a transit time L/c0 earlier (L from an entry's
 * midpoint to an exit's, open_transit): the outlet holds p = 0 on average and pushes back when
 * more leaves than enters (a non-reflecting condition for plane waves, Rudy & Strikwerda 1980, on
 * the section's mean, so that the profile across the exit is free). A prescribed exit profile keeps
 * p = 0. Measuring ū instead from the entries' first fluid rows (the same sampling of the
 * profile as the exit's) made the Poiseuille channel's exit worse, not better (p_err_exit_max
 * 0.32 against 0.12 at dr = 0.1).
 * The delay: at rest the incoming characteristic is 0. With ū taken at once, the exit set it to
 * −ρ0 c0 ū from the start and pulled the fluid out at p = −½ ρ0 c0 ū until the entries' wave
 * arrived (−3.3 ρ U0² for 3 D/U0 behind the square cylinder, cases/square_cylinder.lua,
 * Re = 20, H/80, c0 = 10 U0); negative pressures draw particles together (the tensile
 * instability), and the fluid in the exit's corner by the floor flowed back along the wall
 * (−0.3 U0 at t = 3) until a particle was thrown out of the domain at t = 3.3. With the delay the
 * exit lets the entries' wave out as it arrives, and the pressure stays >= 0 through the
 * start-up (in the linear acoustics of the channel the overshoot is the same, u = 1.5 ū, and it
 * settles after 3 L/c0 instead of 2 L/c0). Until the wave arrives the exit lets out what the
 * fluid let out at the start (open_initial_outflow: 0 from rest): a fluid started on its
 * developed flow (cases/channel_curved.lua) was held back at the exit by ρ0 c0 ū from the first
 * step (the strongly curved channel's outlet ran at 0.4 U_b by t = 0.04 s, L/c0 = 0.24 s). */
static enum clsph_status open_exits(struct sim *sim, struct wcr *w)
{
  enum clsph_status st = CLSPH_OK;
  const struct scene *sc = sim->scene;
  const double rho0 = sc->rho0, c0 = w->c0;
  const double width = open_natural_width(sc);
  const double delay = open_transit(sc) / c0;
  const double ubar = width <= 0.0        ? 0.0
                      : sim->time < delay ? w->ubar0
                                          : open_natural_flux(sc, sim->time - delay) / width;
  if (!w->outlet_fixed) CLSPH_TRY(open_exit_speed(&w->open, sim, w->exit_p));
  for (int k = 0; k < sc->nsections; ++k) {
    const int natural = sc->sections[k].kind == SCENE_OUTFLOW && sc->sections[k].profile == 0;
    const double dp = natural && !w->outlet_fixed ? rho0 * c0 * (w->exit_p[k] - ubar) : 0.0;
    w->exit_p[k] = dp;
    w->exit_rho[k] = rho0 + dp / (c0 * c0);
  }
done:
  return st;
}

/* The layers' ρ and p before a sub-step's sums: an entry layer particle takes its row's first
 * fluid particle's (n·∇ρ = n·∇p = 0), an exit one its section's (open_exits). */
static enum clsph_status open_layers(struct sim *sim, struct wcr *w)
{
  enum clsph_status st = CLSPH_OK;
  CLSPH_TRY(open_layer_scalar_exits(&w->open, sim, pset_mem(&sim->ps, w->f_rho), w->exit_rho));
  CLSPH_TRY(open_layer_scalar_exits(&w->open, sim, pset_mem(&sim->ps, w->f_p), w->exit_p));
done:
  return st;
}

/* After the step's last motion: the recycling, then the state a recycled particle takes over from
 * the entry particle whose place it takes (ρ, p, V, and k, ε, ν_t under the k-ε model; dρ/dt is
 * zero on every layer particle). */
static enum clsph_status open_recycle_layers(struct sim *sim, struct wcr *w)
{
  enum clsph_status st = CLSPH_OK;
  CLSPH_TRY(open_recycle(&w->open, sim));
  const int fields[] = {w->f_rho, w->f_p, w->f_drho, sim->f_vol};
  for (size_t k = 0; k < sizeof fields / sizeof *fields; ++k)
    CLSPH_TRY(open_recycle_copy(&w->open, sim, fields[k]));
  if (w->turb) { /* an entry's k, ε and ν_t */
    const int turb[] = {w->ke.f_k, w->ke.f_eps, w->ke.f_nut};
    for (size_t k = 0; k < sizeof turb / sizeof *turb; ++k)
      CLSPH_TRY(open_recycle_copy(&w->open, sim, turb[k]));
  }
done:
  return st;
}

static enum clsph_status wcr_step(struct sim *sim, void *state, double dt)
{
  enum clsph_status st = CLSPH_OK;
  struct wcr *w = state;
  const double h = sim->sm.h;
  /* the list's skin covers the fluid's moves and the gate's */
  const double vg = gate_speed_at(&w->gate, sim->time, sim->time + dt);
  CLSPH_TRY(configure(sim, w, w->reinit, list_skin(sim, fmax(fmax(w->vmax, w->u_scale), vg), dt)));
  if (w->open.nsec > 0) {
    CLSPH_TRY(open_layer_velocity(&w->open, sim));
    CLSPH_TRY(open_exits(sim, w));
  }
  if (w->turb) {
    if (w->open.nsec > 0) { /* exits: n·∇k = n·∇ε = 0; entries: their prescribed values */
      const int fields[] = {w->ke.f_k, w->ke.f_eps, w->ke.f_nut};
      for (size_t k = 0; k < sizeof fields / sizeof *fields; ++k)
        CLSPH_TRY(open_layer_scalar_prescribed(&w->open, sim, pset_mem(&sim->ps, fields[k])));
    }
    CLSPH_TRY(turbulence(sim, w, dt));
  }
  CLSPH_TRY(advection(sim, w));
  /* the acoustic sub-steps: equal, at most CFL_ac h/(c0 + |v|max) each */
  const double dt_ac = w->cfl_ac * h / (w->c0 + w->vmax);
  const long nac = (long)fmax(1.0, ceil(dt / dt_ac * (1.0 - 1e-12)));
  const double d = dt / (double)nac;
  CLSPH_TRY(drift(sim, w, 0.0, 0.5 * d, 0.5 * d, 1u));
  for (long k = 0; k < nac; ++k) {
    if (w->gate.on) { /* its dummies where they are at the sub-step's end (a lag of d v_gate, 0.08 h
                       * at the Lobovsky gate's 4.53 m/s and c0 = 34 m/s) */
      double vgate[3];
      CLSPH_TRY(gate_move(sim, &w->gate, sim->time + (double)k * d, d,
                          pset_mem(&sim->ps, sim->f_vel), vgate));
    }
    if (w->open.nsec > 0) CLSPH_TRY(open_layers(sim, w));
    CLSPH_TRY(relax(sim, w, d, 1.0 / (double)nac));
    const double tail = k + 1 < nac ? d : 0.5 * d; /* the next sub-step's first half too */
    CLSPH_TRY(drift(sim, w, d, tail, tail, 0u));
    if (w->open.nsec > 0) CLSPH_TRY(open_move(&w->open, sim, d));
  }
  if (w->open.nsec > 0) CLSPH_TRY(open_recycle_layers(sim, w));
  double pairs = 0.0;
  CLSPH_TRY(count_pairs(sim, w, &pairs));
  sim->substeps = nac;
  sim->pairs = pairs * (double)(2 + 2 * nac); /* config, advection, 2 per sub-step */
  w->rec_steps++;
done:
  return st;
}

static enum clsph_status wcr_max_dt(struct sim *sim, void *state, double *dt)
{
  enum clsph_status st = CLSPH_OK;
  struct wcr *w = state;
  const struct scene *s = sim->scene;
  const double h = sim->sm.h;
  double vmax = 0.0;
  CLSPH_TRY(sim_max_speed(sim, KIND_FLUID, &vmax));
  w->vmax = vmax;
  const double v = fmax(fmax(vmax, w->u_scale), gate_speed_at(&w->gate, sim->time, sim->time));
  double d = v > 0.0 ? h / v : HUGE_VAL;                         /* eq 27 */
  const double nu_eff = s->nu + (w->turb ? w->ke.nut_max : 0.0); /* eq 27: ν + ν_t */
  if (nu_eff > 0.0) d = fmin(d, h * h / nu_eff);
  if (!isfinite(d)) d = h / w->c0; /* nothing moves: one acoustic CFL */
  *dt = w->cfl_ad * d;
done:
  return st;
}

/* The sums of a wall group's force from per-particle shares (pressure x, y, viscous x, y at
 * share[stride * i + 4 q + c]): the force, and the torque about the group's centre with each
 * share at its fluid particle's position (the image nearest the centre) */
static void force_sum(const struct sim *sim, const char *group, const real *share, size_t stride,
                      size_t q, const real *hpos, struct wall_force *out)
{
  const struct scene *sc = sim->scene;
  double c[2];
  scene_group_centre(sc, group, c);
  memset(out, 0, sizeof *out);
  for (size_t i = 0; i < sim->ps.n; ++i) {
    const real *f = share + stride * i + 4 * q;
    const double fx = (double)f[0] + (double)f[2], fy = (double)f[1] + (double)f[3];
    out->pressure[0] += (double)f[0];
    out->pressure[1] += (double)f[1];
    out->viscous[0] += (double)f[2];
    out->viscous[1] += (double)f[3];
    if (fx == 0.0 && fy == 0.0) continue;
    double r[2] = {(double)hpos[2 * i] - c[0], (double)hpos[2 * i + 1] - c[1]};
    for (int a = 0; a < 2; ++a)
      if (sc->periodic[a]) r[a] -= (sc->hi[a] - sc->lo[a]) * round(r[a] / (sc->hi[a] - sc->lo[a]));
    out->torque += r[0] * fy - r[1] * fx;
  }
}

/* Force of the fluid on the dummy particles of a wall group (force.cl), summed in double: the
 * record of the last step (its sub-steps' mean; after a restart the checkpoint's, a field), else
 * (the output before the first step) the pairs evaluated once on the present state. */
static enum clsph_status wcr_wall_force(struct sim *sim, void *state, const char *group,
                                        struct wall_force *out)
{
  enum clsph_status st = CLSPH_OK;
  struct wcr *w = state;
  struct pset *ps = &sim->ps;
  const struct scene *sc = sim->scene;
  cl_uint *mask = NULL;
  real *hpos = NULL, *share = NULL;
  const cl_uint n = (cl_uint)ps->n, nmask = (cl_uint)(sc->nwalls > 0 ? sc->nwalls : 1);
  hpos = malloc(2 * (ps->n + 1) * sizeof *hpos);
  CLSPH_CHECK(hpos != NULL, CLSPH_E_NOMEM, "out of memory");
  CLSPH_TRY(kern_read(sim->dev, pset_mem(ps, sim->f_pos), 2 * ps->n * sizeof *hpos, hpos));
  if (w->f_rec >= 0 && (w->rec_steps > 0 || sim->step > 0)) { /* a restart: the checkpoint's */
    size_t q = 0;
    while (q < w->nrec && strcmp(sc->forces[q], group) != 0) ++q;
    CLSPH_CHECK(q < w->nrec, CLSPH_E_INPUT, "%s: force { \"%s\" }: no such recorded group",
                sc->case_path, group);
    const size_t stride = 4 * (size_t)w->nrec;
    share = malloc((ps->n * stride + 1) * sizeof *share);
    CLSPH_CHECK(share != NULL, CLSPH_E_NOMEM, "out of memory");
    CLSPH_TRY(kern_read(sim->dev, pset_mem(ps, w->f_rec), ps->n * stride * sizeof *share, share));
    force_sum(sim, group, share, stride, q, hpos, out);
    goto done;
  }
  mask = calloc(nmask, sizeof *mask);
  CLSPH_CHECK(mask != NULL, CLSPH_E_NOMEM, "out of memory");
  for (int k = 0; k < sc->nwalls; ++k) mask[k] = strcmp(sc->walls[k].group, group) == 0;
  if (w->d_mask == NULL)
    CLSPH_TRY(kern_buffer(sim->dev, nmask * sizeof *mask, NULL, &w->d_mask, "wall mask"));
  if (w->d_force == NULL) {
    CLSPH_TRY(kern_buffer(sim->dev, w->cap * 4 * sizeof(real), NULL, &w->d_force, "wall force"));
    w->h_force = malloc(w->cap * 4 * sizeof *w->h_force);
    CLSPH_CHECK(w->h_force != NULL, CLSPH_E_NOMEM, "out of memory");
  }
  CLSPH_TRY(kern_write(sim->dev, w->d_mask, nmask * sizeof *mask, mask));
  /* before the first step (the initial output), and after a sort since the step (the health
   * check sorts before the outputs), the list, B and a_prior are made again without touching ρ:
   * the list, B and a_prior are buffers in the order of the step's sort, which the sort does not
   * reorder. Before this, a health check's sort left the force to pairs of the wrong particles on
   * the steps it ran: the square cylinder's C_D at Re = 20, H/80 came out 27% low, the samples
   * alternating between the true force and about a tenth of it. */
  if (!w->configured || w->sorted != sim->sorts) {
    CLSPH_TRY(configure(sim, w, WCR_REINIT_OFF, 0.0));
    if (w->turb && sim->time >= sc->turb.delay) CLSPH_TRY(turb_wall(sim, w));
    CLSPH_TRY(advection(sim, w));
  }
  const real rho0 = (real)sc->rho0, c0 = (real)w->c0, mu = (real)(sc->rho0 * sc->nu);
  const real h = (real)sim->sm.h, rdr = (real)sc->dr, ilam = (real)(1.0 / w->lambda);
  const real pbg = (real)w->p_bg;
  cl_mem pos = pset_mem(ps, sim->f_pos), vel = pset_mem(ps, sim->f_vel);
  cl_mem vol = pset_mem(ps, sim->f_vol), kind = pset_mem(ps, sim->f_kind);
  cl_mem rho = pset_mem(ps, w->f_rho), p = pset_mem(ps, w->f_p);
  cl_mem wall = pset_mem(ps, w->f_wall), wd = pset_mem(ps, w->f_wdist);
  cl_mem wn = pset_mem(ps, w->f_wnormal);
  cl_mem tk = w->turb ? pset_mem(ps, w->ke.f_k) : w->d_none;
  cl_mem nut = w->turb ? pset_mem(ps, w->ke.f_nut) : w->d_none;
  cl_mem frame = w->turb ? w->d_frame : w->d_none, wallv = w->turb ? w->d_wallv : w->d_none;
  const real r_ext = (real)(2.0 * sim->sm.h - sc->dr);
  const cl_uint wmodel = w->turb && sim->time >= sc->turb.delay;
  const real wsc = (real)w->wscale;
  const struct realv_arg grav = dev_realv(sc->dim, sc->gravity);
  cl_mem gradp = w->wall_pgrad ? w->d_gradp : w->d_none;
  cl_mem row1 = w->d_row1 != NULL ? w->d_row1 : w->d_none;
  CLSPH_TRY(KERN_SET(
      w->k_force, KARG(n), KARG(sim->grid.geom), KARG(pos), KARG(vel), KARG(vol), KARG(kind),
      KARG(rho), KARG(wd), KARG(wn), KARG(p), KARG(w->d_nlist), KARG(w->d_ncount), KARG(w->d_bmat),
      KARG(w->d_prior), KARG(wall), KARG(w->d_mask), KARG(nmask), KARG(rdr), KARG(rho0), KARG(c0),
      KARG(pbg), KARG(mu), KARG(ilam), KARG(h), KARG(w->d_force), KARG(tk), KARG(nut), KARG(frame),
      KARG(wallv), KARG(r_ext), KARG(wmodel), KARGV(grav), KARG(gradp), KARG(wsc), KARG(row1)));
  CLSPH_TRY(kern_launch(sim->dev, w->k_force, ps->n, NULL));
  CLSPH_TRY(kern_read(sim->dev, w->d_force, ps->n * 4 * sizeof(real), w->h_force));
  force_sum(sim, group, w->h_force, 4, 0, hpos, out);
done:
  free(share);
  free(hpos);
  free(mask);
  return st;
}

static void wcr_destroy(void *state)
{
  struct wcr *w = state;
  if (w == NULL) return;
  cl_kernel *ks[] = {&w->k_config, &w->k_count, &w->k_adv,     &w->k_drift, &w->k_mom,
                     &w->k_cont,   &w->k_force, &w->k_lattice, &w->k_twall, &w->k_ttrans,
                     &w->k_tupd,   &w->k_logf,  &w->k_row1};
  for (size_t k = 0; k < sizeof ks / sizeof *ks; ++k)
    if (*ks[k] != NULL) clReleaseKernel(*ks[k]);
  cl_mem *ms[] = {&w->d_nlist, &w->d_ncount,  &w->d_bmat,  &w->d_sigma,  &w->d_prior, &w->d_shift,
                  &w->d_acc,   &w->d_partial, &w->d_force, &w->d_mask,   &w->d_none,  &w->d_frame,
                  &w->d_wallv, &w->d_grad,    &w->d_gradp, &w->d_wgroup, &w->d_logf,  &w->d_row1};
  for (size_t k = 0; k < sizeof ms / sizeof *ms; ++k) kern_release(ms[k]);
  kepsilon_destroy(&w->ke);
  open_destroy(&w->open);
  gate_destroy(&w->gate);
  free(w->exit_p);
  free(w->h_partial);
  free(w->h_force);
  free(w);
}

const struct scheme_ops scheme_wcsph_riemann = {
    .name = "wcsph-riemann",
    .summary = "Riemann WCSPH, transport-velocity correction, dual-criteria time stepping (Wang, "
               "Sun & Hu)",
    .sources = sources,
    .wall_model = "dummy",
    .three_d = 1,
    .smoothing = "wendland",
    .h_over_dr = 1.3,
    .support_skin = WCR_SKIN,
    .fill_fields = SCHEME_FILL_PRESSURE | SCHEME_FILL_DENSITY,
    /* a fluid set going by an entry holds up to U/c0 more mass until the wave has left through the
     * exits: 0.1 at the default c0 = 10 U (kernels/common/open.cl) */
    .open_reserve = 0.1,
    .options = options,
    .turbulence = turbulence_models,
    .define = wcr_define,
    .create = wcr_create,
    .step = wcr_step,
    .max_dt = wcr_max_dt,
    .wall_force = wcr_wall_force,
    .destroy = wcr_destroy,
};
