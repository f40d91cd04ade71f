/* -*- c -*- -------------------------------------------------------------
   USER-SPHTHERMAL: particle shifting, in C99 (also C++).

   The shift of Skillen et al. 2013 as Reece et al. 2024 use it (eq 38):
     dr_i = -D h |v_i| dt grad C_i,   grad C_i = sum_j V_j grad_i W_ij
   with C the kernel sum of the particles' volumes, so that particles move
   from where they crowd to where they are sparse when D > 0. Reece et al.
   print the term with a leading minus and D = -2 (their Table 2); with
   both signs the particles would move towards crowding: D = -2 is the
   coefficient of DualSPHysics, whose formula has no leading minus, so
   D = 2 here is their setting.
------------------------------------------------------------------------- */

#ifndef SPH_SHIFT_H
#define SPH_SHIFT_H

#include <math.h>

/* dr = -D h |v| dt grad_c */
static inline void sphs_skillen(double coefficient, double h, double speed, double dt,
                                const double grad_c[3], double dr[3])
{
  const double s = -coefficient * h * speed * dt;
  dr[0] = s * grad_c[0];
  dr[1] = s * grad_c[1];
  dr[2] = s * grad_c[2];
}

/* shorten dr to at most 'limit' long; returns 1 when it was shortened */
static inline int sphs_cap(double dr[3], double limit)
{
  const double length = sqrt(dr[0] * dr[0] + dr[1] * dr[1] + dr[2] * dr[2]);
  if (!(length > limit)) return 0;
  const double s = limit / length;
  dr[0] *= s;
  dr[1] *= s;
  dr[2] *= s;
  return 1;
}

#endif
