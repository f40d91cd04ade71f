/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   The MACHDYN solids of a run (sph_machdyn.h).
------------------------------------------------------------------------- */

#include "sph_machdyn.h"

#include "atom.h"
#include "comm.h"
#include "compute.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "fix_sph_materials.h"
#include "force.h"
#include "group.h"
#include "modify.h"
#include "neighbor.h"
#include "pair.h"
#include "sph_checks.h"
#include "sph_hub.h"
#include "sph_particle.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

static const char who[] = "Fix sph/materials";

std::vector<int> SPHMachdynSolids::tlsph_types(LAMMPS *lmp)
{
  std::vector<int> found;
  Pair *tlsph = SPHHub(lmp).machdyn_solids_pair();
  if (!tlsph || !tlsph->setflag) return found;
  for (int t = 1; t <= lmp->atom->ntypes; t++)
    if (tlsph->setflag[t][t]) found.push_back(t);
  return found;
}

/* ----------------------------------------------------------------------
   the per-atom vectors of the solids (sph_particle.h), held by an internal
   fix property/atom that grows them with the atoms; made when the hub is, in a
   scene of atom style smd (hybrid), as a fix cannot be added during init
------------------------------------------------------------------------- */

void SPHMachdynSolids::create_vector()
{
  if (!atom->smd_flag) return;
  int flag, cols;
  if (atom->find_custom(SPHParticles::SOLID_VECTOR, flag, cols) >= 0) return;
  modify->add_fix(fmt::format("{} all property/atom i_{} d_{} d_{} d_{} ghost yes", VECTOR_FIX,
                              SPHParticles::SOLID_VECTOR, SPHParticles::T0_VECTOR, STRESS_T_VECTOR,
                              PLASTIC_VECTOR));
  vector_fix_made = 1;
}

void SPHMachdynSolids::delete_vector()
{
  if (vector_fix_made && modify->nfix && modify->find_fix(VECTOR_FIX) >= 0)
    modify->delete_fix(VECTOR_FIX);
  vector_fix_made = 0;
}

std::string SPHMachdynSolids::type_list() const
{
  std::string text;
  for (int t : types) text += (text.empty() ? "" : " ") + std::to_string(t);
  return text;
}

/* ---------------------------------------------------------------------- */

void SPHMachdynSolids::init()
{
  types = tlsph_types(lmp);
  solid_type.assign(atom->ntypes + 1, 0);
  for (int t : types) solid_type[t] = 1;
  for (int t = 1; t <= atom->ntypes; t++)
    if (!solid_type[t] && materials->solid_property_given(t) && !unused_warned) {
      error->warning(FLERR,
                     "{}: type {} has tref, bulk or fwork, which only MACHDYN solids use, but "
                     "pair smd/tlsph has no coefficients for it: they are ignored",
                     who, t);
      unused_warned = 1;
    }
  if (types.empty()) return;

  // atom style smd alone has neither cv nor rho: the conduction needs both
  if (!atom->cv_flag || !atom->rho_flag || !atom->esph_flag || !atom->vfrac_flag ||
      !atom->rmass_flag)
    error->all(FLERR,
               "{}: the MACHDYN solids of pair smd/tlsph (types {}) need atom_style hybrid sph "
               "smd (the atom style has no {})",
               who, type_list(),
               !atom->cv_flag          ? "cv"
                   : !atom->rho_flag   ? "rho"
                   : !atom->esph_flag  ? "esph"
                   : !atom->vfrac_flag ? "vfrac"
                                       : "rmass");
  for (int t : types) {
    if (!(materials->cv(t) > 0.0))
      error->all(FLERR,
                 "{}: type {} is a MACHDYN solid (pair smd/tlsph) and needs its cv (specific "
                 "heat) in fix sph/materials",
                 who, t);
    if (!(materials->rho0(t) > 0.0))
      error->all(FLERR,
                 "{}: type {} is a MACHDYN solid (pair smd/tlsph) and needs its rho0 (the "
                 "reference density of its *COMMON) in fix sph/materials",
                 who, t);
    if (!std::isfinite(materials->tref(t)))
      error->all(FLERR,
                 "{}: type {} is a MACHDYN solid (pair smd/tlsph) and needs its reference "
                 "temperature tref in fix sph/materials (its energy is m cv (T - tref), as "
                 "MACHDYN's Johnson-Cook model reads it with its own T0)",
                 who, t);
    if (materials->energy_convention_of(t) == 0)
      error->all(FLERR,
                 "{}: type {} is a MACHDYN solid (pair smd/tlsph), but sph/set temperature gave "
                 "its atoms esph = cv T before pair smd/tlsph was defined: define the pair "
                 "first, so that they get MACHDYN's m cv (T - tref)",
                 who, t);
    if (materials->eos(t))
      error->all(FLERR,
                 "{}: type {} is a MACHDYN solid (pair smd/tlsph) and cannot have an equation "
                 "of state in fix sph/materials (pair smd/tlsph gives its stress)",
                 who, t);
    if (materials->expansion(t) != 0.0 && !(materials->bulk(t) > 0.0))
      error->all(FLERR,
                 "{}: type {} is a MACHDYN solid with expansion {} and needs its bulk modulus "
                 "(bulk K, as its *COMMON gives it: E / (3 (1 - 2 nu))) in fix sph/materials: its "
                 "thermal stress is about -K expansion (T - T_start)",
                 who, t, materials->expansion(t));
  }
  expanding = 0;
  for (int t : types) expanding |= (materials->expansion(t) != 0.0);
  int flag, cols;
  // (made with the hub in every scene of atom style smd: create_vector())
  if (atom->find_custom(SPHParticles::SOLID_VECTOR, flag, cols) < 0)
    error->all(FLERR,
               "{}: no per-atom vector {} for the MACHDYN solids (its internal fix {} was "
               "deleted: define fix sph/materials again)",
               who, SPHParticles::SOLID_VECTOR, VECTOR_FIX);
  check_styles();
  check_exclusions();
  check_periodic();
}

