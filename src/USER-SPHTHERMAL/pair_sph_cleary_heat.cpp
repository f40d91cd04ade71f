/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   pair sph/cleary/heat: SPH heat conduction of Cleary 1998 (eq 6), with a
   harmonic-mean (or arithmetic-mean) conductivity from fix sph/materials.
------------------------------------------------------------------------- */

#include "pair_sph_cleary_heat.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_sph_materials.h"
#include "fix_sph_wall_dirichlet.h"
#include "force.h"
#include "math_extra.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "pair_sph_harmonic_visc.h"
#include "sph_checks.h"
#include "sph_compat.h"
#include "sph_conduction.h"
#include "sph_consistent.h"
#include "sph_dispatch.h"
#include "sph_hub.h"
#include "sph_particle.h"
#include "sph_scene_defaults.h"
#include "sph_support.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

// the layout of the restart settings: raise it when a setting is added
static constexpr int RESTART_VERSION = 3;

/* ---------------------------------------------------------------------- */

PairSPHClearyHeat::PairSPHClearyHeat(LAMMPS *lmp) :
    PairSPHKernel(lmp, "sph/cleary/heat", "conductivities come from fix sph/materials"),
    mean(SPHC_HARMONIC), loop_own(0), in_flow_loop(0), temperature(nullptr), mass_of(nullptr),
    volume(nullptr), conductivity(nullptr), eta2(0.0), materials(nullptr), conductivity_varies(0),
    conductance(nullptr), loop_conductance(nullptr), relax_wanted(0), relax_rate(nullptr),
    nmax_relax(0), eta_request(-1.0), eta_logged(-1), correct_request(-1),
    correct(SPHConductionWeights::NONE), correct_logged(-1), sweeps(5), warm_sweeps(1),
    weights(nullptr), interface_types(nullptr), type_conductivity(nullptr), interface(nullptr),
    nmax_pairs(0), pairs_x(nullptr), pairs_rho(nullptr), pairs_valid(0), refresh_pairs(0)
{
  // S and the state of the correction; the interface's estimate; nu of 'correction second'
  comm_forward = SPHS_MAX;
  // the moments of the correction and the interface; relax_rate (init_style()
  // makes room for the Hessian blocks of 'correction second')
  comm_reverse = COMM_REVERSE_MOMENTS;
}

/* ---------------------------------------------------------------------- */

PairSPHClearyHeat::~PairSPHClearyHeat()
{
  memory->destroy(conductance);
  memory->destroy(loop_conductance);
  memory->destroy(relax_rate);
  memory->destroy(pairs_x);
  memory->destroy(pairs_rho);
  memory->destroy(interface_types);
  memory->destroy(type_conductivity);
  delete weights;
  delete interface;
}

/* ---------------------------------------------------------------------- */

void PairSPHClearyHeat::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  // pair sph/harmonic/visc evaluates the term (begin_flow_loop_term)
  if (in_flow_loop) return;
  begin_compute();
  eval_pairs(0, list->inum, atom->desph, relax_wanted ? relax_rate : nullptr);
  end_compute();
}

/* ----------------------------------------------------------------------
   before the pair loop: the per-atom state it reads, the correction's and
   the interface's factors when the particles have moved, relax_rate zeroed
------------------------------------------------------------------------- */

void PairSPHClearyHeat::begin_compute()
{
  SPHCheck::particles(lmp, FLERR, "Pair style sph/cleary/heat", SPHCheck::RHO | SPHCheck::ESPH);
  fill_atom_state(false);
  if (update->setupflag) check_neighbours();
  refresh_pairs = (weights || interface) && !pairs_current();
  if (relax_wanted) zero_relax_rate();
  if (refresh_pairs) refresh_support();
  begin_solid_rates();
}

/* ----------------------------------------------------------------------
   relax_rate of every owned and ghost atom zeroed, room for one copy per
   thread (the /omp styles)
------------------------------------------------------------------------- */

