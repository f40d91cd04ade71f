/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   The body force of the run, read from the fix that applies it
   (sph_body_force.h).
------------------------------------------------------------------------- */

#include "sph_body_force.h"

#include "comm.h"
#include "error.h"
#include "fix.h"
#include "fix_gravity.h"
#include "fix_sph_boussinesq.h"
#include "lammps.h"
#include "modify.h"
#include "sph_hub.h"

#include <cmath>

using namespace LAMMPS_NS;

/* ---------------------------------------------------------------------- */

const double *SPHBodyForce::find(LAMMPS *lmp, const char *who)
{
  const double *gvec = nullptr;
  Fix *source = nullptr;
  for (int i = 0; i < lmp->modify->nfix; i++) {
    Fix *fix = lmp->modify->fix[i];
    int dim = 0;
    const double *g = (const double *) fix->extract("gvec", dim);
    if (!g || dim != 1) continue;
    if (gvec && (g[0] != gvec[0] || g[1] != gvec[1] || g[2] != gvec[2]))
      lmp->error->all(FLERR,
                      "{}: fix {} (style {}) and fix {} (style {}) give different body "
                      "accelerations ({} {} {} and {} {} {}); the package reads one",
                      who, source->id, source->style, fix->id, fix->style, gvec[0], gvec[1],
                      gvec[2], g[0], g[1], g[2]);
    if (!gvec) {
      gvec = g;
      source = fix;
    }
  }
  return gvec;
}

/* ---------------------------------------------------------------------- */

const double *SPHBodyForce::require(LAMMPS *lmp, const char *who, const char *why)
{
  const double *gvec = find(lmp, who);
  if (!gvec)
    lmp->error->all(FLERR, "{} needs the body force for {}: define it with fix gravity first",
                    who, why);
  return gvec;
}

/* ---------------------------------------------------------------------- */

void SPHBodyForce::check_finite(LAMMPS *lmp, const char *file, int line, const char *who,
                                const double *gvec)
{
  if (!gvec || (std::isfinite(gvec[0]) && std::isfinite(gvec[1]) && std::isfinite(gvec[2])))
    return;
  Fix *fix = source(lmp);
  lmp->error->all(file, line,
                  "{}: the body acceleration of fix {} (style {}) is ({} {} {}); it must be "
                  "finite (a direction 'vector 0 0 0', or a variable's NaN?)",
                  who, fix ? fix->id : "?", fix ? fix->style : "?", gvec[0], gvec[1], gvec[2]);
}

/* ---------------------------------------------------------------------- */

const SPHBodyForce::Buoyancy *SPHBodyForce::find_buoyancy(LAMMPS *lmp)
{
  // fix sph/boussinesq's init makes a second one an error
  const std::vector<FixSPHBoussinesq *> all = SPHHub(lmp).fixes<FixSPHBoussinesq>();
  return all.empty() ? nullptr : &all.front()->added_buoyancy();
}

/* ---------------------------------------------------------------------- */

Fix *SPHBodyForce::source(LAMMPS *lmp)
{
  for (int i = 0; i < lmp->modify->nfix; i++) {
    int dim = 0;
    if (lmp->modify->fix[i]->extract("gvec", dim) && dim == 1) return lmp->modify->fix[i];
  }
  return nullptr;
}

int SPHBodyForce::groupbits(LAMMPS *lmp)
{
  int bits = 0;
  for (int i = 0; i < lmp->modify->nfix; i++) {
    int dim = 0;
    if (lmp->modify->fix[i]->extract("gvec", dim) && dim == 1)
      bits |= lmp->modify->fix[i]->groupbit;
  }
  return bits;
}

/* ----------------------------------------------------------------------
   fix gravity keeps how its magnitude is given (a number or a variable)
   protected: read it through a class derived from it (a member pointer
   formed in the derived class applies to any FixGravity); CONSTANT is 0 in
   every LAMMPS version the package supports
------------------------------------------------------------------------- */

namespace {
struct GravityMagnitude : public FixGravity {
  static int constant_zero(FixGravity *fix)
  {
    return fix->*(&GravityMagnitude::mstyle) == 0 && fix->*(&GravityMagnitude::magnitude) == 0.0;
  }
  static int constant(FixGravity *fix) { return fix->*(&GravityMagnitude::varflag) == 0; }
};
}    // namespace

int SPHBodyForce::constant(Fix *fix)
{
  auto *gravity = dynamic_cast<FixGravity *>(fix);
  return gravity ? GravityMagnitude::constant(gravity) : 0;
}

int SPHBodyForce::constant_zero(Fix *fix)
{
  auto *gravity = dynamic_cast<FixGravity *>(fix);
  return gravity ? GravityMagnitude::constant_zero(gravity) : 0;
}

/* ---------------------------------------------------------------------- */

void SPHBodyForce::warn_overridden(LAMMPS *lmp, const char *who, const char *keyword,
                                   const double *given, const char *reads)
{
  const double *gvec = find(lmp, who);
  // a fix gravity with variables sets its vector only at its first force
  if (!gvec || !constant(source(lmp)) || lmp->comm->me != 0) return;
  if (given[0] == gvec[0] && given[1] == gvec[1] && given[2] == gvec[2]) return;
  lmp->error->warning(FLERR, "{}: {} {} {} {} differs from the body force of fix gravity ({} {} {}); {}",
                      who, keyword, given[0], given[1], given[2], gvec[0], gvec[1], gvec[2], reads);
}
