# fix sph/grains: unresolved grains of LAMMPS's GRANULAR in the fluid
# (included by unittest/CMakeLists.txt; helpers: cmake/sphthermal_tests.cmake)

# the exchange laws (sph_grain_laws.h) against their published forms
add_header_test(test_grain_laws grains/test_grain_laws.c)
sphthermal_test(granular.laws LABELS unit COMMAND test_grain_laws)

# Schumann's solution (tools/schumann.py) against its own marched equations
sphthermal_python_test(granular.reference.schumann tools/test_schumann.py LABELS unit)

set(grains_test ${CMAKE_CURRENT_LIST_DIR}/test_grains.py)
# LAMMPS 4Feb2025 has the grains' temperature (fix heat/flow); 29Sep2021 none
if(LAMMPS_RELEASE STREQUAL "4Feb2025")
  set(grains_heat ranz-marshall)
else()
  set(grains_heat none)
endif()
# with the fluid's conduction (pair sph/cleary/heat) in the hybrid
sphthermal_python_test(granular.conservation.conduction ${grains_test} LAMMPS
  ARGS --check conservation --heat ${grains_heat} --conduction 1 LABELS unit)
foreach(drag stokes difelice)
  sphthermal_python_test(granular.conservation.${drag} ${grains_test} LAMMPS
    ARGS --check conservation --drag ${drag} --heat ${grains_heat} LABELS unit)
  sphthermal_python_test(granular.settle.${drag} ${grains_test} LAMMPS
    ARGS --check settle --drag ${drag} LABELS validation)
endforeach()
# the fluid's force in the gradient form (model A): still exchanged to round-off
sphthermal_python_test(granular.conservation.gradient ${grains_test} LAMMPS
  ARGS --check conservation --drag difelice --heat ${grains_heat} --pressure gradient LABELS unit)
# buoyancy: in a column of liquid at rest under gravity, in both forms
sphthermal_python_test(granular.column ${grains_test} LAMMPS ARGS --check column LABELS validation)
sphthermal_python_test(granular.column.gradient ${grains_test} LAMMPS
  ARGS --check column --pressure gradient LABELS validation)
# a fixed packed bed against the drag law's exact value and Ergun's equation
# (examples/grains-bed): viscous at porosity 0.5, inertial at 0.7
sphthermal_python_test(granular.bed.gidaspow_viscous ${grains_test} LAMMPS
  ARGS --check bed --drag gidaspow --porosity 0.5 --gradient 300 LABELS validation)
sphthermal_python_test(granular.bed.gidaspow_inertial ${grains_test} LAMMPS
  ARGS --check bed --drag gidaspow --porosity 0.7 --gradient 1e4 --c0 0.9 --time 0.4
  LABELS validation)
sphthermal_python_test(granular.bed.difelice ${grains_test} LAMMPS
  ARGS --check bed --drag difelice --porosity 0.5 --gradient 300 LABELS validation)
# a bed of free grains poured at random and coupled with liquid at rest
sphthermal_python_test(granular.freebed ${grains_test} LAMMPS ARGS --check freebed LABELS validation)
# the same bed at full size, poured through the liquid, fluidised by an
# upward flow (examples/grains-fluidised), the hydrostatic form: below the
# onset Ergun's pressure drop, above it the bed's weight
sphthermal_python_test(granular.fluidised.fixed ${grains_test} LAMMPS
  ARGS --check fluidised --pressure hydrostatic --velocity 0.0045 --time 1.2 --below 1 LABELS validation)
sphthermal_python_test(granular.fluidised.lifted ${grains_test} LAMMPS
  ARGS --check fluidised --pressure hydrostatic --velocity 0.0105 --time 0.6 --below 0 LABELS validation)
if(LAMMPS_RELEASE STREQUAL "4Feb2025")
  # a packed bed heated by a hot inflow against Schumann's solution
  sphthermal_python_test(granular.heatbed ${grains_test} LAMMPS ARGS --check heatbed LABELS validation)
  # the showcase: hot grains poured into a tank of cold oil (examples/grains-hot-pour)
  sphthermal_python_test(granular.hot_pour ${grains_test} LAMMPS ARGS --check hot_pour LABELS validation)
  sphthermal_python_test(granular.heat.ranz-marshall ${grains_test} LAMMPS
    ARGS --check heat --heat ranz-marshall LABELS validation)
endif()
foreach(np 2 4)
  sphthermal_python_test(granular.mpi.conservation_np${np} ${grains_test} LAMMPS
    ARGS --check mpi --heat ${grains_heat} --np ${np} --mpirun ${MPIRUN} LABELS mpi PROCESSORS ${np})
endforeach()
# no state of its own: a restart (on 2 ranks) continues as in one go
sphthermal_python_test(granular.restart ${grains_test} LAMMPS
  ARGS --check restart --heat ${grains_heat} --np 2 --mpirun ${MPIRUN} LABELS unit PROCESSORS 2)
# a restart file whose fix sph/grains state has another layout is refused
sphthermal_python_test(granular.restart.version_head flow/test_restart_head.py LAMMPS
  ARGS --scene grains --record ${error_sites_dir} LABELS regression)
set_property(GLOBAL APPEND PROPERTY sphthermal_error_tests granular.restart.version_head)
add_error_cases(granular ${CMAKE_CURRENT_LIST_DIR}/errors.in)
