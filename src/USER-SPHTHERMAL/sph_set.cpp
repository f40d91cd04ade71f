/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   sph/set: the initial state of SPH particles from fix sph/materials
   (sph_set.h).
------------------------------------------------------------------------- */

#include "sph_set.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_sph_materials.h"
#include "group.h"
#include "input.h"
#include "irregular.h"
#include "memory.h"
#include "sph_body_force.h"
#include "sph_checks.h"
#include "sph_compat.h"
#include "sph_eos.h"
#include "sph_machdyn.h"
#include "sph_particle.h"
#include "sph_sound_speed.h"
#include "variable.h"

#include <cmath>
#include <cstring>
#include <vector>

using namespace LAMMPS_NS;

static const char cmd[] = "sph/set";

/* ----------------------------------------------------------------------
   sph/set group-ID keyword args ...: whatever their order on the line, the
   keywords act in the order of their physics: materials (rho, cv, mass),
   then temperature (e = cv T needs the material's cv), then hydrostatic
   (the densities that materials would otherwise overwrite)
------------------------------------------------------------------------- */

void SPHSet::command(int narg, char **arg)
{
  if (!atom->rho_flag || !atom->esph_flag || !atom->cv_flag)
    error->all(FLERR, "{} command requires atom style sph (rho, esph, cv)", cmd);
  if (narg < 2)
    error->all(
        FLERR,
        "Illegal {} command: expected 'sph/set <group> materials|temperature|hydrostatic ...'",
        cmd);
  const int igroup = group->find(arg[0]);
  if (igroup < 0) error->all(FLERR, "Illegal {} command: no group {}", cmd, arg[0]);
  groupbit = group->bitmask[igroup];
  group_name = arg[0];
  if (group->count(igroup) == 0)
    error->all(FLERR, "Illegal {} command: group {} has no atoms", cmd, group_name);
  materials = FixSPHMaterials::find(lmp, "sph/set command");

  bool set_mat = false, set_temp = false, set_hydro = false, move = true;
  double volume = 0.0, level = 0.0;
  std::string temperature;
  auto once = [&](bool &given, const std::string &keyword) {
    if (given) error->all(FLERR, "Illegal {} command: keyword '{}' given twice", cmd, keyword);
    given = true;
  };
  int iarg = 1;
  while (iarg < narg) {
    const std::string keyword = arg[iarg];
    if (keyword == "materials") {
      once(set_mat, keyword);
      iarg++;
      if (iarg < narg && (strcmp(arg[iarg], "spacing") == 0 || strcmp(arg[iarg], "volume") == 0)) {
        if (iarg + 1 >= narg)
          error->all(FLERR, "Illegal {} command: missing value after '{}'", cmd, arg[iarg]);
        const double value = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
        if (!(value > 0.0) || !std::isfinite(value))
          error->all(FLERR, "Illegal {} command: {} {} must be > 0", cmd, arg[iarg], arg[iarg + 1]);
        volume = (strcmp(arg[iarg], "spacing") == 0) ? pow(value, domain->dimension) : value;
        iarg += 2;
      }
    } else if (keyword == "temperature") {
      once(set_temp, keyword);
      if (iarg + 1 >= narg)
        error->all(FLERR, "Illegal {} command: missing value after 'temperature'", cmd);
      temperature = arg[iarg + 1];
      iarg += 2;
    } else if (keyword == "hydrostatic") {
      once(set_hydro, keyword);
      if (iarg + 1 >= narg)
        error->all(FLERR,
                   "Illegal {} command: missing level after 'hydrostatic' (the height of the "
                   "free surface, along -g)",
                   cmd);
      level = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      iarg += 2;
      if (iarg < narg && strcmp(arg[iarg], "move") == 0) {
        if (iarg + 1 >= narg)
          error->all(FLERR, "Illegal {} command: missing value after 'move'", cmd);
        move = SPHCompat::yes_no(error, FLERR, cmd, "move", arg[iarg + 1]);
        iarg += 2;
      }
    } else
      error->all(FLERR,
                 "Illegal {} command: unknown keyword '{}' (materials, temperature or hydrostatic)",
                 cmd, keyword);
  }
  if (set_mat) set_materials(volume);
  if (set_temp) set_temperature(temperature);
  if (set_hydro) set_hydrostatic(level, move);
}

