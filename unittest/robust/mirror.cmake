# mirror walls around an obstacle (a surface region 'side out'): exact for
# a linear field, on 1 and 2 ranks
foreach(np 1 2)
  sphthermal_python_test(robust.mirror.side_out.np${np} robust/test_mirror_side.py LAMMPS
    ARGS --np ${np} --mpirun ${MPIRUN} LABELS unit)
endforeach()

# a medium atom past the wall's surface: refused as set up, taken within a
# tolerance at a later run's start (drift), refused beyond it
sphthermal_python_test(robust.mirror.drift robust/test_mirror_drift.py LAMMPS LABELS unit)

# wall atoms beyond the kernel's reach: a warning without an exclusion of
# wall pairs (the energy drifts), none and energy to round-off with one
sphthermal_python_test(robust.mirror.beyond_reach robust/test_mirror_deep.py LAMMPS
  LABELS unit)
