/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifndef LMP_SPH_CHECKS_H
#define LMP_SPH_CHECKS_H

#include "lmptype.h"

#include <cstdio>
#include <string>
#include <vector>

namespace LAMMPS_NS {

class LAMMPS;
class Fix;

// The package's one place for the checks that keep a run from going on
// silently with a value that makes no sense: per-atom state at the start of
// a run, rates after they are computed, and overlapping groups of styles.
namespace SPHCheck {

  // The checks that stop a run take the caller's FLERR (file, line): the
  // error names the line of the style that asked, and the test of error
  // branches (unittest, robust.error_branches) maps each case to that line.

  // what a style needs of every owned atom of a group: finite esph, and a
  // finite positive rho and cv when asked; a collective error naming the
  // first offending atom (lowest ID), its type and the quantity
  enum { RHO = 1, CV = 2, ESPH = 4 };
  void atom_state(LAMMPS *lmp, const char *file, int line, const char *who, int groupbit,
                  int needs);

  // stop for a problem this rank alone has found (no communication): the
  // message reaches the output whichever rank finds it
  void stop(LAMMPS *lmp, const char *file, int line, const std::string &message);

  // every step, before anything is derived from it: the own state of each
  // owned atom (position and velocity finite; rho finite and > 0, esph
  // finite when asked), so that a fault is named at the atom it arose on;
  // a stop (on this rank: no communication) naming the atom, its type, the
  // quantity and the step. A NaN position never triggers a neighbour-list
  // rebuild, so LAMMPS's own checks of coordinates would not see it.
  // One pass per step: a later call in the same step, on the same arrays,
  // returns at once (set-up always checks).
  void particles(LAMMPS *lmp, const char *file, int line, const char *who, int needs);

  // the first owned atom whose value of 'values' is not finite, or -1
  int first_nonfinite(const double *values, int n);
  int first_nonfinite3(double *const *values, int n);

  // stop (on this rank: no communication) naming the owned atom i, its type,
  // the quantity and the step; 'why' says what made it so, may be empty
  void nonfinite(LAMMPS *lmp, const char *file, int line, const char *who, const char *quantity,
                 int i, double value, const std::string &why);

  // the group of a fix that stands for particles of a kind (a wall, a
  // heated surface), at its init: an error when it is empty, or holds every
  // atom (unless every_ok), or shares atoms with a fix of one of the styles
  // 'exclusive' (a particle can be one kind of wall only); integrated by
  // fix sph (moving with the flow) an error, or a warning when moving_ok
  void group_of_kind(LAMMPS *lmp, const char *file, int line, Fix *fix,
                     const std::vector<Fix *> &exclusive, bool every_ok, bool moving_ok);

  // The atom an error names when several ranks may each find bad atoms: the
  // lowest ID, with up to four numbers its owner records of it (type,
  // value, which quantity). consider() on each rank; agree() is
  // collective and returns 1 when any rank found one, with 'tag' and
  // 'info' then that atom's on every rank, ready for error->all.
  class FirstBad {
   public:
    tagint tag = MAXTAGINT;
    double info[4] = {0.0, 0.0, 0.0, 0.0};
    void consider(tagint id, double a = 0.0, double b = 0.0, double c = 0.0, double d = 0.0)
    {
      if (id >= tag) return;
      tag = id;
      info[0] = a, info[1] = b, info[2] = c, info[3] = d;
    }
    int agree(LAMMPS *lmp);
  };

  // 1 when some atom is in both groups (collective)
  int groups_overlap(LAMMPS *lmp, int groupbit1, int groupbit2);
  // number of atoms of a group (collective)
  bigint group_count(LAMMPS *lmp, int groupbit);
  // the atom types of a group: [t] = 1 when an atom of type t is in it,
  // for t = 1 .. ntypes (collective)
  std::vector<int> group_types(LAMMPS *lmp, int groupbit);
  // a warning (rank 0) when group igroup has no atoms: for the computes,
  // whose values are then all 0 (the group may fill later)
  void warn_empty(LAMMPS *lmp, const char *file, int line, const char *who, int igroup);

  // The head of a style's restart settings: a tag and the version of the
  // settings' layout, raised whenever a setting is added, so that a file
  // with another layout is refused instead of misread. write: rank 0's
  // file only; read: collective, an error naming the style when the file
  // has no head (written before heads existed) or another version.
  void write_restart_head(FILE *fp, int version);
  void read_restart_head(LAMMPS *lmp, const char *file, int line, FILE *fp, const char *who,
                         int version);

  // A fix's global restart state (n doubles) behind the same head, as the
  // one block LAMMPS keeps per fix. write: rank 0's file only; read: the
  // state after the head, or the same errors naming the fix (its style and
  // ID); a head-less block holds at least one double, so its first 8 bytes
  // can be read as a head.
  void write_restart_state(FILE *fp, int version, const double *state, int n);
  const double *read_restart_state(LAMMPS *lmp, const char *file, int line, Fix *fix,
                                   const char *buf, int version);

  // A name (a group's) in such a state: its length, then its characters,
  // one per double. unpack: the name at state[at], 'at' moved past it.
  void pack_name(std::vector<double> &state, const std::string &name);
  std::string unpack_name(const double *state, int &at);

}    // namespace SPHCheck
}    // namespace LAMMPS_NS

#endif
