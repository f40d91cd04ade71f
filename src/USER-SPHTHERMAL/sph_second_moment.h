/* -*- c -*- -------------------------------------------------------------
   USER-SPHTHERMAL: conduction pair weights exact to the second moment, in
   C99 (also C++).

   Brookshaw's Laplacian (sph_consistent.h),
     lap(T)_a ~ (2 / V_a) sum_b g_ab w_ab (T_b - T_a),
   is exact for every quadratic field when, for each particle a,
     (first)  sum_b g_ab w_ab r_ab = 0,
     (second) sum_b g_ab w_ab r_ab (x) r_ab = V_a I.
   'correction consistent' meets the first and normalises the second per
   particle before symmetrising it, so the second holds only roughly (a
   relative error of 0.18 on particles jittered by 0.2 spacings). Here both
   hold exactly, with a pair factor that is symmetric (the pair term stays
   antisymmetric: energy to round-off) and never negative (a pair never
   conducts against its temperature difference, so the explicit update
   stays a convex combination):
     w_ab = max(0, 1 + F(r_ab).nu_a + F(r_ba).nu_b),
     F(r) = (x, y, x^2, y^2, 2xy) in 2-D, (x, y, z, x^2, y^2, z^2, 2xy, 2xz,
     2yz) in 3-D, of r / h,
   with per-particle multipliers nu (the first-moment part changes sign
   with r, the second-moment part does not, so w_ab = w_ba). The
   conditions of every particle, (first) and (second) written as
     sum_b g_ab w_ab F(r_ab) = t_a,  t_a = (0, V_a / h^2 on the diagonal),
   are the gradient of the convex function
     Phi(nu) = sum_pairs g_ab max(0, arg_ab)^2 / 2 - sum_a nu_a.t_a
   (the argument arg_ab is linear in nu), so they are solved by minimising
   Phi: Newton's method with the generalised Hessian (constant between the
   pairs' switches at arg = 0), its steps by conjugate gradients
   preconditioned with each particle's own block, and a backtracking line
   search on Phi. Conditions are imposed only on particles with complete
   support (the caller's 'constrained' flag); the others keep nu = 0.

   The conditions are nearly dependent: a smooth field of first-moment
   multipliers mu(x) with second-moment ones L = -grad(mu) / 2 changes no
   pair's argument to second order (none at all for a linear mu), so the
   exact multipliers carry a large smooth part of that kind (|mu| of 300 on
   30 x 30 jittered particles) that barely changes the weights, and
   conjugate gradients need of the order of (width / h)^2 steps to find it
   (the slab of 80 x 20: 234,559 steps, 108 s). A regularisation
     Phi + epsilon / 2 sum_a (V_a / h^2) |nu_a|^2
   leaves that part out: the moments then hold to about epsilon |nu|
   (epsilon 1e-6: the Laplacian of a quadratic field on the 30 x 30 set
   within 0.4 %, where 'correction consistent' is off by 18 %), at a
   fraction of the cost (the slab: 20,347 steps to a tolerance of 1e-13).

   The solver reads pairs and per-atom arrays and calls back for the
   communication of a parallel run (ghost atoms), so that the same code
   runs in the C unit tests and in pair sph/cleary/heat.
------------------------------------------------------------------------- */

#ifndef SPH_SECOND_MOMENT_H
#define SPH_SECOND_MOMENT_H

#include <math.h>
#include <stddef.h>

/* the largest number of multipliers per particle (3-D) */
enum { SPHS_MAX = 9 };

/* multipliers per particle: 5 in 2-D, 9 in 3-D */
static inline int sphs_count(int dim)
{
  return (dim == 2) ? 5 : 9;
}

/* F(r / h), the basis of the pair r seen from the particle at its start */
static inline void sphs_basis(int dim, const double r[3], double inv_h, double f[SPHS_MAX])
{
  const double x = r[0] * inv_h, y = r[1] * inv_h, z = r[2] * inv_h;
  if (dim == 2) {
    f[0] = x;
    f[1] = y;
    f[2] = x * x;
    f[3] = y * y;
    f[4] = 2.0 * x * y;
  } else {
    f[0] = x;
    f[1] = y;
    f[2] = z;
    f[3] = x * x;
    f[4] = y * y;
    f[5] = z * z;
    f[6] = 2.0 * x * y;
    f[7] = 2.0 * x * z;
    f[8] = 2.0 * y * z;
  }
}

