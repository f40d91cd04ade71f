/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(SPH/MIXING/REFERENCE,FixSPHMixingReference);
// clang-format on
#else

#ifndef LMP_FIX_SPH_MIXING_REFERENCE_H
#define LMP_FIX_SPH_MIXING_REFERENCE_H

#include "fix.h"

namespace LAMMPS_NS {

// The reference state of compute sph/mixing, created by it (not a user
// command): each particle's own tag and its neighbours at the reference
// time (their tags then, the periodic image shift that made them
// neighbours, initial distance), the reference time and the reference
// entropies. The lists move with the atoms between ranks and are written
// to restart files. A neighbour is found by its tag at the reference, which
// its atom keeps: tags renumbered since (delete_atoms with 'compress yes',
// reset_atoms id) do not break the lists.
class FixSPHMixingReference : public Fix {
 public:
  FixSPHMixingReference(class LAMMPS *, int, char **);
  ~FixSPHMixingReference() override;
  int setmask() override { return 0; }

  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;
  void write_restart(FILE *) override;
  void restart(char *) override;
  double memory_usage() override;

  // the lists hold up to 'width' neighbours each; clears them
  void resize(int width);

  // a neighbour's periodic image shift (box lengths along x, y, z, each
  // within +-511) in one int, and back
  static int pack_shift(const int shift[3]);
  static void unpack_shift(int packed, int shift[3]);

  // the simulation time now
  double now() const;
  // after a restart, the reference time from the time that had passed
  // (LAMMPS 29Sep2021 restarts the clock at 0, 4Feb2025 keeps it; fix
  // sph/dt/reset restores it when it is created): at the next run's setup
  void settle_restart();

  int captured;           // 1 once the compute has taken its reference
  int width;              // neighbours per atom the arrays hold
  double time0;           // simulation time of the reference
  double entropy0[2];     // S of component A and of the rest at the reference
  tagint *tag0;           // each atom's own tag at the reference (0: created since)
  int *count;             // neighbours stored per atom
  tagint **tags;          // their tags
  int **shifts;           // their periodic image shifts (packed, see the .cpp)
  double **distance0;     // their distances at the reference

 private:
  int restart_pending;       // read from a restart file, time0 not yet settled
  double elapsed_restart;    // the time since the reference when it was written
  int values_per_atom() const { return 2 + 3 * width; }
  // columns of the per-atom lists: at least 1, so that they exist before the capture
  int slots() const { return width > 0 ? width : 1; }
};

}    // namespace LAMMPS_NS

#endif
#endif
