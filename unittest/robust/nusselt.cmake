# compute sph/nusselt: a staircase wall (an annulus cut from the lattice)
# warns and its heat estimate is exact within 0.3 %; flat walls with
# corners do not warn, on 1 and 2 ranks
foreach(np 1 2)
  sphthermal_python_test(robust.nusselt.staircase.np${np} robust/test_nusselt_staircase.py LAMMPS
    ARGS --np ${np} --mpirun ${MPIRUN} LABELS unit)
endforeach()