void PairSPHClearyHeat::zero_relax_rate()
{
  const int nall = atom->nlocal + atom->nghost;
  if (atom->nmax * comm->nthreads > nmax_relax) {
    nmax_relax = atom->nmax * comm->nthreads;
    memory->destroy(relax_rate);
    memory->create(relax_rate, nmax_relax, "pair:relax_rate");
  }
  for (int i = 0; i < nall; i++) relax_rate[i] = 0.0;
}

/* ----------------------------------------------------------------------
   the pair loop over ilist[ifrom..ito), adding to desph (and relax_rate)
------------------------------------------------------------------------- */

struct PairSPHClearyHeat::EvalCall {
  PairSPHClearyHeat *pair;
  int ifrom, ito;
  double *desph, *relax;
  template <int KERNEL, int MEAN, int CORRECT, int VARYING_K, int NEWTON_PAIR, int RMASS, int RELAX>
  void run()
  {
    pair->eval<KERNEL, MEAN, CORRECT, VARYING_K, NEWTON_PAIR, RMASS, RELAX>(ifrom, ito, desph,
                                                                            relax);
  }
};

void PairSPHClearyHeat::eval_pairs(int ifrom, int ito, double *desph, double *relax)
{
  EvalCall call = {this, ifrom, ito, desph, relax};
  const int settings[] = {kernel_kind,
                          mean,
                          weights ? 1 : 0,
                          conductivity_varies ? 1 : 0,
                          force->newton_pair ? 1 : 0,
                          (atom->rmass_flag && atom->rmass) ? 1 : 0,
                          relax_wanted ? 1 : 0};
  SPHDispatch<SPHKernelKinds, SPHValues<SPHC_ARITHMETIC, SPHC_INTERFACE, SPHC_HARMONIC>, SPHFlag,
              SPHFlag, SPHFlag, SPHFlag, SPHFlag>::to(call, settings);
}

/* ----------------------------------------------------------------------
   after the pair loop (the rates summed)
------------------------------------------------------------------------- */

void PairSPHClearyHeat::end_compute()
{
  end_solid_rates();
  check_rates(atom->desph, "desph");
  if (refresh_pairs && update->setupflag) report_setup();
  if (!flows.empty()) tally_flows();
  if (relax_wanted) finish_relax();
}

/* ----------------------------------------------------------------------
   the rates of the MACHDYN solid atoms: the loop's per unit mass, esph's
   per particle (sph_particle.h)
------------------------------------------------------------------------- */

void PairSPHClearyHeat::begin_solid_rates()
{
  solid_desph_before.clear();
  if (!materials->machdyn().any()) return;
  const int nlocal = atom->nlocal;
  solid_desph_before.assign(atom->desph, atom->desph + nlocal);
}

void PairSPHClearyHeat::end_solid_rates()
{
  if (solid_desph_before.empty()) return;
  const SPHParticles particles(atom);
  double *const desph = atom->desph;
  for (int i = 0; i < atom->nlocal; i++)
    if (particles.machdyn(i)) {
      const double rate = particles.esph_per_specific(i) * (desph[i] - solid_desph_before[i]);
      desph[i] = solid_desph_before[i] + rate;
      // (the rest of desph is pair smd/tlsph's work, made heat by the hub)
      materials->note_solid_heat(i, rate);
    }
}

/* ----------------------------------------------------------------------
   lambda_i of the ghosts to their owners, divided by cv
------------------------------------------------------------------------- */

void PairSPHClearyHeat::finish_relax()
{
  if (force->newton_pair) reverse(SPHCommStage().flat(relax_rate, 1));
  // a particle that changes phase relaxes fastest in its phase of smaller cv
  const SPHParticles particles(atom);
  for (int i = 0; i < atom->nlocal; i++) relax_rate[i] /= particles.smallest_cv(i);
}

/* ----------------------------------------------------------------------
   de_i/dt += m_j F_ij and de_j/dt -= m_i F_ij for every pair within the
   kernel support (sph_conduction.h); T = esph / cv
------------------------------------------------------------------------- */