/* ----------------------------------------------------------------------
   pair smd/tlsph takes each particle's partners from its neighbor list at
   the first step and deletes the particles that have none (a message, no
   error): a neigh_modify exclude of the solid's own pairs (as walls' pairs
   are excluded) would silently take the solid apart
------------------------------------------------------------------------- */

void SPHMachdynSolids::check_exclusions()
{
  for (int k = 0; k < neighbor->nex_type; k++) {
    const int t1 = neighbor->ex1_type[k], t2 = neighbor->ex2_type[k];
    if (solid_type[t1] && solid_type[t2])
      error->all(FLERR,
                 "{}: neigh_modify exclude type {} {} leaves out pairs of the MACHDYN solid types "
                 "{}: pair smd/tlsph finds each particle's partners in the neighbor list and "
                 "deletes the particles that have none",
                 who, t1, t2, type_list());
  }
  const int nlocal = atom->nlocal;
  const int *const type = atom->type;
  const int *const mask = atom->mask;
  for (int k = 0; k < neighbor->nex_group; k++) {
    const int bit1 = group->bitmask[neighbor->ex1_group[k]];
    const int bit2 = group->bitmask[neighbor->ex2_group[k]];
    int local[2] = {0, 0}, all[2];
    for (int i = 0; i < nlocal; i++)
      if (solid_type[type[i]]) {
        if (mask[i] & bit1) local[0] = 1;
        if (mask[i] & bit2) local[1] = 1;
      }
    MPI_Allreduce(local, all, 2, MPI_INT, MPI_MAX, world);
    if (all[0] && all[1])
      error->all(FLERR,
                 "{}: neigh_modify exclude group {} {} leaves out pairs of atoms of the MACHDYN "
                 "solid types {}: pair smd/tlsph finds each particle's partners in the neighbor "
                 "list and deletes the particles that have none",
                 who, group->names[neighbor->ex1_group[k]], group->names[neighbor->ex2_group[k]],
                 type_list());
  }
}

/* ----------------------------------------------------------------------
   pair smd/tlsph (ComputeForces of LAMMPS 29Sep2021 and 4Feb2025) takes the
   minimum image of its reference distance before it sets it, once per step
   on a value left on the stack: with LAMMPS 29Sep2021 a large one loops
   there forever (seen on 2 ranks), later releases stop with 'Atoms have
   moved too far apart'. Warned once: a periodic scene may still be meant.
------------------------------------------------------------------------- */

void SPHMachdynSolids::check_periodic()
{
  if (periodic_warned || !(domain->xperiodic || domain->yperiodic || domain->zperiodic)) return;
  periodic_warned = 1;
  if (comm->me == 0)
    error->warning(FLERR,
                   "{}: the MACHDYN solids (types {}) are in a periodic box: pair smd/tlsph "
                   "reads an unset reference distance once per step there, so that a run can "
                   "hang (LAMMPS 29Sep2021) or stop with 'Atoms have moved too far apart' "
                   "(later releases); boundaries f, s or m avoid it",
                   who, type_list());
}