/* ----------------------------------------------------------------------
   present[t] = 1 when an atom of type t is in the group (collective);
   returns the number of such types
------------------------------------------------------------------------- */

int SPHSet::types_in_group(int *present)
{
  const std::vector<int> types = SPHCheck::group_types(lmp, groupbit);
  int n = 0;
  for (int t = 0; t <= atom->ntypes; t++) {
    present[t] = types[t];
    if (t > 0) n += types[t];
  }
  return n;
}

/* ----------------------------------------------------------------------
   rho = rho0 and cv of each atom's type; with a volume, the mass of every
   type in the group (or of each atom, with per-atom masses) = rho0 volume
------------------------------------------------------------------------- */

void SPHSet::set_materials(double volume)
{
  const int ntypes = atom->ntypes;
  std::vector<int> present(ntypes + 1, 0);
  types_in_group(present.data());
  for (int t = 1; t <= ntypes; t++)
    if (present[t] && !(materials->rho0(t) > 0.0))
      error->all(FLERR, "{} materials: atom type {} (in group {}) has no rho0 in fix sph/materials",
                 cmd, t, group_name);

  const int *const type = atom->type;
  const int *const mask = atom->mask;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    const int t = type[i];
    atom->rho[i] = materials->rho0(t);
    if (materials->cv(t) > 0.0) atom->cv[i] = materials->cv(t);
    if (volume > 0.0 && atom->rmass_flag) atom->rmass[i] = materials->rho0(t) * volume;
    // MACHDYN's particle volume (atom_style hybrid sph smd)
    if (volume > 0.0 && atom->vfrac_flag) atom->vfrac[i] = volume;
  }
  if (volume > 0.0 && !atom->rmass_flag)
    for (int t = 1; t <= ntypes; t++)
      if (present[t]) atom->set_mass(FLERR, t, materials->rho0(t) * volume);

  if (comm->me == 0)
    for (int t = 1; t <= ntypes; t++) {
      if (!present[t]) continue;
      std::string line = fmt::format("{} materials: group {}, type {}: rho {}", cmd, group_name, t,
                                     materials->rho0(t));
      line += (materials->cv(t) > 0.0) ? fmt::format(", cv {}", materials->cv(t))
                                       : std::string(", cv unchanged (no cv in fix sph/materials)");
      if (volume > 0.0)
        line += fmt::format(", mass {}{}", materials->rho0(t) * volume,
                            atom->rmass_flag ? " per atom" : " (of every atom of the type)");
      utils::logmesg(lmp, line + "\n");
    }
}

/* ----------------------------------------------------------------------
   per type: 1 for a MACHDYN solid (a type of pair smd/tlsph) in the group,
   whose cv (the material's) and reference temperature are checked
------------------------------------------------------------------------- */

std::vector<int> SPHSet::machdyn_solid_types()
{
  std::vector<int> solid(atom->ntypes + 1, 0);
  if (!atom->smd_flag) return solid;
  const std::vector<int> tlsph = SPHMachdynSolids::tlsph_types(lmp);
  std::vector<int> present(atom->ntypes + 1, 0);
  types_in_group(present.data());
  for (int t : tlsph) {
    if (!present[t]) continue;
    if (!(materials->cv(t) > 0.0) || !std::isfinite(materials->tref(t)))
      error->all(FLERR,
                 "{} temperature: type {} is a MACHDYN solid (pair smd/tlsph) and needs its cv "
                 "and tref in fix sph/materials",
                 cmd, t);
    solid[t] = 1;
  }
  // the hub checks at each run that no type becomes a MACHDYN solid after
  // its atoms were given the other convention
  for (int t = 1; t <= atom->ntypes; t++)
    if (present[t]) materials->note_energy_convention(t, solid[t]);
  // their cv is the material's (fix sph/materials gives it to them at each run too)
  for (int i = 0; i < atom->nlocal; i++)
    if ((atom->mask[i] & groupbit) && solid[atom->type[i]])
      atom->cv[i] = materials->cv(atom->type[i]);
  return solid;
}

/* ----------------------------------------------------------------------
   esph = cv T of each atom (of a MACHDYN solid: m cv (T - tref)); T a
   number or an equal- or atom-style variable
------------------------------------------------------------------------- */