/* t_a: no first moment, the second V_a / h^2 times I (the off-diagonal
   entries 0) */
static inline void sphs_target(int dim, double volume, double inv_h, double t[SPHS_MAX])
{
  const int n = sphs_count(dim);
  for (int k = 0; k < n; k++) t[k] = (k >= dim && k < 2 * dim) ? volume * inv_h * inv_h : 0.0;
}

/* F(r_ab).nu_a + F(r_ba).nu_b, with F(r_ba) = F(r_ab) but for the sign of
   the first dim entries: the same from either side of the pair */
static inline double sphs_linear(int dim, const double f[SPHS_MAX], const double *nu_a,
                                 const double *nu_b)
{
  const int n = sphs_count(dim);
  double sum = 0.0;
  for (int k = 0; k < n; k++) sum += f[k] * (k < dim ? nu_a[k] - nu_b[k] : nu_a[k] + nu_b[k]);
  return sum;
}

/* the pair's argument 1 + F(r_ab).nu_a + F(r_ba).nu_b */
static inline double sphs_argument(int dim, const double f[SPHS_MAX], const double *nu_a,
                                   const double *nu_b)
{
  return 1.0 + sphs_linear(dim, f, nu_a, nu_b);
}

/* the pair factor w_ab = max(0, argument) */
static inline double sphs_factor(int dim, const double f[SPHS_MAX], const double *nu_a,
                                 const double *nu_b)
{
  const double arg = sphs_argument(dim, f, nu_a, nu_b);
  return (arg > 0.0) ? arg : 0.0;
}

/* Cholesky factor of the symmetric positive definite n x n matrix a (row
   major), in place (lower triangle); 0 if a is not positive definite */
static inline int sphs_cholesky(int n, double *a)
{
  for (int j = 0; j < n; j++) {
    double d = a[j * n + j];
    for (int k = 0; k < j; k++) d -= a[j * n + k] * a[j * n + k];
    if (!(d > 0.0)) return 0;
    d = sqrt(d);
    a[j * n + j] = d;
    for (int i = j + 1; i < n; i++) {
      double s = a[i * n + j];
      for (int k = 0; k < j; k++) s -= a[i * n + k] * a[j * n + k];
      a[i * n + j] = s / d;
    }
  }
  return 1;
}

/* x = (L L^T)^-1 b for the factor of sphs_cholesky (x may be b) */
static inline void sphs_cholesky_solve(int n, const double *l, const double *b, double *x)
{
  double y[SPHS_MAX];
  for (int i = 0; i < n; i++) {
    double s = b[i];
    for (int k = 0; k < i; k++) s -= l[i * n + k] * y[k];
    y[i] = s / l[i * n + i];
  }
  for (int i = n - 1; i >= 0; i--) {
    double s = y[i];
    for (int k = i + 1; k < n; k++) s -= l[k * n + i] * x[k];
    x[i] = s / l[i * n + i];
  }
}

/* ---------------------------------------------------------------- solver */

/* a pair within the support: i owned, j owned or ghost, r = x_i - x_j, g
   the plain weight; each pair once on the rank of i (and, with newton
   off, once more on the rank that owns j when j is a ghost here) */
typedef struct {
  int i, j;
  double r[3];
  double g;
} sphs_pair;

/* the communication of a parallel run: n values per atom, atom-major */
typedef struct {
  void *context;
  /* copies the owned atoms' values to their ghosts */
  void (*forward)(void *context, double *values, int n);
  /* adds the ghosts' values to their owners' */
  void (*reverse)(void *context, double *values, int n);
  /* the sum and the largest value over all ranks */
  double (*sum)(void *context, double value);
  double (*max)(void *context, double value);
} sphs_exchange;

typedef struct {
  int dim;
  int nlocal, nall; /* owned atoms come first, then the ghosts */
  int newton;       /* 1: each pair exists on one rank only */
  int npairs;
  const sphs_pair *pairs;
  const double *volume;   /* per owned atom */
  const int *constrained; /* per owned atom: 1 where the moments are imposed */
  double h;
  double tolerance;      /* on the largest residual of a moment, relative to V / h^2 */
  double regularization; /* epsilon: Phi + epsilon / 2 sum_a V_a / h^2 |nu_a|^2 */
  int max_newton, max_cg;
  sphs_exchange exchange;
} sphs_problem;

