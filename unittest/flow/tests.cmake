# flow tests (included by unittest/CMakeLists.txt; helpers: cmake/sphthermal_tests.cmake)

# ------------------------------------------------------------ C terms
add_header_test(test_flow_terms flow/test_flow_terms.c)
# the same checks with the headers compiled as C++
add_header_test_cxx(test_flow_terms_cxx flow/test_flow_terms_cxx.cpp)
sphthermal_unit_checks(flow.terms test_flow_terms eos symmetry dissipation laplacian fused
  artificial)
sphthermal_test(flow.terms.cxx LABELS unit COMMAND test_flow_terms_cxx laplacian)

# ------------------------------------------------------------ rates
# forces, drho and the state after 5 steps of the flow regression system
# (two fluids between Adami walls, one sliding) against stored references
foreach(kernel ${kernels})
  foreach(newton on off)
    sphthermal_state_test(flow.rates.${kernel}.newton_${newton} state ${flow_input}
      ARGS --var kernel=${kernel} --var newton=${newton} REF flow/rates.${kernel}.ref)
  endforeach()
endforeach()
# the forms of the other papers, no density diffusion, gravity with the body-force term
set(flow_variant_reece --var pressure=sum --var viscosity=morris --var delta=0)
set(flow_variant_cleary --var pressure=symmetric --var viscosity=cleary --var delta=0)
set(flow_variant_gravity --var body=-0.5)
set(flow_variant_fourtakas --var body=-0.5 --var fourtakas=yes)
foreach(variant reece cleary gravity fourtakas)
  sphthermal_state_test(flow.rates.quintic.${variant} state ${flow_input}
    ARGS ${flow_variant_${variant}} REF flow/rates.quintic.${variant}.ref)
endforeach()

# 2 and 4 ranks give the 1-rank result (to round-off)
foreach(np 2 4)
  foreach(variant default gravity)
    sphthermal_state_test(flow.mpi.${variant}.np${np} same ${flow_input}
      ARGS ${flow_variant_${variant}} NP ${np} RTOL 1e-12)
  endforeach()
endforeach()

# pairs of two wall particles get no flow terms: the same state (walls'
# forces too) whether or not neigh_modify excludes them
sphthermal_state_test(flow.wall_pairs_skipped same ${flow_input} ARGS --var2 exclude=no RTOL 1e-12)

# ------------------------------------------------------------ shared loop
# thermal flow in one pair loop: pair sph/harmonic/visc evaluating pair
# sph/cleary/heat's term ('loop shared', the default) gives what the two
# styles' own loops give ('loop own'), for every kernel, per-type and
# per-atom conductivities, the relaxation rates of fix sph/dt/reset, solid
# and fluid-like plates, newton off, 2-D and 3-D; and on 2 and 4 ranks
set(thermal_flow_input ${CMAKE_CURRENT_LIST_DIR}/in.thermal_flow)
set(shared_loop_default "")
set(shared_loop_relax --var relax=yes)
set(shared_loop_varying_k --var laws=varying --var relax=yes)
set(shared_loop_fluid_plates --var plates=fluid)
set(shared_loop_newton_off --var newton=off --var relax=yes)
set(shared_loop_3d --var dim=3 --var relax=yes)
set(shared_loop_quintic --var kernel=quintic --var laws=varying)
set(shared_loop_lucy --var kernel=lucy)
set(shared_loop_cubic_3d --var kernel=cubic --var dim=3)
# conduction on fewer type pairs than the flow (adiabatic plates)
set(shared_loop_fewer_pairs --var heat=fluid --var relax=yes)
foreach(variant default relax varying_k fluid_plates newton_off 3d quintic lucy cubic_3d
        fewer_pairs)
  sphthermal_state_test(flow.shared_loop.${variant} same ${thermal_flow_input}
    ARGS ${shared_loop_${variant}} --var2 loop=own RTOL 1e-12)
endforeach()
foreach(np 2 4)
  sphthermal_state_test(flow.shared_loop.mpi.np${np} same ${thermal_flow_input}
    ARGS ${shared_loop_varying_k} NP ${np} RTOL 1e-12)