template <int KERNEL, int MEAN, int CORRECT, int VARYING_K, int NEWTON_PAIR, int RMASS, int RELAX>
void PairSPHClearyHeat::eval(int ifrom, int ito, double *desph, double *relax_rate)
{
  const double *const *const x = atom->x;
  const double *const temperature = this->temperature;
  const double *const conductivity = this->conductivity;
  const double *const iface_distance = (MEAN == SPHC_INTERFACE) ? interface->distances() : nullptr;
  const double *const rho = atom->rho;
  // the mass by type: one array fewer to stream than a per-atom copy
  const double *const mass = atom->mass;
  const double *const rmass = atom->rmass;
  const int *const type = atom->type;
  const int nlocal = atom->nlocal;

  const double cutsq_kernel = cut_global * cut_global;
  const double inv_h = kernel.inv_h;
  const double dw_scale = kernel.dw_scale;

  const int *const ilist = list->ilist;
  const int *const numneigh = list->numneigh;
  int **const firstneigh = list->firstneigh;
  // the factors of the pairs within the support, stored with the list
  const int *const first_pair = support_pairs.first.data();
  const int *const stop_pair = support_pairs.stop.data();
  const double *const pair_weights = support_pairs.weight.data();
  const int *const pair_j = support_pairs.j.data();
  const double *const pair_distance = support_pairs.distance.data();
  const double *const pair_dwdr = support_pairs.dwdr.data();
  // the entries of each list inside the support (sph_support.h)
  SPHSupport support;

  for (int ii = ifrom; ii < ito; ii++) {
    const int i = ilist[ii];
    const int itype = type[i];
    const double temp_i = temperature[i];
    const double rho_i = rho[i];
    const double mass_i = RMASS ? rmass[i] : mass[itype];
    // (across an interface of constant conductivities, the per-type ones)
    const double k_i = VARYING_K   ? conductivity[i]
        : (MEAN == SPHC_INTERFACE) ? type_conductivity[itype]
                                   : 0.0;
    const double distance_i = (MEAN == SPHC_INTERFACE) ? iface_distance[i] : 0.0;
    const int *const interface_i = (MEAN == SPHC_INTERFACE) ? interface_types[itype] : nullptr;
    const double *const conductance_i = conductance[itype];
    const int *const jlist = firstneigh[i];
    const int jnum = numneigh[i];
    const double *const weight_in = CORRECT ? pair_weights + first_pair[ii] : nullptr;
    double desph_i = 0.0, relax_i = 0.0;

    // CORRECT: the pairs stored for this step's positions (refresh_support)
    // with their distances and kernel derivatives, read in place; else the
    // entries of the list inside the support, with 3-D distances as the loop
    // always took them (z = 0 in 2-D)
    const int from = CORRECT ? first_pair[ii] : 0;
    const double *const distance_in = CORRECT ? pair_distance + from : nullptr;
    const double *const dwdr_in = CORRECT ? pair_dwdr + from : nullptr;
    int nin;
    const int *jin;
    if (CORRECT) {
      nin = stop_pair[ii] - from;
      jin = pair_j + from;
    } else {
      nin = support.gather<3, false>(x[i], x, jlist, jnum, cutsq_kernel);
      jin = support.index;
      for (int k = 0; k < nin; k++) {
        const double r = sqrt(support.rsq[k]);
        support.a[k] = r * dw_scale * sphk_df(KERNEL, r * inv_h);
      }
    }

    for (int k = 0; k < nin; k++) {
      const int j = jin[k];
      const double rsq = CORRECT ? distance_in[k] * distance_in[k] : support.rsq[k];
      const int jtype = type[j];
      const double r_dwdr = CORRECT ? distance_in[k] * dwdr_in[k] : support.a[k];
      const double k_j = VARYING_K   ? conductivity[j]
          : (MEAN == SPHC_INTERFACE) ? type_conductivity[jtype]
                                     : 0.0;
      const double conductance_ij = sphc_pair_conductance(
          MEAN, VARYING_K, (MEAN == SPHC_INTERFACE) && interface_i[jtype], k_i, k_j,
          VARYING_K ? 0.0 : conductance_i[jtype], (MEAN == SPHC_INTERFACE) ? distance_i : 0.0,
          (MEAN == SPHC_INTERFACE) ? iface_distance[j] : 0.0);
      const double temp_ij = temp_i - temperature[j];
      const double mass_j = RMASS ? rmass[j] : mass[jtype];
      // the pairs within the support, in the order they were stored
      const double weight = CORRECT ? weight_in[k] : 1.0;
      // with RELAX, F_ij per unit temperature difference (<= 0, as dW/dr) is
      // needed too: one evaluation serves both
      const double inv_den = 1.0 / sphc_cleary_denominator(rho_i, rho[j], rsq, eta2);
      const double g_ij =
          RELAX ? weight * sphc_cleary_pair_inv(conductance_ij, 1.0, r_dwdr, inv_den) : 0.0;
      const double f_ij = RELAX
          ? g_ij * temp_ij
          : weight * sphc_cleary_pair_inv(conductance_ij, temp_ij, r_dwdr, inv_den);
      desph_i += mass_j * f_ij;
      if (NEWTON_PAIR || j < nlocal) desph[j] -= mass_i * f_ij;
      if (RELAX) {
        relax_i -= mass_j * g_ij;
        if (NEWTON_PAIR || j < nlocal) relax_rate[j] -= mass_i * g_ij;
      }
    }
    desph[i] += desph_i;
    if (RELAX) relax_rate[i] += relax_i;
  }
}

