/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifndef LMP_SPH_BODY_FORCE_H
#define LMP_SPH_BODY_FORCE_H

#include "sph_buoyancy.h"

namespace LAMMPS_NS {

class LAMMPS;
class Fix;

// The body force of a run is given once, as a fix that exposes its
// acceleration as extract("gvec") (LAMMPS's fix gravity). Every style that
// needs it (the wall pressure of fix sph/wall/adami, the hydrostatic density
// diffusion of pair sph/harmonic/visc, the force limit of fix sph/dt/reset,
// the hydrostatic start of sph/set) reads it here.
namespace SPHBodyForce {

  // The buoyancy of fix sph/boussinesq: a = -g beta(type) (T - T0) on the
  // atoms of its group (sph_buoyancy.h), valid for the fix's lifetime. T0 is
  // one temperature, or (nlayers > 0) a function of the height along g:
  // linear between the values at the layers' centres, and in the outer half
  // of the first and last layer.
  struct Buoyancy {
    const double *gravity;     // g: the fix's own vector or fix gravity's
    double t0;                 // reference temperature (nlayers == 0)
    const double *beta;        // expansion coefficient per type (1..ntypes)
    int groupbit;              // the buoyant atoms
    int nlayers;               // T0 by layers: their number, 0 for one T0
    const double *layer_t0;    // T0 at the centre of each layer
    double unit[3];            // direction of g
    double origin, width;      // layer k spans origin + [k, k + 1) width along unit
    // the potential phi of the buoyancy's curl-free part per atom (owned and
    // ghost), whose pressure rho0 phi the flow adds to its equation of
    // state's; nullptr (or *potential nullptr) when the fix solves none
    double *const *potential;
  };
  // the buoyancy solves its potential
  inline bool has_potential(const Buoyancy *b)
  {
    return b && b->potential && *b->potential;
  }
  // phi of atom i, 0 without one
  inline double potential_of(const Buoyancy *b, int mask, int i)
  {
    return (has_potential(b) && (mask & b->groupbit)) ? (*b->potential)[i] : 0.0;
  }

  // T0 at position x
  inline double reference(const Buoyancy &b, const double x[3])
  {
    if (b.nlayers == 0) return b.t0;
    const double along = x[0] * b.unit[0] + x[1] * b.unit[1] + x[2] * b.unit[2];
    if (b.nlayers == 1) return b.layer_t0[0];
    const double c = (along - b.origin) / b.width - 0.5;
    // the outer half layers continue their neighbours' line
    const int k = c < 1.0 ? 0 : (c >= b.nlayers - 2 ? b.nlayers - 2 : (int) c);
    const double frac = c - k;
    return (1.0 - frac) * b.layer_t0[k] + frac * b.layer_t0[k + 1];
  }

  // the body acceleration an atom feels: 'body' (fix gravity's, or a
  // style's given vector) plus the buoyancy when the atom is buoyant
  // ('buoyancy' may be nullptr); t is its temperature, x its position
  inline void acceleration(const double body[3], const Buoyancy *buoyancy, int mask, int type,
                           double t, const double x[3], double a[3])
  {
    a[0] = body[0];
    a[1] = body[1];
    a[2] = body[2];
    if (!buoyancy || !(mask & buoyancy->groupbit)) return;
    double b[3];
    sphb_acceleration(buoyancy->gravity, buoyancy->beta[type], t, reference(*buoyancy, x), b);
    for (int k = 0; k < 3; k++) a[k] += b[k];
  }

  // the acceleration vector of the body-force fix, valid for the fix's
  // lifetime and updated by it when it varies in time; nullptr when there
  // is none. Several such fixes (e.g. on two groups) must agree: otherwise
  // an error naming 'who' and both fixes.
  const double *find(LAMMPS *lmp, const char *who);

  // the same, as an error naming 'who' and 'why' when there is none
  const double *require(LAMMPS *lmp, const char *who, const char *why);

  // an error naming 'who' and the body-force fix when its acceleration is
  // not finite (fix gravity's direction 'vector 0 0 0', a variable's NaN):
  // before a style derives anything from it
  void check_finite(LAMMPS *lmp, const char *file, int line, const char *who, const double *gvec);

  // a style's keyword that gives its own acceleration ('given') instead of
  // reading the body force: a warning (rank 0) naming 'who', 'keyword' and
  // both vectors when a constant body-force fix gives another one; 'reads'
  // says what the style reads without the keyword
  void warn_overridden(LAMMPS *lmp, const char *who, const char *keyword, const double *given,
                       const char *reads);

  // the fix whose acceleration find() returns, nullptr when there is none
  class Fix *source(LAMMPS *lmp);

  // the group bits of the atoms some body-force fix acts on (0: none)
  int groupbits(LAMMPS *lmp);

  // 1 when 'fix' is a fix gravity whose magnitude is a constant 0 (not a
  // variable, which may ramp it up later): its acceleration is 0 for good
  int constant_zero(class Fix *fix);

  // 1 when 'fix' is a fix gravity with no variable: its acceleration is set
  // from its creation on (a variable one sets it at its first force)
  int constant(class Fix *fix);

  // the buoyancy of the run (fix sph/boussinesq), nullptr when none
  const Buoyancy *find_buoyancy(LAMMPS *lmp);

}    // namespace SPHBodyForce
}    // namespace LAMMPS_NS

#endif
