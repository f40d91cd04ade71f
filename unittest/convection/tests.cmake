# convection tests (included by unittest/CMakeLists.txt; helpers: cmake/sphthermal_tests.cmake)
add_header_test(test_convection_terms convection/test_convection_terms.c C_EXTENSIONS OFF)
sphthermal_unit_checks(convection.terms test_convection_terms buoyancy linear thin shift gradient
  quadratic moments)
add_error_cases(convection convection/errors.in)
# the reference of the Rayleigh-Benard onset (linear stability, Chebyshev)
sphthermal_python_test(convection.reference.rb_linear tools/test_rb_linear.py LABELS unit)
# the reference of the heated cavity (steady Boussinesq finite volumes)
sphthermal_python_test(convection.reference.cavity_fv tools/test_cavity_fv.py LABELS unit)
# the reference of steady Rayleigh-Benard rolls (the same finite volumes, one roll
# between free-slip sides): conduction below onset, the onset of rb_linear, Nu at 1e4
sphthermal_python_test(convection.reference.rb_fv tools/test_rb_fv.py LABELS unit)
# mirror walls: exact for linear fields, energy kept, Nu = 1 without buoyancy
foreach(check linear conserve)
  sphthermal_python_test(convection.adiabatic.${check} convection/test_walls.py LAMMPS
    ARGS ${check} LABELS unit)
endforeach()
# fix sph/shift: none on a lattice, evens out crowding, walls stay, T
# follows, rho follows the volume
foreach(check lattice spread linear follow volume shared)
  sphthermal_python_test(convection.shift.${check} convection/test_shift.py LAMMPS
    ARGS ${check} LABELS unit)
endforeach()
# examples/convection-cavity/in.air started from a dump of itself (-var from)
sphthermal_python_test(convection.air.from convection/test_air_from.py LAMMPS LABELS regression)
# examples/convection-cavity/in.air in 3-D (-var nz, quasi-2-D) against 2-D
sphthermal_python_test(convection.air.depth convection/test_air_depth.py LAMMPS LABELS regression)
# examples/convection-cavity/in.air in two pieces (-var restart, -var resume) against one run
sphthermal_python_test(convection.air.resume convection/test_air_resume.py LAMMPS
  LABELS regression)
# compute sph/nusselt: exact wall gradient of a linear field, heat estimate
sphthermal_python_test(convection.nusselt.linear convection/test_walls.py LAMMPS ARGS nusselt
  LABELS unit)
# measured: |Nu - 1| = 0.011 % at 20 x 20 with the input's consistent conduction
# (0.095 % with the plain operator; 0.2 % is the issue's bound at 40 x 40)
sphthermal_python_test(convection.validation.conduction_20 convection/test_walls.py LAMMPS
  ARGS conduction --n 20 --tolerance 0.002 LABELS validation)
# the same in 3-D with a periodic depth (quasi-2-D): measured -0.014 % (plain
# operator -0.069 %)
sphthermal_python_test(convection.validation.conduction_3d convection/test_walls.py LAMMPS
  ARGS conduction --n 10 --nz 8 --tend 0.3 --tolerance 0.002 LABELS validation)
# the cavity with buoyancy, 20 x 20 (Wendland, h = 2 dx, the input's defaults:
# corrected gradient, shifting, consistent conduction, compression by the
# buoyancy 0.02 at Ra 1e3 and 0.05 above): measured mean Nu +1.06 % (Ra 1e3,
# t = 0.6) and +4.98 % (Ra 1e4, t = 0.3) off de Vahl Davis. The issue's
# bounds (1 %) hold from 40 across; these coarse runs check that Nu stays
# near its measured value
sphthermal_python_test(convection.validation.cavity_ra1e3_20 convection/test_walls.py LAMMPS
  ARGS cavity --ra 1e3 --tend 0.6 --n 20 --tolerance 0.015 LABELS validation)
sphthermal_python_test(convection.validation.cavity_ra1e4_20 convection/test_walls.py LAMMPS
  ARGS cavity --ra 1e4 --tend 0.3 --n 20 --tolerance 0.06 LABELS validation)
# Rayleigh-Benard onset (width 2H, 20 per H) from three growth rates, with
# the package's defaults (in.rb): measured -1.36 % off linear theory
# (1707.92; the full search -2.62 %; -4.58 % with the example's earlier
# explicit settings, +1.18 % with eta 0.01 in the heat pair); the issue's
# bound is 10 %, this test's 3 %
file(MAKE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/rb_onset)
sphthermal_python_test(convection.validation.rb_onset_20
  ${SPHTHERMAL_ROOT}/examples/convection-rayleigh-benard/analyse.py
  ARGS onset --steps 1 --n 20 --lmp ${SPHTHERMAL_LMP} --plugin ${SPHTHERMAL_PLUGIN}
       --out ${CMAKE_CURRENT_BINARY_DIR}/rb_onset --max-error 3
  LABELS validation)
