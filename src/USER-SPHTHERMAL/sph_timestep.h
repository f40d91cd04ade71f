/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifndef LMP_SPH_TIMESTEP_H
#define LMP_SPH_TIMESTEP_H

#include <cmath>

namespace LAMMPS_NS {
class LAMMPS;
class FixSPHMaterials;

// The stability limits of the timestep of weakly compressible, thermal SPH,
// one formula each, shared by fix sph/dt/reset (which sets dt from them)
// and the check of a fixed timestep at the setup of a run
// (fix_sph_timestep_check.h):
//   acoustic  C_c h / (s c_i + |v_i|)
//   force     C_f sqrt(h / (s |f_i| / m_i))
//   viscous   C_v h^2 rho_i / (s mu_i)
//   thermal   C_t / (s lambda_i)
// with s = force->ftm2v. LAMMPS's fix sph (and fix sph/stationary)
// advances v by dt ftm2v f / m, and rho and esph by dt ftm2v drho and
// dt ftm2v desph; the package's pair styles compute f, drho and desph from
// the material parameters without unit factors. Each rate is thus
// integrated s times its pair value: the sound speed of the equations
// integrated is s c (pressure gradient and continuity each scaled by s),
// the momentum diffusivity s mu / rho, the relaxation rate s lambda. s = 1
// in units si, cgs, lj, micro and nano; 1 / 1.0364269e-4 in metal,
// 1 / 48.88821291^2 in real, 0.937582899 in electron.
namespace SPHTimestep {
  enum { ACOUSTIC = 0, FORCE, VISCOUS, THERMAL, NLIMITS };

  // "acoustic", "force", "viscous", "thermal"
  const char *name(int limit);

  // the per-atom quantity each limit falls with, as integrated (s applied)
  inline double signal_speed(double c, double speed, double s)
  {
    return s * c + speed;
  }
  inline double acceleration(double fmag, double mass, double s)
  {
    return s * fmag / mass;
  }
  inline double relaxation(double lambda, double s)
  {
    return s * lambda;
  }

  // the limits from those quantities (the viscous one from rho and mu)
  inline double acoustic(double coeff, double h, double signal)
  {
    return coeff * h / signal;
  }
  inline double force(double coeff, double h, double accel)
  {
    return coeff * sqrt(h / accel);
  }
  inline double viscous(double coeff, double h, double rho, double mu, double s)
  {
    return coeff * (h * h) * rho / (s * mu);
  }
  inline double thermal(double coeff, double rate)
  {
    return coeff / rate;
  }

  // the limits of the atoms of a group, as one pass over the owned atoms
  struct Scan {
    double coeff[NLIMITS];         // 0: the limit is off
    double h;                      // smoothing length
    int groupbit;                  // the atoms whose limits count
    FixSPHMaterials *materials;    // eos and viscosity (acoustic, viscous limits)
    const double *relax_rate;      // pair sph/cleary/heat's lambda_i (thermal), or nullptr
    const double *body_force;      // fix gravity's acceleration, or nullptr
    const char *who;               // for the messages of the viscosity laws
  };
  // this rank's minimum of each limit (coefficient applied; 'none' where no
  // atom has it), and bad[k] = 1 where an atom's limit is 0 or not a number.
  // A limit whose property the atom's type lacks (no eos, no viscosity, no
  // force, lambda = 0) does not apply to it. The body force counts as the
  // force limit of C_f sqrt(h / (s |g|)).
  void local_limits(LAMMPS *lmp, const Scan &scan, double none, double local[NLIMITS],
                    int bad[NLIMITS]);

  // h = cutoff / q_max of the package's SPH pair styles (the smallest when
  // there are several, e.g. in hybrid/overlay); 0 when there is none
  double smoothing_length(LAMMPS *lmp);
}    // namespace SPHTimestep

}    // namespace LAMMPS_NS

#endif