/* ---------------------------------------------------------------------- */

void PairSPHClearyHeat::allocate()
{
  PairSPHKernel::allocate();
  const int n = atom->ntypes;
  memory->create(conductance, n + 1, n + 1, "pair:conductance");
  memory->create(loop_conductance, n + 1, n + 1, "pair:loop_conductance");
  memory->create(interface_types, n + 1, n + 1, "pair:interface_types");
  memory->create(type_conductivity, n + 1, "pair:type_conductivity");
  for (int i = 0; i <= n; i++) {
    type_conductivity[i] = 0.0;
    for (int j = 0; j <= n; j++) {
      conductance[i][j] = 0.0;
      interface_types[i][j] = 0;
    }
  }
}

/* ----------------------------------------------------------------------
   pair_style sph/cleary/heat kernel cutoff [mean harmonic|arithmetic|interface] [distance d_name] [eta f]
     [correction none|consistent|second] [sweeps n] [warm m|hold] [loop shared|own]
------------------------------------------------------------------------- */

void PairSPHClearyHeat::settings(int narg, char **arg)
{
  int iarg = parse_kernel(narg, arg);
  eta_factor = 0.1;
  eta_request = -1.0;
  mean = SPHC_HARMONIC;
  correct_request = -1;
  sweeps = 5;
  warm_sweeps = 1;
  distance_name.clear();
  loop_own = 0;
  while (iarg < narg) {
    if (strcmp(arg[iarg], "eta") != 0 && strcmp(arg[iarg], "mean") != 0 &&
        strcmp(arg[iarg], "correction") != 0 && strcmp(arg[iarg], "sweeps") != 0 &&
        strcmp(arg[iarg], "warm") != 0 && strcmp(arg[iarg], "loop") != 0 &&
        strcmp(arg[iarg], "distance") != 0)
      error->all(FLERR,
                 "Illegal pair_style sph/cleary/heat command: unknown keyword '{}' (after the "
                 "kernel and cutoff: eta, mean, distance, correction, sweeps, warm or loop)",
                 arg[iarg]);
    if (iarg + 1 >= narg)
      error->all(FLERR, "Illegal pair_style sph/cleary/heat command: missing value after '{}'",
                 arg[iarg]);
    if (strcmp(arg[iarg], "eta") == 0) {
      eta_request = eta_factor = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (eta_factor < 0.0)
        error->all(FLERR, "Illegal pair_style sph/cleary/heat command: eta {} must be >= 0",
                   arg[iarg + 1]);
      // eta = f h in r^2 + eta^2: a pair at r = h conducts 1 / (1 + f^2) of its heat
      if (eta_factor > 1.0)
        error->all(FLERR,
                   "Illegal pair_style sph/cleary/heat command: eta {} must be <= 1 (a fraction "
                   "of h: eta 1 already halves the conduction at r = h; Cleary's 0.1 is the "
                   "default)",
                   arg[iarg + 1]);
      if (eta_factor > 0.3 && comm->me == 0)
        error->warning(FLERR,
                       "Pair style sph/cleary/heat: eta {} lowers the conduction of a pair at "
                       "r = h by {:.0f} %, and the conductance of the particles by about as "
                       "much (eta is a fraction of h; the default 0.1 lowers it by 1 %)",
                       arg[iarg + 1], 100.0 * (1.0 - 1.0 / (1.0 + eta_factor * eta_factor)));
    } else if (strcmp(arg[iarg], "correction") == 0) {
      if (strcmp(arg[iarg + 1], "none") == 0)
        correct_request = SPHConductionWeights::NONE;
      else if (strcmp(arg[iarg + 1], "consistent") == 0)
        correct_request = SPHConductionWeights::CONSISTENT;
      else if (strcmp(arg[iarg + 1], "second") == 0)
        correct_request = SPHConductionWeights::SECOND;
      else
        error->all(FLERR,
                   "Illegal pair_style sph/cleary/heat command: unknown correction '{}' "
                   "(none, consistent or second)",
                   arg[iarg + 1]);
    } else if (strcmp(arg[iarg], "loop") == 0) {
      if (strcmp(arg[iarg + 1], "shared") == 0)
        loop_own = 0;
      else if (strcmp(arg[iarg + 1], "own") == 0)
        loop_own = 1;
      else
        error->all(FLERR,
                   "Illegal pair_style sph/cleary/heat command: unknown loop '{}' (shared or own)",
                   arg[iarg + 1]);
    } else if (strcmp(arg[iarg], "distance") == 0) {
      if (strncmp(arg[iarg + 1], "d_", 2) != 0 || !arg[iarg + 1][2])
        error->all(FLERR,
                   "Illegal pair_style sph/cleary/heat command: distance '{}' is not a d_name "
                   "of fix property/atom",
                   arg[iarg + 1]);
      distance_name = arg[iarg + 1];
    } else if (strcmp(arg[iarg], "sweeps") == 0) {
      sweeps = utils::inumeric(FLERR, arg[iarg + 1], false, lmp);
      if (sweeps < 1)
        error->all(FLERR, "Illegal pair_style sph/cleary/heat command: sweeps {} must be >= 1",
                   arg[iarg + 1]);
    } else if (strcmp(arg[iarg], "warm") == 0) {
      if (strcmp(arg[iarg + 1], "hold") == 0)
        warm_sweeps = SPHConductionWeights::HOLD;
      else {
        warm_sweeps = utils::inumeric(FLERR, arg[iarg + 1], false, lmp);
        if (warm_sweeps < 0)
          error->all(FLERR,
                     "Illegal pair_style sph/cleary/heat command: warm {} must be >= 0 or 'hold'",
                     arg[iarg + 1]);
      }
    } else if (strcmp(arg[iarg], "mean") == 0) {
      if (strcmp(arg[iarg + 1], "harmonic") == 0)
        mean = SPHC_HARMONIC;
      else if (strcmp(arg[iarg + 1], "arithmetic") == 0)
        mean = SPHC_ARITHMETIC;
      else if (strcmp(arg[iarg + 1], "interface") == 0)
        mean = SPHC_INTERFACE;
      else
        error->all(FLERR,
                   "Illegal pair_style sph/cleary/heat command: unknown mean '{}' "
                   "(harmonic, arithmetic or interface)",
                   arg[iarg + 1]);
    }
    iarg += 2;
  }
  if (!distance_name.empty() && mean != SPHC_INTERFACE)
    error->all(FLERR,
               "Illegal pair_style sph/cleary/heat command: distance {} needs mean interface",
               distance_name);
}

