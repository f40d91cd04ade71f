/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifndef LMP_SPH_COMM_STAGE_H
#define LMP_SPH_COMM_STAGE_H

namespace LAMMPS_NS {

// One communication stage of a style: the per-atom values it exchanges,
// listed once and packed the same way by all four of LAMMPS's pack and
// unpack calls. Forward: the owners' values copied to their ghosts;
// reverse: the ghosts' values combined into their owners' (summed, or the
// largest or smallest kept). A style lists the fields of its current stage
//
//   SPHCommStage stage;
//   stage.rows(corr_kinv, 6).rows(corr_deficit, 3);    // 9 values per atom
//
// and hands its pack/unpack calls to the stage's.
class SPHCommStage {
 public:
  enum Combine { SUM, MAX, MIN };

  // 'width' values per atom: array[i][offset .. offset + width)
  SPHCommStage &rows(double **array, int width, int offset = 0, Combine combine = SUM);
  // 'width' values per atom: array[i * width .. (i + 1) * width)
  SPHCommStage &flat(double *array, int width, Combine combine = SUM);

  int size() const;    // values per atom

  int pack(int n, const int *list, double *buf) const;    // atoms list[0..n)
  int pack(int n, int first, double *buf) const;          // atoms first..first+n-1
  void unpack_forward(int n, int first, const double *buf) const;
  void unpack_reverse(int n, const int *list, const double *buf) const;

 private:
  struct Field {
    double **rows;
    double *flat;
    int width, offset;
    Combine combine;
  };
  static constexpr int MAX_FIELDS = 4;
  Field fields[MAX_FIELDS];
  int nfields = 0;
  SPHCommStage &add(const Field &field);
  // visit(field, the atom's values of it, their place in the buffer) for
  // atoms atom_of(0..n-1), field after field
  template <class AtomOf, class Visit> void walk(int n, AtomOf atom_of, Visit visit) const;
};

}    // namespace LAMMPS_NS

#endif