void SPHSet::set_temperature(const std::string &value)
{
  const int nlocal = atom->nlocal;
  std::vector<double> temperature(nlocal > 0 ? nlocal : 1, 0.0);
  if (utils::strmatch(value, "^v_")) {
    const std::string name = value.substr(2);
    const int ivar = input->variable->find(name.c_str());
    if (ivar < 0)
      error->all(FLERR, "Illegal {} command: temperature {}: no variable {}", cmd, value, name);
    if (input->variable->atomstyle(ivar)) {
      input->variable->compute_atom(ivar, group->find(group_name), temperature.data(), 1, 0);
    } else if (input->variable->equalstyle(ivar)) {
      const double t = input->variable->compute_equal(ivar);
      for (auto &ti : temperature) ti = t;
    } else
      error->all(FLERR,
                 "Illegal {} command: temperature {}: variable {} is neither equal- nor "
                 "atom-style",
                 cmd, value, name);
  } else {
    const double t = utils::numeric(FLERR, value.c_str(), false, lmp);
    for (auto &ti : temperature) ti = t;
  }

  // every atom is checked before any is changed; the lowest bad ID is named
  const int *const mask = atom->mask;
  SPHCheck::FirstBad bad;    // 1 T / 2 cv, its value
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    int kind = 0;
    double what = 0.0;
    if (!std::isfinite(temperature[i]))
      kind = 1, what = temperature[i];
    else if (!(std::isfinite(atom->cv[i]) && atom->cv[i] > 0.0))
      kind = 2, what = atom->cv[i];
    if (kind) bad.consider(atom->tag[i], kind, what);
  }
  if (bad.agree(lmp)) {
    if (bad.info[0] == 1.0)
      error->all(FLERR, "{} temperature {}: atom {} gets T = {}; it must be finite", cmd, value,
                 bad.tag, bad.info[1]);
    error->all(FLERR,
               "{} temperature {}: atom {} has cv = {}; e = cv T needs cv > 0 (set it first: "
               "sph/set materials, or set sph/cv)",
               cmd, value, bad.tag, bad.info[1]);
  }

  // LAMMPS creates every atom with cv = 1: a type whose material has no cv
  // and whose atoms all still have that value was probably never given one
  const int ntypes = atom->ntypes;
  std::vector<int> unset(ntypes + 1, 0), unset_all(ntypes + 1, 0), present(ntypes + 1, 0);
  for (int t = 1; t <= ntypes; t++) unset[t] = (materials->cv(t) > 0.0) ? 0 : 1;
  for (int i = 0; i < nlocal; i++)
    if ((mask[i] & groupbit) && atom->cv[i] != 1.0) unset[atom->type[i]] = 0;
  MPI_Allreduce(unset.data(), unset_all.data(), ntypes + 1, MPI_INT, MPI_MIN, world);
  types_in_group(present.data());
  for (int t = 1; t <= ntypes; t++)
    if (present[t] && unset_all[t] && comm->me == 0)
      error->warning(FLERR,
                     "{} temperature {}: the atoms of type {} have cv = 1, atom style sph's "
                     "default, and fix sph/materials gives their type no cv: e = cv T uses "
                     "cv = 1 (give cv in fix sph/materials, or set sph/cv, if that is not meant)",
                     cmd, value, t);

  // the MACHDYN solids hold their energy as MACHDYN does (sph_particle.h)
  const std::vector<int> solid = machdyn_solid_types();
  const SPHParticles particles(atom);
  double range[2] = {-INFINITY, -INFINITY};    // -(lowest T), highest T
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    const int t = atom->type[i];
    // (a melting type's enthalpy by its law of fix sph/phase, sph_particle.h)
    atom->esph[i] = solid[t] ? SPHParticles::machdyn_energy(particles.mass(i), atom->cv[i],
                                                            temperature[i], materials->tref(t))
                             : particles.energy_at(i, temperature[i]);
    range[0] = fmax(range[0], -temperature[i]);
    range[1] = fmax(range[1], temperature[i]);
  }
  double range_all[2];
  MPI_Allreduce(range, range_all, 2, MPI_DOUBLE, MPI_MAX, world);
  if (comm->me == 0)
    utils::logmesg(lmp, "{} temperature: group {}: T from {} to {} (e = cv T)\n", cmd, group_name,
                   -range_all[0], range_all[1]);
}