endforeach()
# kernel 'same' (either pair, whichever comes first in the hybrid) gives
# what the kernel given twice gives, and the shared loop is still taken
foreach(which heat flow)
  sphthermal_state_test(flow.kernel_same.${which} same ${thermal_flow_input}
    ARGS --var same=${which} --var laws=varying --var2 same=none RTOL 1e-14)
  sphthermal_lammps_test(flow.kernel_same.${which}_shared_loop_taken ${thermal_flow_input}
    IN_BUILD_DIR VARS steps 0 same ${which} LABELS regression
    PASS "evaluated in the pair loop of sph/harmonic/visc")
endforeach()
# the shared loop is taken where it can be, and not with 'loop own' or an
# option that needs more than the pair (correction consistent)
set(shared_loop_taken "evaluated in the pair loop of sph/harmonic/visc")
set(shared_loop_not_taken "ERROR;evaluated in the pair loop")
sphthermal_lammps_test(flow.shared_loop.taken ${thermal_flow_input} IN_BUILD_DIR
  VARS steps 0 LABELS regression PASS ${shared_loop_taken})
sphthermal_lammps_test(flow.shared_loop.not_with_loop_own ${thermal_flow_input} IN_BUILD_DIR
  VARS steps 0 loop own LABELS regression FAIL ${shared_loop_not_taken})
sphthermal_lammps_test(flow.shared_loop.taken_fewer_pairs ${thermal_flow_input} IN_BUILD_DIR
  VARS steps 0 heat fluid LABELS regression PASS ${shared_loop_taken})
# per-atom conductivities on fewer type pairs would need a test per pair: own loops
sphthermal_lammps_test(flow.shared_loop.not_with_varying_k_on_fewer_pairs ${thermal_flow_input}
  IN_BUILD_DIR VARS steps 0 heat fluid laws varying LABELS regression FAIL ${shared_loop_not_taken})
sphthermal_lammps_test(flow.shared_loop.not_with_correction ${thermal_flow_input} IN_BUILD_DIR
  VARS steps 0 loop "shared correction consistent" LABELS regression
  FAIL ${shared_loop_not_taken})

# ------------------------------------------------------------ OpenMP
# the /omp styles (package omp, suffix omp) give the serial styles' rates
# to round-off on 2 and 3 threads: the shared loop with per-atom
# conductivities and relaxation rates, 2-D and 3-D; each style's own loop;
# the heat style's own loop with mean interface; with correction consistent
# (2-D and 3-D: the threads gather the pairs and make the factors, each its
# block) and second (threads read their slices of the stored factors); the
# flow style's correction gradient (3-D, its moments on the threads)
if(host_openmp)
  set(omp_shared --var laws=varying --var relax=yes)
  set(omp_shared_3d --var dim=3 --var relax=yes)
  set(omp_own --var loop=own --var relax=yes)
  set(omp_own_fewer_pairs --var loop=own --var heat=fluid --var relax=yes)
  set(omp_interface "--var" "loop=own mean interface")
  set(omp_correction "--var" "loop=own correction consistent")
  set(omp_correction_3d "--var" "loop=own correction consistent" --var dim=3)
  set(omp_second "--var" "loop=own correction second")
  set(omp_gradient "--var" "flow_keywords=correction gradient" --var dim=3 --var relax=yes)
  foreach(variant shared shared_3d own own_fewer_pairs interface correction correction_3d second
          gradient)
    foreach(threads 2 3)
      sphthermal_state_test(flow.omp.${variant}.threads${threads} same ${thermal_flow_input}
        ARGS ${omp_${variant}} --var2 threads=${threads} RTOL 1e-12 PROCESSORS 2)
    endforeach()
  endforeach()
  # sph/harmonic/visc/omp evaluates the term of sph/cleary/heat/omp in its
  # loop (the styles named with /omp in the hybrid)
  sphthermal_lammps_test(flow.omp.shared_loop_taken ${thermal_flow_input} IN_BUILD_DIR
    VARS steps 0 threads 2 LABELS regression PROCESSORS 2 PASS ${shared_loop_taken})
  # with MPI too: 2 ranks of 2 threads against 1 serial rank
  sphthermal_state_test(flow.omp.shared.np2_threads2 same ${thermal_flow_input}
    ARGS ${omp_shared} --var2 threads=2 NP 2 RTOL 1e-12)
endif()