typedef struct {
  int newton_steps, cg_steps, converged;
  double residual; /* the largest relative residual of Phi's gradient at the end */
  double moments;  /* the largest residual of a moment relative to V / h^2 (residual
                      but for the regularisation's epsilon V / h^2 nu) */
  int clipped;     /* pairs on this rank whose factor is 0 */
} sphs_result;

/* doubles of work space the solver needs */
static inline size_t sphs_work_size(const sphs_problem *p)
{
  const size_t n = (size_t) sphs_count(p->dim);
  return (size_t) p->nall * n * (8 + n) + (size_t) p->npairs * (n + 1);
}

/* the pair's share of Phi on this rank: with newton off, a pair whose j is
   a ghost exists on two ranks */
static inline double sphs_share(const sphs_problem *p, int j)
{
  return (p->newton || j < p->nlocal) ? 1.0 : 0.5;
}

static inline int sphs_gather_j(const sphs_problem *p, int j)
{
  return p->newton || j < p->nlocal;
}

/* V_a / h^2: the target's diagonal, the unit of the residuals and of the
   regularisation */
static inline double sphs_scale(const sphs_problem *p, int a)
{
  return p->volume[a] / (p->h * p->h);
}

/* out_i += s F(r_ij) and, where this rank gathers j's side, out_j += s F(r_ji) */
static inline void sphs_scatter(const sphs_problem *p, const sphs_pair *pair, const double *f,
                                double s, double *out)
{
  const int n = sphs_count(p->dim);
  double *oi = out + (size_t) pair->i * n, *oj = out + (size_t) pair->j * n;
  const int to_j = sphs_gather_j(p, pair->j);
  for (int k = 0; k < n; k++) {
    oi[k] += s * f[k];
    if (to_j) oj[k] += s * (k < p->dim ? -f[k] : f[k]);
  }
}

/* Phi at nu (nu's ghosts current); with gradient: its gradient on the
   owned atoms (0 where unconstrained), the active flags and the arguments */
static inline double sphs_phi(const sphs_problem *p, const double *nu, const double *basis,
                              double *arg, double *grad, const double *target)
{
  const int n = sphs_count(p->dim);
  double phi = 0.0;
  if (grad)
    for (int k = 0; k < p->nall * n; k++) grad[k] = 0.0;
  for (int q = 0; q < p->npairs; q++) {
    const sphs_pair *pair = &p->pairs[q];
    const double *f = basis + (size_t) q * n;
    const double a = sphs_argument(p->dim, f, nu + (size_t) pair->i * n, nu + (size_t) pair->j * n);
    const double w = (a > 0.0) ? a : 0.0;
    phi += sphs_share(p, pair->j) * 0.5 * pair->g * w * w;
    if (grad) {
      arg[q] = a;
      sphs_scatter(p, pair, f, pair->g * w, grad);
    }
  }
  for (int a = 0; a < p->nlocal; a++)
    if (p->constrained[a])
      for (int k = 0; k < n; k++) {
        const double v = nu[(size_t) a * n + k];
        phi += v * (0.5 * p->regularization * sphs_scale(p, a) * v - target[(size_t) a * n + k]);
      }
  if (grad) {
    if (p->newton) p->exchange.reverse(p->exchange.context, grad, n);
    for (int a = 0; a < p->nlocal; a++)
      for (int k = 0; k < n; k++)
        grad[(size_t) a * n + k] = p->constrained[a]
            ? grad[(size_t) a * n + k] - target[(size_t) a * n + k] +
                p->regularization * sphs_scale(p, a) * nu[(size_t) a * n + k]
            : 0.0;
  }
  return p->exchange.sum(p->exchange.context, phi);
}

/* out = (H + diag(shift)) v on the owned atoms (0 where unconstrained), H
   the generalised Hessian at the arguments arg; v's ghosts are made
   current here */
static inline void sphs_hessian_apply(const sphs_problem *p, const double *basis, const double *arg,
                                      const double *shift, double *v, double *out)
{
  const int n = sphs_count(p->dim);
  p->exchange.forward(p->exchange.context, v, n);
  for (int k = 0; k < p->nall * n; k++) out[k] = 0.0;
  for (int q = 0; q < p->npairs; q++) {
    if (!(arg[q] > 0.0)) continue;
    const sphs_pair *pair = &p->pairs[q];
    const double *f = basis + (size_t) q * n;
    sphs_scatter(
        p, pair, f,
        pair->g * sphs_linear(p->dim, f, v + (size_t) pair->i * n, v + (size_t) pair->j * n), out);
  }
  if (p->newton) p->exchange.reverse(p->exchange.context, out, n);
  for (int a = 0; a < p->nlocal; a++)
    for (int k = 0; k < n; k++) {
      const size_t m = (size_t) a * n + k;
      out[m] = p->constrained[a] ? out[m] + shift[m] * v[m] : 0.0;
    }
}

