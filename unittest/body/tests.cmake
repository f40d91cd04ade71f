# compute sph/force: the force and torque on a body (included by
# unittest/CMakeLists.txt; helpers: cmake/sphthermal_tests.cmake)
set(force_input ${CMAKE_CURRENT_LIST_DIR}/in.force)
# against the forces the pair gave the disc, every pressure and viscosity
# form, the gradient correction, torques about the centre of mass and a point
foreach(forms averaged:adami symmetric:cleary sum:morris)
  string(REPLACE ":" ";" pv ${forms})
  list(GET pv 0 p)
  list(GET pv 1 v)
  sphthermal_lammps_test(body.force.sum.${p}_${v} ${force_input}
    VARS check sum pressure ${p} viscosity ${v} LABELS unit PASS "force: sum passed")
endforeach()
sphthermal_lammps_test(body.force.sum.gradient_point ${force_input}
  VARS check sum correction gradient center point LABELS unit PASS "force: sum passed")
# the split: all viscous at rest density, all pressure without viscosity
foreach(v adami cleary morris)
  sphthermal_lammps_test(body.force.viscous.${v} ${force_input}
    VARS check viscous viscosity ${v} LABELS unit PASS "force: viscous passed")
endforeach()
sphthermal_lammps_test(body.force.pressure ${force_input}
  VARS check pressure LABELS unit PASS "force: pressure passed")
foreach(np 2 4)
  sphthermal_python_test(body.mpi.force_np${np} body/test_force_ranks.py LAMMPS
    ARGS --np ${np} --mpirun ${MPIRUN} LABELS mpi PROCESSORS ${np})
endforeach()
# the sums of the /omp pair style's loop (made after its threads' reduction)
if(host_openmp)
  sphthermal_lammps_test(body.force.sum.omp ${force_input}
    VARS check sum omp 2 LABELS unit PASS "force: sum passed" ENVIRONMENT OMP_NUM_THREADS=2)
endif()
add_error_cases(body ${CMAKE_CURRENT_LIST_DIR}/errors.in)
