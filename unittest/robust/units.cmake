# fix sph/dt/reset in every unit style: the same scene (conduction; a
# viscous flow under gravity) in si and in <units> gets the same timestep
# and limits in seconds, so each limit has the unit factor ftm2v with which
# fix sph integrates the rates; each run stays finite and bounded
foreach(units cgs metal real electron lj)
  sphthermal_python_test(robust.dt_units.${units} robust/test_dt_units.py LAMMPS
    ARGS --units ${units} LABELS unit)
endforeach()

# a fixed timestep (checked by the internal fix SPH/TIMESTEP/CHECK that the
# package's pairs add): no warning below the smallest limit the pairs know, a
# warning above it, none with fix sph/dt/reset (which sets dt itself)
foreach(units si metal real)
  sphthermal_python_test(robust.timestep.fixed.${units} robust/test_dt_units.py LAMMPS
    ARGS --fixed ${units} LABELS unit)
endforeach()