# ------------------------------------------------------------ momentum
# total momentum conserved to 1e-12 over 1000 steps in a periodic box
set(momentum_message "relative change of sum\\(m v\\)")
foreach(mass pertype peratom)
  foreach(form averaged:adami sum:morris symmetric:cleary)
    string(REPLACE ":" ";" pv ${form})
    list(GET pv 0 pressure)
    list(GET pv 1 viscosity)
    sphthermal_lammps_test(flow.momentum.${mass}_mass.${viscosity} flow/in.momentum
      VARS mass ${mass} pressure ${pressure} viscosity ${viscosity}
      LABELS validation PASS ${momentum_message})
  endforeach()
endforeach()

# ------------------------------------------------------------ validation
# coarse versions of the flow examples, against exact solutions
foreach(case poiseuille:poiseuille_20 couette:couette_20 two-fluid-couette:two_fluid_couette_20
        hydrostatic:hydrostatic_20x40)
  string(REPLACE ":" ";" parts ${case})
  list(GET parts 0 example)
  list(GET parts 1 name)
  add_example_test(flow.validation.${name} flow-${example} quick ${name})
endforeach()

# the walls' surface (fix sph/wall/adami surface) from a jittered start stays
# laminar: the mirror image along the walls' normal, not the quadratic
add_example_test(flow.validation.poiseuille_surface_jitter_20 flow-poiseuille surface-jitter
  poiseuille_surface_jitter_20)

# Fourtakas's diffusion vanishes at hydrostatic balance, Molteni's does not:
# under fix gravity, fix sph/boussinesq's buoyancy (T0 given or 'mean'), both
sphthermal_python_test(flow.diffusion.hydrostatic flow/test_fourtakas.py
  ARGS $<TARGET_FILE:sph_state_host> ${SPHTHERMAL_PLUGIN} LABELS unit)
foreach(case buoyancy:300.0 both:300.0 buoyancy:mean both:mean)
  string(REPLACE ":" ";" parts ${case})
  list(GET parts 0 force)
  list(GET parts 1 t0)
  sphthermal_python_test(flow.diffusion.hydrostatic_${force}_${t0} flow/test_fourtakas.py
    ARGS $<TARGET_FILE:sph_state_host> ${SPHTHERMAL_PLUGIN} ${force} ${t0} LABELS unit)
endforeach()

# two fluids of density ratio 2, 10 and 1000: no diffusion across the
# interface, layered Couette flow stable with the defaults
sphthermal_python_test(flow.two_fluids.stable flow/test_two_fluids.py LAMMPS LABELS unit)
# the same layered under gravity: stable at the default timestep when the
# light fluid has the heavy one's rho0 c0^2, and the pair warns when it has not
sphthermal_python_test(flow.two_fluids.column flow/test_two_fluid_column.py LAMMPS LABELS validation)

# 'eos linear auto' without buoyancy: c0 = 10 times the scene's speed (the
# eos's 'speed', moving atoms, sqrt(g H)), one rho0 c0^2 for two fluids, and
# the background a flow without weight or buoyancy takes by default
sphthermal_python_test(flow.auto_sound_speed flow/test_auto_sound_speed.py LAMMPS
  ARGS --np 2 --mpirun ${MPIRUN} LABELS mpi PROCESSORS 2)

# fix sph/wall/adami 'surface': the walls extend a linear profile exactly
# (Couette flow from its steady profile), on 1, 2 and 4 ranks
sphthermal_python_test(flow.adami_surface flow/test_adami_surface.py LAMMPS LABELS unit)

# the adaptive timestep (fix sph/dt/reset)
include(${CMAKE_CURRENT_LIST_DIR}/dt_reset.cmake)

# ------------------------------------------------------------ restart
# a restart continues exactly (bitwise) as a second run would; the restart
# tests of one input write the same file next to it: one at a time
set(restart_lock RESOURCE_LOCK flow_restart_file)
sphthermal_state_test(flow.restart same flow/in.restart ARGS --var2 split=yes RTOL 0 ${restart_lock})
# a restart file whose pair settings have another layout is refused, not misread
sphthermal_python_test(flow.restart.version_head flow/test_restart_head.py LAMMPS
  ARGS --record ${error_sites_dir} LABELS regression)
set_property(GLOBAL APPEND PROPERTY sphthermal_error_tests flow.restart.version_head)
# the setting of mean_pressure comes back from the restart file
sphthermal_state_test(flow.restart.mean_pressure same flow/in.restart
  ARGS --var mean_pressure=2.5 --var2 split=yes RTOL 0 ${restart_lock})