# Rayleigh-Benard convection above onset (width 2H, 16 per H, Ra 1e4, to
# t = 0.6, settings convection of in.rb: the package's defaults with fix
# sph/shift, the flow pair's correction gradient among them): measured mean Nu
# +0.35 % off the steady rolls of tools/rb_fv.py (+0.08 % at 20 per H to
# t = 0.8, -1.90 % there without the gradient correction; +9.04 % at 16
# per H with Adami's Shepard mean at the walls); checks that it stays
# near its measured value
file(MAKE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/rb_nu)
sphthermal_python_test(convection.validation.rb_nu_16
  ${SPHTHERMAL_ROOT}/examples/convection-rayleigh-benard/analyse.py
  ARGS nu --run 1e4 --n 16 --tend 0.6 --from 0.3 --lmp ${SPHTHERMAL_LMP}
       --plugin ${SPHTHERMAL_PLUGIN} --dir ${CMAKE_CURRENT_BINARY_DIR}/rb_nu --max-error 2
  LABELS validation)
# every convection style together: 1, 2 and 4 ranks, and a restart
set(cavity_small ${CMAKE_CURRENT_LIST_DIR}/in.cavity_small)
foreach(np 2 4)
  sphthermal_state_test(convection.mpi.np${np} same ${cavity_small} NP ${np} RTOL 1e-12)
endforeach()
# compute sph/nusselt and fix sph/shift in the cavity: 1 against 2 and 4 ranks
foreach(np 2 4)
  sphthermal_python_test(convection.mpi.cavity_np${np} convection/test_walls.py LAMMPS
    ARGS ranks --np ${np} --mpirun ${MPIRUN} LABELS mpi PROCESSORS ${np})
endforeach()
sphthermal_state_test(convection.restart same ${cavity_small} ARGS --var2 split=yes RTOL 0)
# the skillen shift's sums from the flow pair's loop, with the ghosts' sent home
sphthermal_python_test(convection.mpi.shift_shared_np2 convection/test_shift.py LAMMPS
  ARGS shared --np 2 --mpirun ${MPIRUN} LABELS mpi PROCESSORS 2)
# and from the /omp pair's threads, each adding to its own copy of the sums
if(host_openmp)
  # the whole cavity on threads (the /omp pairs; the conduction's factors,
  # the gradient correction and the mirror walls on the threads of package
  # omp) against one thread, over builds and warm sweeps between them
  foreach(threads 2 3)
    sphthermal_state_test(convection.omp.cavity_threads${threads} same ${cavity_small}
      ARGS --var steps=60 --var2 threads=${threads} RTOL 1e-12 PROCESSORS 2)
  endforeach()
  sphthermal_state_test(convection.omp.cavity_hold_threads2 same ${cavity_small}
    ARGS --var steps=60 --var warm=hold --var gradient=gradient/hold --var2 threads=2
    RTOL 1e-12 PROCESSORS 2)
  sphthermal_python_test(convection.omp.shift_shared_threads2 convection/test_shift.py LAMMPS
    ARGS shared --threads 2 LABELS unit PROCESSORS 2)
  # the fix's own pass on threads, both forms
  foreach(form skillen delta-plus)
    sphthermal_python_test(convection.omp.shift_own_${form}_threads2 convection/test_shift.py
      LAMMPS ARGS threads --form ${form} --threads 2 LABELS unit PROCESSORS 2)
  endforeach()
endif()
# the mirror walls keep their ghost points' neighbours, and the Adami walls
# their fluid neighbours, from one neighbour build to the next: a skin of
# 0.1 (no build in 200 steps) gives the state of 0.02 (builds every few
# steps) to round-off (measured 9e-16; mirror neighbours found within the
# cutoff alone: 2e-6; Adami neighbours within the cutoff alone: fails too);
# with warm 0, as the warm sweeps' factors depend on the steps of the
# builds by design
sphthermal_state_test(convection.mirror.skin same ${cavity_small}
  ARGS --var steps=100 --var warm=0 --var2 skin=0.1 RTOL 1e-10)
# with the default warm 1 they differ by what 5 Jacobi sweeps from zero
# leave unconverged (a skin of 0.1 sweeps on from the last step's factors
# throughout; measured 1.1e-4 of max T, 1.2e-3 of max desph). A warm
# start from the factors of re-indexed atoms fails convection.mpi.cavity_*
sphthermal_state_test(convection.mirror.skin_warm same ${cavity_small}
  ARGS --var steps=100 --var2 skin=0.1 RTOL 1e-2)

# 'warm hold': where the lists are built every step the factors are made
# anew every step, as with warm 0, to the bit; with builds every few steps
# (skin 0.02, 100 steps) the held factors at the pairs' current separations
# keep the state within 2e-2 of warm 0's (measured 1.2e-2 of max desph;
# the plain term, correction none, is 5.6e-2 off in drho, 4.7e-2 in desph);
# the same on 2 ranks, and across a restart (whose setup makes them anew,
# as a run's does)
sphthermal_state_test(convection.hold.builds same ${cavity_small}
  ARGS --var steps=20 --var warm=hold --var check=no --var2 warm=0 RTOL 0)
