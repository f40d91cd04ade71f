# pair sph/cleary/heat 'correction consistent' on a lattice rotated against
# free edges (atoms exactly on the edges, corners cutting the rows): desph
# finite, the corners on the plain term, energy kept, a linear field exact
# deep inside
foreach(case cubic_f wendland_s quintic_f)
  sphthermal_python_test(robust.consistent_edge.${case} robust/test_consistent_edge.py LAMMPS
    ARGS --case ${case} LABELS unit)
endforeach()