/* ----------------------------------------------------------------------
   the package's styles and LAMMPS's SPH styles that would act on the
   solid atoms without knowing their energy convention or that they move
------------------------------------------------------------------------- */

void SPHMachdynSolids::check_styles()
{
  const int nlocal = atom->nlocal;
  const int *const type = atom->type;
  const int *const mask = atom->mask;
  auto solid_atoms_in = [&](int groupbit) {
    int local = 0, total = 0;
    for (int i = 0; i < nlocal; i++)
      if ((mask[i] & groupbit) && solid_type[type[i]]) local++;
    MPI_Allreduce(&local, &total, 1, MPI_INT, MPI_SUM, world);
    return total;
  };
  const std::string supported =
      "pair sph/cleary/heat, fix sph/wall/isothermal, fix sph/surface/flux, fix "
      "sph/wall/adami (the solid as a moving wall of pair sph/harmonic/visc's flow) and "
      "compute sph/thermal";
  const SPHHub hub(lmp);
  for (int i = 0; i < modify->nfix; i++) {
    Fix *fix = modify->fix[i];
    if (hub.may_act_on_machdyn(fix)) continue;
    const int n = solid_atoms_in(fix->groupbit);
    if (n)
      error->all(FLERR,
                 "Fix {} ({}): its group {} holds {} atoms of the MACHDYN solid types {} of pair "
                 "smd/tlsph, which fix smd/integrate_tlsph moves and whose energy is held as "
                 "MACHDYN holds it; on them USER-SPHTHERMAL supports {}",
                 fix->id, fix->style, group->names[fix->igroup], n, type_list(), supported);
  }
  for (int i = 0; i < modify->ncompute; i++) {
    Compute *compute = modify->compute[i];
    if (hub.may_act_on_machdyn(compute)) continue;
    const int n = solid_atoms_in(compute->groupbit);
    if (n)
      error->all(FLERR,
                 "Compute {} ({}): its group {} holds {} atoms of the MACHDYN solid types {} of "
                 "pair smd/tlsph, whose temperature is not esph / cv; on them USER-SPHTHERMAL "
                 "supports {} (its per-atom temperature for dumps)",
                 compute->id, compute->style, group->names[compute->igroup], n, type_list(),
                 supported);
  }
}

/* ----------------------------------------------------------------------
   m / vfrac of each solid atom is the rho0 of its type (MACHDYN's
   'set ... smd/mass/density' and the *COMMON density give it)
------------------------------------------------------------------------- */

void SPHMachdynSolids::check_density()
{
  const int nlocal = atom->nlocal;
  const int *const type = atom->type;
  const double *const rmass = atom->rmass;
  const double *const vfrac = atom->vfrac;
  // every rank agrees on the lowest bad ID: a collective error names it
  SPHCheck::FirstBad bad;    // type, mass, volume
  for (int i = 0; i < nlocal; i++) {
    if (!solid_type[type[i]]) continue;
    const double rho0 = materials->rho0(type[i]);
    const double density = rmass[i] / vfrac[i];
    if (!std::isfinite(density) || fabs(density - rho0) > 1e-6 * rho0)
      bad.consider(atom->tag[i], type[i], rmass[i], vfrac[i]);
  }
  if (bad.agree(lmp)) {
    const int t = (int) bad.info[0];
    error->all(FLERR,
               "{}: atom {} of the MACHDYN solid type {} has mass / volume {} (mass {}, volume "
               "{}), not the type's rho0 {} (set its mass with 'set ... smd/mass/density')",
               who, bad.tag, t, bad.info[1] / bad.info[2], bad.info[1], bad.info[2],
               materials->rho0(t));
  }
}

/* ---------------------------------------------------------------------- */