/* ---------------------------------------------------------------------- */

void PairSPHClearyHeat::init_style()
{
  if (!atom->esph_flag || !atom->cv_flag || !atom->rho_flag)
    error->all(FLERR, "Pair style sph/cleary/heat requires atom style sph (esph, desph, cv, rho){}",
               atom->smd_flag ? "; with MACHDYN's solids, atom_style hybrid sph smd" : "");

  materials = FixSPHMaterials::find(lmp, "Pair style sph/cleary/heat");
  flows.clear();    // the fixes that want them ask again at their init
  for (int i = 1; i <= atom->ntypes; i++)
    if (!materials->conductivity(i))
      error->all(FLERR,
                 "Pair style sph/cleary/heat: atom type {} has no conductivity in fix "
                 "sph/materials",
                 i);
  conductivity_varies = !materials->conductivity_constant();
  // the type pairs that cross an interface: two conductivity laws
  for (int i = 1; i <= atom->ntypes; i++) {
    type_conductivity[i] = conductivity_varies ? 0.0 : materials->conductivity(i)->c[0];
    for (int j = 1; j <= atom->ntypes; j++)
      interface_types[i][j] =
          !sphm_law_same(materials->conductivity(i), materials->conductivity(j));
  }
  delete interface;
  interface = nullptr;
  if (mean == SPHC_INTERFACE) {
    interface = new SPHInterfaceDistance(lmp, distance_name);
    interface->init(interface_types);
  }
  int interfaces = 0;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = 1; j <= atom->ntypes; j++) interfaces |= interface_types[i][j];
  if (mean == SPHC_INTERFACE && !interfaces && comm->me == 0)
    error->warning(FLERR,
                   "Pair style sph/cleary/heat: mean interface has no effect: every atom type has "
                   "the same conductivity law in fix sph/materials");
  // without 'correction' in the command, the scene's default
  if (correct_request < 0) {
    const SPHSceneDefaults::Choice choice = SPHSceneDefaults::heat_correction(lmp);
    correct = choice.value;
    SPHSceneDefaults::log(lmp, "Pair style sph/cleary/heat", "correction",
                          correct == SPHConductionWeights::CONSISTENT ? "consistent" : "none",
                          choice, correct_logged);
  } else
    correct = correct_request;
  if (eta_request < 0.0) {
    const SPHSceneDefaults::Choice choice = SPHSceneDefaults::heat_eta(lmp);
    eta_factor = choice.number;
    SPHSceneDefaults::log(lmp, "Pair style sph/cleary/heat", "eta",
                          fmt::format("{:g}", eta_factor).c_str(), choice, eta_logged);
  } else
    eta_factor = eta_request;
  // the Hessian blocks of 'correction second' are the largest reverse
  // communication; Comm sizes its buffers after this (LAMMPS::init)
  comm_reverse = (correct == SPHConductionWeights::SECOND) ? SPHS_MAX * SPHS_MAX
                                                           : COMM_REVERSE_MOMENTS;
  relax_wanted = 0;    // set again by the styles that want it, at their init
  pairs_valid = 0;     // the correction's factors are made anew at the first step
  SPHCheck::atom_state(lmp, FLERR, "Pair style sph/cleary/heat", 0,
                       SPHCheck::RHO | SPHCheck::CV | SPHCheck::ESPH);

  eta2 = init_kernel();
  // (the per-atom states exist from here on, for compute sph/correction/atom)
  delete weights;
  weights = SPHConductionWeights::create(lmp, correct, kernel.inv_h, sweeps, warm_sweeps);
  for (int i = 0; i <= atom->ntypes; i++)
    for (int j = 0; j <= atom->ntypes; j++) loop_conductance[i][j] = 0.0;
  const int was_in_flow_loop = in_flow_loop;
  in_flow_loop = flow_loop_possible();
  if (in_flow_loop && !was_in_flow_loop && comm->me == 0)
    utils::logmesg(lmp,
                   "Pair style sph/cleary/heat: the term is evaluated in the pair loop of "
                   "sph/harmonic/visc (loop shared)\n");

  SPHCompat::request_half_list(neighbor, this, instance_me);
}