/* sum over the owned atoms of u.v */
static inline double sphs_dot(const sphs_problem *p, const double *u, const double *v)
{
  const int n = sphs_count(p->dim);
  double s = 0.0;
  for (int k = 0; k < p->nlocal * n; k++) s += u[k] * v[k];
  return p->exchange.sum(p->exchange.context, s);
}

/* The multipliers nu (nall x count values, atom-major; on entry the start,
   e.g. 0 or the last solution, on the owned atoms; on return current on the
   ghosts too) that make the moments of every constrained atom exact.
   work: sphs_work_size(p) doubles. */
static inline sphs_result sphs_solve(const sphs_problem *p, double *nu, double *work)
{
  const int n = sphs_count(p->dim), dim = p->dim;
  const size_t per_atom = (size_t) p->nall * n;
  double *grad = work, *dir = grad + per_atom, *cg_r = dir + per_atom, *cg_z = cg_r + per_atom;
  double *cg_p = cg_z + per_atom, *cg_hp = cg_p + per_atom, *target = cg_hp + per_atom;
  double *shift = target + per_atom, *blocks = shift + per_atom, *basis = blocks + per_atom * n;
  double *arg = basis + (size_t) p->npairs * n;
  const double inv_h = 1.0 / p->h;
  sphs_result result = {0, 0, 0, 0.0, 0.0, 0};

  for (int a = 0; a < p->nlocal; a++) {
    sphs_target(dim, p->volume[a], inv_h, target + (size_t) a * n);
    if (!p->constrained[a])
      for (int k = 0; k < n; k++) nu[(size_t) a * n + k] = 0.0;
  }
  for (int q = 0; q < p->npairs; q++) sphs_basis(dim, p->pairs[q].r, inv_h, basis + (size_t) q * n);
  p->exchange.forward(p->exchange.context, nu, n);

  double phi = sphs_phi(p, nu, basis, arg, grad, target);
  double first_norm = -1.0;
  for (;;) {
    /* the largest residual relative to each atom's V / h^2 */
    double worst = 0.0;
    for (int a = 0; a < p->nlocal; a++) {
      const double scale = sphs_scale(p, a);
      for (int k = 0; k < n; k++) worst = fmax(worst, fabs(grad[(size_t) a * n + k]) / scale);
    }
    result.residual = p->exchange.max(p->exchange.context, worst);
    if (result.residual <= p->tolerance) {
      result.converged = 1;
      break;
    }
    if (result.newton_steps == p->max_newton) break;
    result.newton_steps++;

    /* each constrained atom's own block of H, factored */
    for (int k = 0; k < (int) per_atom * n; k++) blocks[k] = 0.0;
    for (int q = 0; q < p->npairs; q++) {
      if (!(arg[q] > 0.0)) continue;
      const sphs_pair *pair = &p->pairs[q];
      const double *f = basis + (size_t) q * n;
      double *bi = blocks + (size_t) pair->i * n * n, *bj = blocks + (size_t) pair->j * n * n;
      const int to_j = sphs_gather_j(p, pair->j);
      /* F(r_ba) F(r_ba)^T has the signs of F(r_ab) F(r_ab)^T but for the
         first-second cross terms; both blocks are full */
      for (int k = 0; k < n; k++)
        for (int l = 0; l < n; l++) {
          const double v = pair->g * f[k] * f[l];
          bi[k * n + l] += v;
          if (to_j) bj[k * n + l] += ((k < dim) != (l < dim)) ? -v : v;
        }
    }
    if (p->newton) p->exchange.reverse(p->exchange.context, blocks, n * n);
    /* H is singular where an atom's pairs at factor > 0 do not span its
       moments: a small shift of its diagonal that vanishes with the
       residual (Levenberg-Marquardt) keeps the steps bounded and the
       convergence superlinear. H is also ill-conditioned along smooth
       fields: first-moment multipliers mu(x) with second-moment ones
       L = grad(mu) / 2 nearly cancel in every pair's argument (exactly for
       a linear mu), so conjugate gradients need of the order of
       (width / h)^2 steps for a region width across; a larger shift would
       stall the Newton steps on those fields instead (measured on 24 x 24
       jittered particles: shift 1e-2 of the diagonal, residual 1e-3 after
       50 steps; 1e-6, 1e-12 after 13) */
    const double damping = 1e-6 * fmin(1.0, result.residual);
    for (int a = 0; a < p->nlocal; a++) {
      double *b = blocks + (size_t) a * n * n;
      if (!p->constrained[a]) continue;
      double trace = 0.0;
      for (int k = 0; k < n; k++) trace += b[k * n + k];
      for (int k = 0; k < n; k++) {
        shift[(size_t) a * n + k] =
            damping * b[k * n + k] + 1e-12 * trace + p->regularization * sphs_scale(p, a);
        b[k * n + k] += shift[(size_t) a * n + k];
      }
      if (!sphs_cholesky(n, b)) {
        for (int k = 0; k < n * n; k++) b[k] = 0.0;
        for (int k = 0; k < n; k++) b[k * n + k] = sqrt(trace > 0.0 ? trace / n : 1.0);
      }
    }

    /* H dir = -grad by preconditioned conjugate gradients, to a relative
       residual that shrinks with the gradient (inexact Newton) */
    const double norm = sqrt(sphs_dot(p, grad, grad));
    if (first_norm < 0.0) first_norm = norm;
    const double forcing = fmin(0.1, sqrt(norm / first_norm));
    for (int k = 0; k < (int) per_atom; k++) {
      dir[k] = 0.0;
      cg_r[k] = -grad[k];
    }
    double rz = 0.0;
    for (int it = 0; it < p->max_cg; it++) {
      for (int a = 0; a < p->nlocal; a++) {
        double *z = cg_z + (size_t) a * n;
        if (p->constrained[a])
          sphs_cholesky_solve(n, blocks + (size_t) a * n * n, cg_r + (size_t) a * n, z);
        else
          for (int k = 0; k < n; k++) z[k] = 0.0;
      }
      const double rz_next = sphs_dot(p, cg_r, cg_z);
      if (it == 0)
        for (int k = 0; k < p->nlocal * n; k++) cg_p[k] = cg_z[k];
      else
        for (int k = 0; k < p->nlocal * n; k++) cg_p[k] = cg_z[k] + rz_next / rz * cg_p[k];
      rz = rz_next;
      sphs_hessian_apply(p, basis, arg, shift, cg_p, cg_hp);
      const double curvature = sphs_dot(p, cg_p, cg_hp);
      result.cg_steps++;
      if (!(curvature > 0.0)) break;
      const double alpha = rz / curvature;
      for (int k = 0; k < p->nlocal * n; k++) {
        dir[k] += alpha * cg_p[k];
        cg_r[k] -= alpha * cg_hp[k];
      }
      if (sqrt(sphs_dot(p, cg_r, cg_r)) <= forcing * norm) break;
    }

    /* backtracking on Phi (Armijo), from the full step */
    const double slope = sphs_dot(p, grad, dir);
    if (!(slope < 0.0)) break;
    /* once the decrease is below Phi's round-off the full step is taken */
    const int in_round_off = -slope < 1e-12 * fabs(phi);
    double step = 1.0, trial_phi = phi;
    double *trial = cg_z; /* free until the next CG solve */
    for (int tries = 0; tries < 30; tries++, step *= 0.5) {
      for (int k = 0; k < p->nlocal * n; k++) trial[k] = nu[k] + step * dir[k];
      p->exchange.forward(p->exchange.context, trial, n);
      if (in_round_off) break;
      trial_phi = sphs_phi(p, trial, basis, arg, NULL, target);
      if (trial_phi <= phi + 1e-4 * step * slope) break;
    }
    for (int k = 0; k < (int) per_atom; k++) nu[k] = trial[k];
    phi = sphs_phi(p, nu, basis, arg, grad, target);
  }
  for (int q = 0; q < p->npairs; q++) result.clipped += !(arg[q] > 0.0);
  double worst = 0.0;
  for (int a = 0; a < p->nlocal; a++) {
    const double scale = sphs_scale(p, a);
    if (!p->constrained[a]) continue;
    for (int k = 0; k < n; k++) {
      const size_t m = (size_t) a * n + k;
      worst = fmax(worst, fabs(grad[m] - p->regularization * scale * nu[m]) / scale);
    }
  }
  result.moments = p->exchange.max(p->exchange.context, worst);
  return result;
}

#endif