sphthermal_state_test(convection.hold.moved same ${cavity_small}
  ARGS --var steps=100 --var warm=hold --var2 warm=0 RTOL 2e-2)
sphthermal_state_test(convection.mpi.hold_np2 same ${cavity_small} NP 2
  ARGS --var steps=100 --var warm=hold RTOL 1e-12)
sphthermal_state_test(convection.hold.restart same ${cavity_small}
  ARGS --var warm=hold --var2 split=yes RTOL 0)
# the same with correction second (nu held; measured 1.3e-2 of max desph,
# the plain term 8.1e-2)
sphthermal_state_test(convection.hold.second_builds same ${cavity_small}
  ARGS --var steps=20 "--var=warm=hold correction second" --var check=no
  "--var2=warm=0 correction second" RTOL 0)
sphthermal_state_test(convection.hold.second_moved same ${cavity_small}
  ARGS --var steps=100 "--var=warm=hold correction second" "--var2=warm=0 correction second"
  RTOL 2e-2)
# 'correction gradient/hold' likewise against gradient: to the bit with a
# build every step; within 5e-2 with builds every few steps (measured
# 3.1e-2 of max drho; correction none: 1.4e-1 of drho, 5.8e-2 of fx)
sphthermal_state_test(convection.hold.gradient_builds same ${cavity_small}
  ARGS --var steps=20 --var gradient=gradient/hold --var check=no --var2 gradient=gradient RTOL 0)
sphthermal_state_test(convection.hold.gradient_moved same ${cavity_small}
  ARGS --var steps=100 --var gradient=gradient/hold --var2 gradient=gradient RTOL 5e-2)
sphthermal_state_test(convection.mpi.hold_gradient_np2 same ${cavity_small} NP 2
  ARGS --var steps=100 --var gradient=gradient/hold --var warm=hold RTOL 1e-12)
sphthermal_state_test(convection.hold.gradient_restart same ${cavity_small}
  ARGS --var gradient=gradient/hold --var2 split=yes RTOL 0)

# fix sph/boussinesq T0 'mean': the buoyancy sums to zero while the fluid warms
sphthermal_python_test(convection.boussinesq.mean convection/test_boussinesq_mean.py LAMMPS LABELS unit)
sphthermal_python_test(convection.boussinesq.layers convection/test_boussinesq_layers.py LAMMPS LABELS unit)
# the flagship input (the package's defaults) against the same scene with every setting given
sphthermal_python_test(convection.cavity_defaults convection/test_walls.py LAMMPS ARGS defaults
  LABELS unit)
# the corrections' defaults from the scene (buoyancy or not, pressure form, restart)
sphthermal_python_test(convection.scene_defaults convection/test_scene_defaults.py LAMMPS LABELS unit)
# 'eos ... auto': the speed of sound from fix sph/boussinesq's compression
# bound, a background relative to rho0 c0^2, tait, restart; 2 ranks alike
sphthermal_python_test(convection.sound_speed_auto convection/test_sound_speed_auto.py LAMMPS
  LABELS unit)
sphthermal_python_test(convection.mpi.sound_speed_auto_np2 convection/test_sound_speed_auto.py
  LAMMPS ARGS --np 2 --mpirun ${MPIRUN} LABELS mpi PROCESSORS 2)
# fix sph/boussinesq 'hold': held by default in a closed domain, not with
# fix gravity or a solid type, standing down for the user's own, restarts
sphthermal_python_test(convection.hold_default convection/test_hold_default.py LAMMPS LABELS unit)
sphthermal_python_test(convection.mpi.hold_default_np2 convection/test_hold_default.py LAMMPS
  ARGS --np 2 --mpirun ${MPIRUN} LABELS mpi PROCESSORS 2)
# fix sph/hold/volume: the layer's volume held to round-off, and across a restart
sphthermal_python_test(convection.hold_volume convection/test_hold_volume.py LAMMPS LABELS unit)
sphthermal_python_test(convection.mpi.hold_volume_np2 convection/test_hold_volume.py LAMMPS
  ARGS --np 2 --mpirun ${MPIRUN} LABELS mpi PROCESSORS 2)
# fix sph/boussinesq 'potential': phi against the exact series of a linear
# temperature at rest (2.2 % of max|phi| at 20 across, 0.82 % at 40), a
# restart goes on from the file's phi, and 1 against 2 and 4 ranks
sphthermal_python_test(convection.potential.series convection/test_potential.py LAMMPS
  ARGS series --n 20 --tolerance 0.025 LABELS validation)
sphthermal_python_test(convection.potential.restart convection/test_potential.py LAMMPS
  ARGS restart LABELS regression)
foreach(np 2 4)
  sphthermal_python_test(convection.potential.ranks_np${np} convection/test_potential.py LAMMPS
    ARGS ranks --np ${np} --mpirun ${MPIRUN} LABELS mpi PROCESSORS ${np})
endforeach()
# the cavity at c0 = 10 v_max (12 across) with and without the potential:
# the density's range (0.49 of it) and Nu (within 1 %)
sphthermal_python_test(convection.potential.cavity convection/test_potential.py LAMMPS
  ARGS cavity LABELS regression)