/* ---------------------------------------------------------------------- */

double PairSPHClearyHeat::init_one(int i, int j)
{
  // with constant conductivities the conductance is a property of the type
  // pair; the flow pair's loop sees it on this style's type pairs only (the
  // others keep the 0 of init_style)
  if (!conductivity_varies)
    conductance[i][j] = conductance[j][i] = loop_conductance[i][j] = loop_conductance[j][i] =
        sphc_conductance(mean, materials->conductivity(i)->c[0], materials->conductivity(j)->c[0]);
  return cut_global;
}

/* ---------------------------------------------------------------------- */

void PairSPHClearyHeat::write_restart_settings(FILE *fp)
{
  SPHCheck::write_restart_head(fp, RESTART_VERSION);
  fwrite(&kernel_kind, sizeof(int), 1, fp);
  fwrite(&mean, sizeof(int), 1, fp);
  fwrite(&cut_global, sizeof(double), 1, fp);
  fwrite(&eta_request, sizeof(double), 1, fp);
  fwrite(&correct_request, sizeof(int), 1, fp);
  fwrite(&sweeps, sizeof(int), 1, fp);
  fwrite(&warm_sweeps, sizeof(int), 1, fp);
  fwrite(&loop_own, sizeof(int), 1, fp);
  const int length = (int) distance_name.size();
  fwrite(&length, sizeof(int), 1, fp);
  fwrite(distance_name.data(), sizeof(char), length, fp);
}

