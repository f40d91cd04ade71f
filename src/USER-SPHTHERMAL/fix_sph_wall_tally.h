/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifndef LMP_FIX_SPH_WALL_TALLY_H
#define LMP_FIX_SPH_WALL_TALLY_H

#include "fix.h"

namespace LAMMPS_NS {

// The heat a wall of prescribed temperature exchanges with the medium (the
// energy method of Cleary 1998, eq 10), for the wall fixes that hold a
// temperature: the rate into each wall particle, the energy it took up, and
// their sums as the fix's scalar and vector, kept across restarts. Not a
// style: fix sph/wall/isothermal and fix sph/wall/dirichlet derive from it.
class FixSPHWallTally : public Fix {
 public:
  FixSPHWallTally(class LAMMPS *, int, char **);
  ~FixSPHWallTally() override;
  double compute_scalar() override;
  double compute_vector(int) override;
  void write_restart(FILE *) override;
  void restart(char *) override;
  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;
  double memory_usage() override;

  // the heat rate into owned wall atom i at the last force evaluation, and
  // the particle spacing given to the fix (0: none)
  double rate_into(int i) const { return wall[i][0]; }
  double spacing_given() const { return spacing; }

 protected:
  double spacing;           // particle spacing for the flux of eq 10, 0 when not given
  double rate_previous;     // heat rate into the wall at the previous force evaluation
  double rate;              // heat rate into the wall now (sum over all ranks)
  double energy;            // energy taken up by the wall since the fix was defined
  double **wall;            // per atom: heat rate in, energy taken up [, flux]
  int callbacks_added;      // 1 once tally_arrays() has run

  // after the derived constructor has read 'spacing': the per-atom columns
  void tally_arrays();
  // take up the pair's heat rates of the wall's particles (first: at a
  // run's setup, rates only); zero_rates: then zero their desph
  void tally(int first, int zero_rates);
};

}    // namespace LAMMPS_NS

#endif
