# pair sph/cleary/heat 'correction second' on a lattice rotated by atan(1/2):
# with free edges the Laplacian of a quadratic field exact on every corrected
# atom (the regularised solve alone left 1.1e-3 deep inside, worse than the
# plain term's 1.6e-4), periodic no worse than the plain term
foreach(case free periodic)
  sphthermal_python_test(robust.second_rotated.${case} robust/test_second_rotated.py LAMMPS
    ARGS --case ${case} LABELS unit)
endforeach()
