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
   preconditioned with each particle's own block and a coarse space (two
   levels, below), and a backtracking line search on Phi. Conditions are imposed only on particles with complete
   support (the caller's 'constrained' flag); the others keep nu = 0.

   The conditions are nearly dependent: a smooth field of first-moment
   multipliers mu(x) with second-moment ones L = -grad(mu) / 2 changes no
   pair's argument to second order (none at all for a linear mu), so the
   exact multipliers carry a large smooth part of that kind (|mu| of 300 on
   30 x 30 jittered particles) that barely changes the weights, and
   conjugate gradients with per-particle blocks alone need of the order of
   (width / h)^2 steps to find it (the slab of 80 x 20: 234,559 steps,
   108 s). The coarse space holds these fields; and a regularisation
     Phi + epsilon / 2 sum_a (V_a / h^2) |nu_a|^2
   leaves that part out: the moments then hold to about epsilon |nu|
   (epsilon 1e-6: the Laplacian of a quadratic field on the 30 x 30 set
   within 0.4 %, where 'correction consistent' is off by 18 %), at a
   fraction of the cost (the slab: 20,347 steps to a tolerance of 1e-13
   with one level, 546 with two).

   The solver reads pairs and per-atom arrays and calls back for the
   communication of a parallel run (ghost atoms), so that the same code
   runs in the C unit tests and in pair sph/cleary/heat.
------------------------------------------------------------------------- */

#ifndef SPH_SECOND_MOMENT_H
#define SPH_SECOND_MOMENT_H

#include <math.h>
#include <stddef.h>
#include <stdlib.h>

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

/* x = (L L^T)^-1 b for the factor of sphs_cholesky, any n (x may be b) */
static inline void sphs_cholesky_solve(int n, const double *l, const double *b, double *x)
{
  for (int i = 0; i < n; i++) {
    double s = b[i];
    for (int k = 0; k < i; k++) s -= l[i * n + k] * x[k];
    x[i] = s / l[i * n + i];
  }
  for (int i = n - 1; i >= 0; i--) {
    double s = x[i];
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
  /* sums n values over all ranks, in place (the coarse space) */
  void (*sum_array)(void *context, double *values, int n);
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
  /* the coarse space (two levels): positions of the owned atoms (nlocal x 3,
     NULL: one level), the grid's spacing in units of h and the largest
     coarse dimension (the spacing grows until the grid fits) */
  const double *x;
  double coarse;
  int max_coarse;
  sphs_exchange exchange;
} sphs_problem;

typedef struct {
  int newton_steps, cg_steps, converged;
  int coarse_size; /* the coarse dimension (0: one level) */
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

/* ---------------------------------------------------------- coarse space */

/* What conjugate gradients with per-atom blocks find last are smooth
   fields of first-moment multipliers mu(x) with second-moment ones
   L = -(h / 2) sym(grad mu): they leave every pair's argument unchanged to
   second order (exactly for a linear mu). A coarse space of them, solved
   directly, takes them out of the iteration (a two-level additive
   preconditioner, z = B^-1 r + P (P^T H P)^-1 P^T r). Its columns, for
   each node c of a regular grid over the constrained atoms and each
   direction k < dim:
     mu_a = phi_c(x_a) e_k,  L_a = -(h / 4) (e_k grad phi_c^T + grad phi_c e_k^T),
   phi_c the node's quadratic B-spline (C1, so that L is continuous).
   A grid of 2 h cuts the CG steps about twentyfold on jittered particles;
   columns of smooth L as well, or hat functions, gain nothing (step
   counts: the package's theory page, Howto_sph_theory). */
typedef struct {
  int dim, n;
  int count[3];
  int size;          /* nodes x dim: the coarse dimension (0: one level) */
  double spacing[3]; /* the grid's spacing per direction */
  double h;          /* the kernel's h, which scales the columns' second-moment part */
  double *grid;      /* nall x (dim + 1): the grid coordinates of each atom (of
                     its owner, so that periodic images agree) and whether it
                     is constrained */
  double *matrix;    /* size x size: P^T H P, factored */
  double *vector;    /* size */
} sphs_coarse;

/* the quadratic B-spline of unit knot spacing centred on 0, and its
   derivative */
static inline double sphs_bspline(double u, double *derivative)
{
  const double a = fabs(u);
  if (a < 0.5) {
    *derivative = -2.0 * u;
    return 0.75 - u * u;
  }
  if (a < 1.5) {
    *derivative = (u > 0.0 ? 1.0 : -1.0) * (a - 1.5);
    return 0.5 * (a - 1.5) * (a - 1.5);
  }
  *derivative = 0.0;
  return 0.0;
}

/* The nodes whose functions reach grid coordinates t, their values and
   gradients (in grid units); returns how many (3^dim) */
static inline int sphs_coarse_corners(const sphs_coarse *c, const double *t, int node[27],
                                      double phi[27], double dphi[27][3])
{
  int first[3] = {0, 0, 0};
  double value[3][3], slope[3][3];
  for (int d = 0; d < c->dim; d++) {
    const double u = fmin(fmax(t[d], 0.0), (double) (c->count[d] - 3));
    first[d] = (int) floor(u + 0.5) - 1;
    for (int m = 0; m < 3; m++) value[d][m] = sphs_bspline(u - (first[d] + m), &slope[d][m]);
  }
  int corners = 0;
  const int total = (c->dim == 2) ? 9 : 27;
  for (int m = 0; m < total; m++) {
    const int digit[3] = {m % 3, (m / 3) % 3, m / 9};
    int index = 0, stride = 1;
    for (int d = 0; d < c->dim; d++) {
      index += (first[d] + digit[d] + 1) * stride; /* node -1 is index 0 */
      stride *= c->count[d];
    }
    node[corners] = index;
    phi[corners] = 1.0;
    for (int d = 0; d < c->dim; d++) phi[corners] *= value[d][digit[d]];
    for (int e = 0; e < 3; e++) {
      double g = 0.0;
      if (e < c->dim) {
        g = slope[e][digit[e]];
        for (int d = 0; d < c->dim; d++)
          if (d != e) g *= value[d][digit[d]];
      }
      dphi[corners][e] = g;
    }
    corners++;
  }
  return corners;
}

/* the coarse column of direction k at an atom (n multipliers), from its
   node's function value phi and gradient dphi (per length), h the
   kernel's */
static inline void sphs_coarse_column(int dim, double h, double phi, const double dphi[3], int k,
                                      double v[SPHS_MAX])
{
  static const int off_i[3] = {0, 0, 1}, off_j[3] = {1, 2, 2};
  const int n = sphs_count(dim), off = (dim == 2) ? 1 : 3;
  for (int l = 0; l < n; l++) v[l] = 0.0;
  v[k] = phi;
  v[dim + k] = -0.5 * h * dphi[k];
  for (int o = 0; o < off; o++) {
    const int i = off_i[o], j = off_j[o];
    v[2 * dim + o] = -0.25 * h * ((i == k ? dphi[j] : 0.0) + (j == k ? dphi[i] : 0.0));
  }
}

/* An atom's coarse columns: for each of its nodes and each direction, the
   column index and the column (n values); returns how many */
static inline int sphs_coarse_columns(const sphs_coarse *c, int a, int *index, double *columns)
{
  const double *t = c->grid + (size_t) a * (c->dim + 1);
  if (!(t[c->dim] > 0.0)) return 0;
  int node[27];
  double phi[27], dphi[27][3];
  const int corners = sphs_coarse_corners(c, t, node, phi, dphi);
  int m = 0;
  for (int q = 0; q < corners; q++) {
    double grad[3];
    for (int e = 0; e < 3; e++) grad[e] = dphi[q][e] / c->spacing[e];
    for (int k = 0; k < c->dim; k++, m++) {
      index[m] = node[q] * c->dim + k;
      sphs_coarse_column(c->dim, c->h, phi[q], grad, k, columns + (size_t) m * c->n);
    }
  }
  return m;
}

/* the grid over the constrained atoms, each atom's grid coordinates and the
   coarse arrays; returns 0 (one level) without positions or constrained
   atoms */
static inline int sphs_coarse_setup(const sphs_problem *p, sphs_coarse *c)
{
  const int dim = p->dim;
  c->dim = dim;
  c->n = sphs_count(dim);
  c->size = 0;
  c->grid = c->matrix = c->vector = NULL;
  if (!p->x || !(p->coarse > 0.0) || p->max_coarse < dim || !p->exchange.sum_array) return 0;
  double lo[3], hi[3];
  for (int d = 0; d < dim; d++) {
    double low = -HUGE_VAL, high = -HUGE_VAL;
    for (int a = 0; a < p->nlocal; a++)
      if (p->constrained[a]) {
        low = fmax(low, -p->x[3 * a + d]);
        high = fmax(high, p->x[3 * a + d]);
      }
    lo[d] = -p->exchange.max(p->exchange.context, low);
    hi[d] = p->exchange.max(p->exchange.context, high);
    if (!(hi[d] >= lo[d])) return 0; /* no constrained atom */
  }
  double h_coarse = p->coarse * p->h;
  for (;;) {
    int nodes = 1;
    for (int d = 0; d < dim; d++) {
      const int span = (int) ceil((hi[d] - lo[d]) / h_coarse - 1e-9);
      c->count[d] = 3 + (span > 0 ? span : 0);
      nodes *= c->count[d];
    }
    if ((double) nodes * dim <= p->max_coarse) {
      c->size = nodes * dim;
      break;
    }
    h_coarse *= 1.25;
  }
  for (int d = dim; d < 3; d++) c->count[d] = 1;
  for (int d = 0; d < 3; d++)
    c->spacing[d] = (d < dim && c->count[d] > 3) ? (hi[d] - lo[d]) / (c->count[d] - 3) : 1.0;
  c->h = p->h;
  const size_t width = (size_t) dim + 1;
  c->grid = (double *) malloc((size_t) p->nall * width * sizeof(double));
  c->matrix = (double *) malloc((size_t) c->size * c->size * sizeof(double));
  c->vector = (double *) malloc((size_t) c->size * sizeof(double));
  if (!c->grid || !c->matrix || !c->vector) {
    free(c->grid);
    free(c->matrix);
    free(c->vector);
    c->grid = c->matrix = c->vector = NULL;
    c->size = 0;
    return 0;
  }
  for (int a = 0; a < p->nlocal; a++) {
    double *t = c->grid + (size_t) a * width;
    for (int d = 0; d < dim; d++)
      t[d] = (c->count[d] > 3) ? (p->x[3 * a + d] - lo[d]) / c->spacing[d] : 0.0;
    t[dim] = p->constrained[a] ? 1.0 : 0.0;
  }
  p->exchange.forward(p->exchange.context, c->grid, (int) width);
  return 1;
}

static inline void sphs_coarse_free(sphs_coarse *c)
{
  free(c->grid);
  free(c->matrix);
  free(c->vector);
  c->grid = c->matrix = c->vector = NULL;
}

/* P^T (H + diag(shift)) P at the arguments arg, summed over the ranks and
   factored; 0 if it is not positive definite */
static inline int sphs_coarse_assemble(const sphs_problem *p, sphs_coarse *c, const double *basis,
                                       const double *arg, const double *shift)
{
  enum { MAX_COLUMNS = 27 * 3 };
  const int n = c->n, size = c->size, dim = p->dim;
  double *m = c->matrix;
  for (size_t k = 0; k < (size_t) size * size; k++) m[k] = 0.0;
  int index_i[MAX_COLUMNS], index_j[MAX_COLUMNS], index[2 * MAX_COLUMNS];
  double col_i[MAX_COLUMNS * SPHS_MAX], col_j[MAX_COLUMNS * SPHS_MAX], t[2 * MAX_COLUMNS];
  for (int q = 0; q < p->npairs; q++) {
    if (!(arg[q] > 0.0)) continue;
    const sphs_pair *pair = &p->pairs[q];
    const int ni = sphs_coarse_columns(c, pair->i, index_i, col_i);
    const int nj = sphs_coarse_columns(c, pair->j, index_j, col_j);
    if (ni + nj == 0) continue;
    /* t = P_i^T F(r_ij) + P_j^T F(r_ji), the columns the pair's row of H reaches;
       a column both atoms share is summed into one entry */
    const double *f = basis + (size_t) q * n;
    int count = 0;
    for (int u = 0; u < ni; u++) {
      double s = 0.0;
      for (int l = 0; l < n; l++) s += f[l] * col_i[u * n + l];
      index[count] = index_i[u];
      t[count++] = s;
    }
    for (int u = 0; u < nj; u++) {
      double s = 0.0;
      for (int l = 0; l < n; l++) s += (l < dim ? -f[l] : f[l]) * col_j[u * n + l];
      int v = 0;
      while (v < ni && index[v] != index_j[u]) v++;
      if (v < ni)
        t[v] += s;
      else {
        index[count] = index_j[u];
        t[count++] = s;
      }
    }
    const double w = sphs_share(p, pair->j) * pair->g;
    for (int u = 0; u < count; u++) {
      const double wu = w * t[u];
      double *row = m + (size_t) index[u] * size;
      for (int v = 0; v < count; v++) row[index[v]] += wu * t[v];
    }
  }
  for (int a = 0; a < p->nlocal; a++) {
    const int na = sphs_coarse_columns(c, a, index_i, col_i);
    const double *s = shift + (size_t) a * n;
    for (int u = 0; u < na; u++)
      for (int v = 0; v < na; v++) {
        double sum = 0.0;
        for (int l = 0; l < n; l++) sum += col_i[u * n + l] * s[l] * col_i[v * n + l];
        m[(size_t) index_i[u] * size + index_i[v]] += sum;
      }
  }
  p->exchange.sum_array(p->exchange.context, m, size * size);
  /* columns no constrained atom carries are empty: identity there; a trace
     bound keeps the exact null fields (constant mu) definite */
  double largest = 0.0;
  for (int k = 0; k < size; k++) largest = fmax(largest, m[(size_t) k * size + k]);
  for (int k = 0; k < size; k++) {
    double *d = m + (size_t) k * size + k;
    *d = (*d > 0.0) ? *d + 1e-12 * largest : 1.0;
  }
  return sphs_cholesky(size, m);
}

/* z += P (P^T H P)^-1 P^T r on the owned atoms */
static inline void sphs_coarse_apply(const sphs_problem *p, sphs_coarse *c, const double *r,
                                     double *z)
{
  enum { MAX_COLUMNS = 27 * 3 };
  const int n = c->n;
  int index[MAX_COLUMNS];
  double columns[MAX_COLUMNS * SPHS_MAX];
  for (int k = 0; k < c->size; k++) c->vector[k] = 0.0;
  for (int a = 0; a < p->nlocal; a++) {
    const int na = sphs_coarse_columns(c, a, index, columns);
    const double *ra = r + (size_t) a * n;
    for (int u = 0; u < na; u++) {
      double s = 0.0;
      for (int l = 0; l < n; l++) s += columns[u * n + l] * ra[l];
      c->vector[index[u]] += s;
    }
  }
  p->exchange.sum_array(p->exchange.context, c->vector, c->size);
  sphs_cholesky_solve(c->size, c->matrix, c->vector, c->vector);
  for (int a = 0; a < p->nlocal; a++) {
    const int na = sphs_coarse_columns(c, a, index, columns);
    double *za = z + (size_t) a * n;
    for (int u = 0; u < na; u++) {
      const double y = c->vector[index[u]];
      for (int l = 0; l < n; l++) za[l] += y * columns[u * n + l];
    }
  }
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
  sphs_result result = {0, 0, 0, 0, 0.0, 0.0, 0};

  for (int a = 0; a < p->nlocal; a++) {
    sphs_target(dim, p->volume[a], inv_h, target + (size_t) a * n);
    if (!p->constrained[a])
      for (int k = 0; k < n; k++) nu[(size_t) a * n + k] = 0.0;
  }
  for (int q = 0; q < p->npairs; q++) sphs_basis(dim, p->pairs[q].r, inv_h, basis + (size_t) q * n);
  p->exchange.forward(p->exchange.context, nu, n);
  sphs_coarse coarse;
  sphs_coarse_setup(p, &coarse);
  result.coarse_size = coarse.size;
  int two_level = 0;

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
       stall the Newton steps on those fields instead (a shift of 1e-2 of
       the diagonal leaves a residual of 1e-3 after 50 steps where 1e-6
       converges in about a dozen) */
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

    /* the coarse matrix of the first step (every pair active) serves all
       steps: fewer CG steps in all than with a new one each Newton step,
       and no factoring per step */
    if (coarse.size && result.newton_steps == 1)
      two_level = sphs_coarse_assemble(p, &coarse, basis, arg, shift);

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
      if (two_level) sphs_coarse_apply(p, &coarse, cg_r, cg_z);
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
  sphs_coarse_free(&coarse);
  return result;
}

#endif