void SPHMachdynSolids::setup()
{
  if (types.empty()) return;
  // at step 0 the solids are in their reference configuration; later (a
  // run after a run, a restart) rho is their deformed density, and vfrac
  // is no longer m / rho0 once MACHDYN has updated the reference
  const int reference = (update->ntimestep == 0);
  if (reference) check_density();
  const int nall = atom->nlocal + atom->nghost;
  const int *const type = atom->type;
  for (int i = 0; i < nall; i++) {
    if (!solid_type[type[i]]) continue;
    atom->cv[i] = materials->cv(type[i]);
    if (reference) atom->rho[i] = atom->rmass[i] / atom->vfrac[i];
  }
  // the thermal stress counts from the temperature at the start of the
  // first run from step 0 (a restart keeps the one in its file)
  if (reference && expanding && !stress_started) {
    stress_started = 1;
    double *const last = stress_temperature();
    const SPHParticles particles(atom);
    for (int i = 0; i < atom->nlocal; i++)
      if (solid_type[type[i]])
        last[i] = particles.temperature_of_solid(i, materials->tref(type[i]));
  }
  // the work to heat likewise counts from the plastic strain at that start
  if (reference && !plastic_started) {
    plastic_started = 1;
    double *const converted = converted_strain();
    for (int i = 0; i < atom->nlocal; i++) converted[i] = atom->eff_plastic_strain[i];
  }
}

/* ----------------------------------------------------------------------
   thermal expansion in MACHDYN's constitutive update, without changing
   LAMMPS: pair smd/tlsph integrates a rate form of the stress, held in the
   per-atom state smd_stress (read and written back at each force
   evaluation); before each one, the thermal part of the rate is added to
   that state, so that sigma_dot = C (D - D_th): a free solid expands, a
   held one is stressed. The thermal strain is beta_lin (T - T0) of the
   length at T0 (beta_lin = beta / 3, T0 the type's tref), so the thermal
   stretch from the atom's last temperature T_last to T is
   (1 + beta_lin (T - T0)) / (1 + beta_lin (T_last - T0)), and the rate
   form, whose pressure follows ln J, gets -3 K ln(stretch) on the
   diagonal (-K beta dT for small changes).
------------------------------------------------------------------------- */

void SPHMachdynSolids::thermal_stress()
{
  if (!expanding) return;
  double *const last = stress_temperature();
  double **const stress = atom->smd_stress;
  const int *const type = atom->type;
  const SPHParticles particles(atom);
  for (int i = 0; i < atom->nlocal; i++) {
    const int t = type[i];
    if (!solid_type[t] || materials->expansion(t) == 0.0) continue;
    const double t0 = materials->tref(t);
    const double T = particles.temperature_of_solid(i, t0);
    const double linear = materials->expansion(t) / 3.0;
    const double length = 1.0 + linear * (T - t0), length_last = 1.0 + linear * (last[i] - t0);
    if (!(length > 0.0))
      SPHCheck::stop(
          lmp, FLERR,
          fmt::format("{}: atom {} of MACHDYN solid type {} at T = {} would have no "
                      "length: its thermal strain expansion/3 (T - tref) is {}, below -1",
                      who, atom->tag[i], t, T, linear * (T - t0)));
    const double change = -3.0 * materials->bulk(t) * log(length / length_last);
    // (smd_stress: xx xy xz yy yz zz)
    stress[i][0] += change;
    stress[i][3] += change;
    stress[i][5] += change;
    last[i] = T;
  }
}

double *SPHMachdynSolids::stress_temperature()
{
  // (the internal fix holds it with SOLID_VECTOR, whose presence init() checks)
  int flag, cols;
  return atom->dvector[atom->find_custom(STRESS_T_VECTOR, flag, cols)];
}

double *SPHMachdynSolids::converted_strain()
{
  int flag, cols;
  return atom->dvector[atom->find_custom(PLASTIC_VECTOR, flag, cols)];
}

/* ----------------------------------------------------------------------
   work to heat (Xu, eq. 13: fwork w = rho c dT). Pair smd/tlsph adds
   the work of the stress (elastic, plastic, its artificial viscosity and
   hourglass control) to desph, as MACHDYN's esph is an internal energy.
   Here esph is heat (sph_particle.h): that work is taken out again, and
   fwork times the plastic work of the evaluation put in, sigma_eq
   d(eps_p) V: MACHDYN's strength models return the deviatoric stress to
   the yield surface, so its von Mises stress after the evaluation is the
   flow stress that the plastic strain increment d(eps_p) was made at,
   and V = vfrac det F the current volume. The work that stays out is the
   stored elastic energy, the cold work (1 - fwork) and the dissipation of
   the artificial terms.
------------------------------------------------------------------------- */

void SPHMachdynSolids::note_heat(int i, double rate)
{
  if (noted_step != update->ntimestep) {
    // the first note of this force evaluation (earlier notes were used or,
    // from an evaluation without work_to_heat, are dropped)
    noted_heat.assign(noted_heat.size(), 0.0);
    noted_step = update->ntimestep;
  }
  if ((int) noted_heat.size() <= i) noted_heat.resize(atom->nmax, 0.0);
  noted_heat[i] += rate;
}