# ------------------------------------------------------------ mean_pressure
# mean_pressure: the pair's offset is the fluid's volume-weighted mean
# pressure (from the equations of state in the input) less P; the control
# without the keyword (offset 0) must fail
sphthermal_lammps_test(flow.mean_pressure.offset ${flow_input} NO_FAIL
  VARS check_offset yes mean_pressure 3.5 offset_target 3.5 background 100 LABELS unit)
sphthermal_lammps_test(flow.mean_pressure.control ${flow_input} NO_FAIL
  VARS check_offset yes background 100 LABELS unit WILL_FAIL)
# with mean_pressure a background pressure added to every equation of state
# changes nothing (to round-off); without it, it changes the run (control)
sphthermal_state_test(flow.mean_pressure.background same ${flow_input}
  ARGS --var mean_pressure=0 --var2 background=500 RTOL 1e-9)
sphthermal_state_test(flow.mean_pressure.background_control same ${flow_input}
  ARGS --var2 background=500 RTOL 1e-9 WILL_FAIL)
foreach(np 2 4)
  sphthermal_state_test(flow.mpi.mean_pressure.np${np} same ${flow_input}
    ARGS --var mean_pressure=1.0 NP ${np} RTOL 1e-12)
endforeach()

# ------------------------------------------------------------ correction gradient
# correction gradient: the pressure force of a linear pressure field is
# -V grad p on a rectangular lattice (2-D, 3-D, every kernel), to 1e-6
# (measured 1.2e-7 and 1.6e-7: the test's density variation); the plain
# gradient is 3.1 % and 1.6 % off (controls)
foreach(kernel ${kernels})
  sphthermal_lammps_test(flow.gradient.linear.${kernel} flow/in.gradient NO_FAIL
    VARS kernel ${kernel} LABELS unit)
endforeach()
foreach(dim 2 3)
  sphthermal_lammps_test(flow.gradient.linear.dim${dim} flow/in.gradient NO_FAIL
    VARS dim ${dim} correction gradient LABELS unit)
  sphthermal_lammps_test(flow.gradient.linear.dim${dim}.control flow/in.gradient NO_FAIL
    VARS dim ${dim} correction none LABELS unit WILL_FAIL)
endforeach()
# ... it changes the flow regression system's run (else the above would not
# reach the pair loop), which stays the same on 2 and 4 ranks, with newton
# off, and across a restart; momentum is kept to round-off (jittered
# periodic box, per-atom masses)
sphthermal_state_test(flow.gradient.changes_run same ${flow_input}
  ARGS --var body=-0.5 --var2 correction=gradient RTOL 1e-9 WILL_FAIL)
foreach(np 2 4)
  sphthermal_state_test(flow.mpi.gradient.np${np} same ${flow_input}
    ARGS --var correction=gradient --var body=-0.5 NP ${np} RTOL 1e-12)
endforeach()
sphthermal_state_test(flow.gradient.newton same ${flow_input}
  ARGS --var correction=gradient --var body=-0.5 --var2 newton=off RTOL 1e-12)
sphthermal_state_test(flow.restart.gradient same flow/in.restart
  ARGS --var correction=gradient --var pressure=averaged --var2 split=yes RTOL 0 ${restart_lock})
sphthermal_lammps_test(flow.momentum.gradient flow/in.momentum
  VARS mass peratom correction gradient LABELS validation PASS ${momentum_message})

# ------------------------------------------------------------ bad input
add_error_cases(flow flow/errors.in)

# where Monaghan's artificial viscosity acts: at the free surface and at
# walls, not in the bulk; its default under fix gravity, none in a closed tank
sphthermal_python_test(flow.artificial_surface flow/test_artificial_surface.py LAMMPS LABELS unit)

# a dam break (examples/flow-dam-break) with the package's defaults (Monaghan's
# artificial viscosity under fix gravity):
# the front against Martin and Moyce's experiment, no particle lost through
# the far wall after the impact, 1 and 2 ranks
sphthermal_python_test(flow.dam_break flow/test_dam_break.py LAMMPS
  ARGS --np 2 --mpirun ${MPIRUN} LABELS validation mpi PROCESSORS 2)