/* ----------------------------------------------------------------------
   a fluid at rest under the run's body force (fix gravity), as a
   Lagrangian column (sphe_hydrostatic): the atom at depth d0 below 'level'
   (a height along -g) gets the density of the EOS of its type at the
   pressure P_b + rho0 g d0; with 'move', every atom moves along g to its
   compressed depth, the deepest atom of the group staying in place
------------------------------------------------------------------------- */

void SPHSet::set_hydrostatic(double level, bool move)
{
  const double *gvec = SPHBodyForce::require(lmp, "sph/set hydrostatic", "the weight of the fluid");
  const double g = sqrt(gvec[0] * gvec[0] + gvec[1] * gvec[1] + gvec[2] * gvec[2]);
  if (!(g > 0.0))
    error->all(FLERR, "{} hydrostatic: the body force of fix gravity is zero: no hydrostatic state",
               cmd);
  const double up[3] = {-gvec[0] / g + 0.0, -gvec[1] / g + 0.0, -gvec[2] / g + 0.0};

  // the fluid of the group: its types with an equation of state; solids (no
  // equation of state, e.g. the walls and blocks of fix sph/wall/adami) keep
  // their density and place
  const int ntypes = atom->ntypes;
  std::vector<int> present(ntypes + 1, 0);
  types_in_group(present.data());
  int fluid_types = 0, solid_types = 0;
  for (int t = 1; t <= ntypes; t++)
    if (present[t]) (materials->eos(t) ? fluid_types : solid_types)++;
  if (!fluid_types)
    error->all(FLERR,
               "{} hydrostatic: no atom type of group {} has an equation of state in fix "
               "sph/materials: no fluid to set",
               cmd, group_name);
  // an 'auto' speed of sound is needed now: from this column's head
  SPHSoundSpeed::derive(lmp, materials, "sph/set hydrostatic", groupbit, level);

  double **x = atom->x;
  const int *const mask = atom->mask;
  const int nlocal = atom->nlocal;
  std::vector<double> compression(nlocal > 0 ? nlocal : 1, 0.0);
  double local[2] = {0.0, 0.0};    // largest density ratio, largest compression
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    const sphe_eos *eos = materials->eos(atom->type[i]);
    if (!eos) continue;
    const double d0 = level - (up[0] * x[i][0] + up[1] * x[i][1] + up[2] * x[i][2]);
    double rho, d;
    sphe_hydrostatic(eos, g, d0, &rho, &d);
    atom->rho[i] = rho;
    compression[i] = d0 - d;
    local[0] = fmax(local[0], rho / eos->rho0);
    local[1] = fmax(local[1], compression[i]);
  }
  double largest[2];
  MPI_Allreduce(local, largest, 2, MPI_DOUBLE, MPI_MAX, world);

  if (move && largest[1] > 0.0) {
    imageint *image = atom->image;
    for (int i = 0; i < nlocal; i++) {
      if (!(mask[i] & groupbit) || !materials->eos(atom->type[i])) continue;
      const double shift = compression[i] - largest[1];    // <= 0: down, along g
      for (int k = 0; k < 3; k++) x[i][k] += shift * up[k];
      domain->remap(x[i], image[i]);
    }
    // as displace_atoms does: atoms may change their sub-domain
    if (domain->triclinic) domain->x2lamda(atom->nlocal);
    domain->reset_box();
    Irregular *irregular = new Irregular(lmp);
    irregular->migrate_atoms(1);
    delete irregular;
    if (domain->triclinic) domain->lamda2x(atom->nlocal);
  }
  if (comm->me == 0)
    utils::logmesg(lmp,
                   "{} hydrostatic: group {}: surface at height {} along ({} {} {}), g = {}; "
                   "density up to {} rho0{}{}\n",
                   cmd, group_name, level, up[0], up[1], up[2], g, largest[0],
                   move ? fmt::format(", atoms moved down by up to {}", largest[1])
                        : std::string(", atoms not moved"),
                   solid_types ? fmt::format("; {} solid type(s) (no equation of state) left as "
                                             "they are",
                                             solid_types)
                               : std::string());
}