void PairSPHClearyHeat::read_restart_settings(FILE *fp)
{
  SPHCheck::read_restart_head(lmp, FLERR, fp, "pair sph/cleary/heat", RESTART_VERSION);
  int length = 0;
  if (comm->me == 0) {
    utils::sfread(FLERR, &kernel_kind, sizeof(int), 1, fp, nullptr, error);
    utils::sfread(FLERR, &mean, sizeof(int), 1, fp, nullptr, error);
    utils::sfread(FLERR, &cut_global, sizeof(double), 1, fp, nullptr, error);
    utils::sfread(FLERR, &eta_request, sizeof(double), 1, fp, nullptr, error);
    utils::sfread(FLERR, &correct_request, sizeof(int), 1, fp, nullptr, error);
    utils::sfread(FLERR, &sweeps, sizeof(int), 1, fp, nullptr, error);
    utils::sfread(FLERR, &warm_sweeps, sizeof(int), 1, fp, nullptr, error);
    utils::sfread(FLERR, &loop_own, sizeof(int), 1, fp, nullptr, error);
    utils::sfread(FLERR, &length, sizeof(int), 1, fp, nullptr, error);
  }
  MPI_Bcast(&length, 1, MPI_INT, 0, world);
  std::vector<char> name(length + 1, '\0');
  if (comm->me == 0) utils::sfread(FLERR, name.data(), sizeof(char), length, fp, nullptr, error);
  MPI_Bcast(name.data(), length, MPI_CHAR, 0, world);
  distance_name = name.data();
  MPI_Bcast(&kernel_kind, 1, MPI_INT, 0, world);
  MPI_Bcast(&mean, 1, MPI_INT, 0, world);
  MPI_Bcast(&cut_global, 1, MPI_DOUBLE, 0, world);
  MPI_Bcast(&eta_request, 1, MPI_DOUBLE, 0, world);
  MPI_Bcast(&correct_request, 1, MPI_INT, 0, world);
  MPI_Bcast(&sweeps, 1, MPI_INT, 0, world);
  MPI_Bcast(&warm_sweeps, 1, MPI_INT, 0, world);
  MPI_Bcast(&loop_own, 1, MPI_INT, 0, world);
}

/* ---------------------------------------------------------------------- */

double PairSPHClearyHeat::memory_usage()
{
  return Pair::memory_usage() + (double) (nmax_relax + 4 * nmax_pairs) * sizeof(double) +
      support_pairs.memory_usage() + (weights ? weights->memory_usage() : 0.0) +
      (interface ? interface->memory_usage() : 0.0);
}

/* ----------------------------------------------------------------------
   beyond the state every SPH pair reads: the conductivity of atom i
------------------------------------------------------------------------- */

std::string PairSPHClearyHeat::diagnose(int i)
{
  std::string why = PairSPHKernel::diagnose(i);
  if (why.empty() && conductivity && !std::isfinite(conductivity[i]))
    why = fmt::format("its conductivity is {}", conductivity[i]);
  return why;
}