void SPHMachdynSolids::work_to_heat(int step)
{
  if (types.empty()) return;
  const int nlocal = atom->nlocal;
  // no note in this evaluation: no package style heated a solid atom
  if (noted_step != update->ntimestep) noted_heat.clear();
  noted_heat.resize(std::max((int) noted_heat.size(), nlocal), 0.0);
  double *const converted = converted_strain();
  const double *const plastic = atom->eff_plastic_strain;
  const int *const type = atom->type;
  const double *const det = SPHHub(lmp).machdyn_deformation_det();
  double **const stress = atom->smd_stress;
  const double *const vfrac = atom->vfrac;
  double *const desph = atom->desph;
  const double dt = update->dt;
  double work = 0.0, heat = 0.0;
  for (int i = 0; i < nlocal; i++) {
    const int t = type[i];
    if (!solid_type[t]) continue;
    const double *const s = stress[i];    // (xx xy xz yy yz zz)
    const double p = (s[0] + s[3] + s[5]) / 3.0;
    const double j2 =
        0.5 * ((s[0] - p) * (s[0] - p) + (s[3] - p) * (s[3] - p) + (s[5] - p) * (s[5] - p)) +
        s[1] * s[1] + s[2] * s[2] + s[4] * s[4];
    const double volume = vfrac[i] * ((det && det[i] > 0.0) ? det[i] : 1.0);
    const double plastic_work = sqrt(3.0 * j2) * (plastic[i] - converted[i]) * volume;
    const double converted_rate = materials->fwork(t) * plastic_work / dt;
    work += desph[i] - noted_heat[i];
    heat += converted_rate;
    desph[i] = noted_heat[i] + converted_rate;
    if (step) converted[i] = plastic[i];
  }
  if (step) {
    // fix smd/integrate_tlsph applies a step's rate once, over the whole step
    work_local += dt * work;
    heat_local += dt * heat;
  }
  noted_step = -1;    // (the notes are used)
}

void SPHMachdynSolids::restore_tallies(double work, double heat)
{
  // (the sums over the ranks are the totals)
  work_local = comm->me == 0 ? work : 0.0;
  heat_local = comm->me == 0 ? heat : 0.0;
}

double SPHMachdynSolids::work_done() const
{
  double sum = 0.0;
  MPI_Allreduce(&work_local, &sum, 1, MPI_DOUBLE, MPI_SUM, world);
  return sum;
}

double SPHMachdynSolids::heat_from_work() const
{
  double sum = 0.0;
  MPI_Allreduce(&heat_local, &sum, 1, MPI_DOUBLE, MPI_SUM, world);
  return sum;
}

/* ----------------------------------------------------------------------
   the current density of the solid atoms: their mass over their reference
   volume (MACHDYN's vfrac) times det F of pair smd/tlsph's last force
   evaluation (this step's positions). MACHDYN gives a failed atom det F = 0
   and leaves it out of its stress: it keeps its last density. When fix
   smd/integrate_tlsph's reference configuration is updated, MACHDYN sets
   vfrac = m / rho from this density.
------------------------------------------------------------------------- */

void SPHMachdynSolids::follow_deformation()
{
  if (types.empty()) return;
  const double *const det = SPHHub(lmp).machdyn_deformation_det();
  if (!det) return;
  const int *const type = atom->type;
  const double *const rmass = atom->rmass;
  const double *const vfrac = atom->vfrac;
  double *const rho = atom->rho;
  for (int i = 0; i < atom->nlocal; i++)
    if (solid_type[type[i]] && det[i] > 0.0) rho[i] = rmass[i] / (vfrac[i] * det[i]);
}

/* ---------------------------------------------------------------------- */

void SPHMachdynSolids::mark()
{
  int flag, cols;
  const int isolid = atom->find_custom(SPHParticles::SOLID_VECTOR, flag, cols);
  const int it0 = atom->find_custom(SPHParticles::T0_VECTOR, flag, cols);
  if (isolid < 0 || it0 < 0) return;
  int *const solid = atom->ivector[isolid];
  double *const t0 = atom->dvector[it0];
  const int nall = atom->nlocal + atom->nghost;
  const int *const type = atom->type;
  const int marked = !solid_type.empty();
  for (int i = 0; i < nall; i++) {
    solid[i] = marked ? solid_type[type[i]] : 0;
    t0[i] = solid[i] ? materials->tref(type[i]) : 0.0;
  }
}
