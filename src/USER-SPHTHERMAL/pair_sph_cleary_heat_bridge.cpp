/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   pair sph/cleary/heat: the term for other styles: evaluated in the loop of pair
   sph/harmonic/visc, pair by pair (pair_term), the heat flows between
   groups, and the communication of the per-atom state.
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
#include "sph_comm_stage.h"
#include "sph_compat.h"
#include "sph_conduction.h"
#include "sph_consistent.h"
#include "sph_hub.h"
#include "sph_machdyn.h"
#include "sph_particle.h"
#include "sph_support.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
/* ----------------------------------------------------------------------
   the term in pair sph/harmonic/visc's loop: possible when that style is
   the only flow pair and this the only heat pair, both with one kernel and
   cutoff on the same type pairs (so on the same neighbour list), and the
   term needs only the pair: no correction, no interface distances, a mean
   of per-atom conductivities only when harmonic (per type pair otherwise)
------------------------------------------------------------------------- */

int PairSPHClearyHeat::flow_loop_possible()
{
  if (loop_own || correct != SPHConductionWeights::NONE || mean == SPHC_INTERFACE) return 0;
  // the solids' rates are made per particle after this style's own loop
  if (!SPHMachdynSolids::tlsph_types(lmp).empty()) return 0;
  if (conductivity_varies && mean != SPHC_HARMONIC) return 0;
  // (the /omp styles too, named as such in the hybrid)
  SPHHub hub(lmp);
  if (hub.heat() != this) return 0;
  const PairSPHHarmonicVisc *flow = hub.flow();
  if (!flow || !same_kernel(flow)) return 0;
  // the flow's list holds every pair of this style's; on type pairs only
  // the flow covers, a zero conductance (per type pair) keeps the term out
  int same_pairs = 1;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      if (setflag[i][j] && !flow->setflag[i][j]) return 0;
      if (setflag[i][j] != flow->setflag[i][j]) same_pairs = 0;
    }
  return same_pairs || !conductivity_varies;
}

/* ----------------------------------------------------------------------
   this force evaluation's temperature and mass of every owned and ghost
   atom (and conductivity, and zeroed relax_rate) for the flow pair's loop
------------------------------------------------------------------------- */

PairSPHClearyHeat::FlowLoopTerm PairSPHClearyHeat::begin_flow_loop_term()
{
  fill_atom_state(true);
  if (update->setupflag) check_neighbours();
  if (relax_wanted) zero_relax_rate();
  FlowLoopTerm term;
  term.temperature = temperature;
  // the heat style's mass of every atom (the flow's differs for solids)
  term.mass = mass_of;
  term.rho = atom->rho;
  term.conductivity = conductivity;
  term.conductance = loop_conductance;
  term.relax_rate = relax_wanted ? relax_rate : nullptr;
  term.eta2 = eta2;
  return term;
}

/* ----------------------------------------------------------------------
   the per-atom state this style reads, from the store of fix
   sph/materials: filled once per force evaluation for all the styles
------------------------------------------------------------------------- */

void PairSPHClearyHeat::fill_atom_state(bool flow_loop)
{
  SPHAtomState &state = materials->atom_state();
  // the own loop takes the masses by type (or rmass) as it goes; the flow
  // loop and the support's volumes read the per-atom masses
  const int support = (weights || interface) ? SPHAtomState::VOLUME : 0;
  state.fill(SPHAtomState::TEMPERATURE | (flow_loop ? SPHAtomState::MASS : 0) | support |
                 (conductivity_varies ? SPHAtomState::CONDUCTIVITY : 0),
             "Pair style sph/cleary/heat");
  temperature = state.temperature();
  mass_of = (flow_loop || support) ? state.mass() : nullptr;
  volume = support ? state.volume() : nullptr;
  conductivity = conductivity_varies ? state.conductivity() : nullptr;
}

void PairSPHClearyHeat::end_flow_loop_term()
{
  check_rates(atom->desph, "desph");
  if (!flows.empty()) tally_flows();
  if (relax_wanted) finish_relax();
}

/* ----------------------------------------------------------------------
   the heat flows asked for: the pair terms of eval() between atoms of the
   two groups, with the energy each side receives (the j side only where
   eval() gives it to an atom of this rank), summed over the ranks
------------------------------------------------------------------------- */

int PairSPHClearyHeat::request_heat_flow(int to_groupbit, int from_groupbit)
{
  flows.push_back({to_groupbit, from_groupbit, 0.0});
  return (int) flows.size() - 1;
}

double PairSPHClearyHeat::pair_term(int i, int j, double rsq, double temp_ij) const
{
  const double r = sqrt(rsq);
  const double inv_denominator =
      1.0 / sphc_cleary_denominator(atom->rho[i], atom->rho[j], rsq, eta2);
  return pair_weight(i, j, r) *
      sphc_cleary_pair_inv(pair_conductance(i, j), temp_ij, r * kernel_dwdr(r), inv_denominator);
}

double PairSPHClearyHeat::pair_conductance(int i, int j) const
{
  const int *const type = atom->type;
  const double k_i = conductivity_varies ? conductivity[i] : type_conductivity[type[i]];
  const double k_j = conductivity_varies ? conductivity[j] : type_conductivity[type[j]];
  const int crosses = interface && interface_types[type[i]][type[j]];
  const double *const distance = crosses ? interface->distances() : nullptr;
  return sphc_pair_conductance(mean, conductivity_varies, crosses, k_i, k_j,
                               conductance[type[i]][type[j]], crosses ? distance[i] : 0.0,
                               crosses ? distance[j] : 0.0);
}

double PairSPHClearyHeat::pair_weight(int i, int j, double r) const
{
  if (!weights) return 1.0;
  const double *const *const x = atom->x;
  const double r_ij[3] = {x[i][0] - x[j][0], x[i][1] - x[j][1], x[i][2] - x[j][2]};
  return weights->factor(i, j, r_ij, r);
}

void PairSPHClearyHeat::tally_flows()
{
  const SPHParticles particles(atom);
  const double *const *const x = atom->x;
  const int *const mask = atom->mask;
  const int nlocal = atom->nlocal;
  const int newton = force->newton_pair;
  const double cutsq_kernel = cut_global * cut_global;
  int either = 0;
  for (const auto &flow : flows) either |= flow.to | flow.from;

  std::vector<double> local(flows.size(), 0.0);
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    if (!(mask[i] & either)) continue;
    const int *const jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      if (!(mask[j] & either)) continue;
      const double delx = x[i][0] - x[j][0];
      const double dely = x[i][1] - x[j][1];
      const double delz = x[i][2] - x[j][2];
      const double rsq = delx * delx + dely * dely + delz * delz;
      if (rsq >= cutsq_kernel) continue;
      const double f_ij = pair_term(i, j, rsq, particles.temperature(i) - particles.temperature(j));
      const double energy = particles.mass(i) * particles.mass(j) * f_ij;    // into i, out of j
      for (size_t k = 0; k < flows.size(); k++) {
        if ((mask[i] & flows[k].to) && (mask[j] & flows[k].from)) local[k] += energy;
        if ((mask[j] & flows[k].to) && (mask[i] & flows[k].from) && (newton || j < nlocal))
          local[k] -= energy;
      }
    }
  }
  std::vector<double> total(flows.size(), 0.0);
  MPI_Allreduce(local.data(), total.data(), (int) flows.size(), MPI_DOUBLE, MPI_SUM, world);
  for (size_t k = 0; k < flows.size(); k++) flows[k].power = total[k];
}

/* ---------------------------------------------------------------------- */
