# conduction tests (included by unittest/CMakeLists.txt; helpers: cmake/sphthermal_tests.cmake)

# ------------------------------------------------------------ C terms
add_header_test(test_conduction_terms conduction/test_conduction_terms.c)
sphthermal_unit_checks(conduction.terms test_conduction_terms symmetry limits conservation interface choice)

add_header_test(test_material_laws conduction/test_material_laws.c)
sphthermal_test(conduction.laws LABELS unit COMMAND test_material_laws)

# the consistency correction (sph_consistent.h) and the second-moment weights
# (sph_second_moment.h) on jittered lattices, and its C++ twin
add_header_test(test_consistent_terms conduction/test_consistent_terms.c C_EXTENSIONS OFF)
add_header_test_cxx(test_consistent_terms_cxx conduction/test_consistent_terms_cxx.cpp)
foreach(check inverse eigen factors cholesky)
  sphthermal_unit_checks(conduction.disorder test_consistent_terms ${check})
  sphthermal_unit_checks(conduction.disorder.cxx test_consistent_terms_cxx ${check})
endforeach()
foreach(check linear quadratic conservation second regularised coarse two-level)
  foreach(dim 2 3)
    sphthermal_test(conduction.disorder.${check}.${dim}d LABELS unit
                    COMMAND test_consistent_terms ${check} ${dim})
    sphthermal_test(conduction.disorder.cxx.${check}.${dim}d LABELS unit
                    COMMAND test_consistent_terms_cxx ${check} ${dim})
  endforeach()
endforeach()

# ------------------------------------------------------------ rates
# regression: T, desph, rho, drho after 5 steps against stored references,
# newton on and off against the same reference
foreach(kernel ${kernels})
  foreach(newton on off)
    sphthermal_state_test(conduction.rates.${kernel}.newton_${newton} state ${rates_input}
      ARGS --var kernel=${kernel} --var newton=${newton} REF conduction/rates.${kernel}.ref)
  endforeach()
endforeach()

# the variants of the pair: the papers' forms differ in the mean and in eta
set(variant_harmonic_eta0 --var mean=harmonic --var eta=0)
set(variant_arithmetic --var mean=arithmetic --var eta=0)
set(variant_varying_k --var laws=varying)
set(variant_isothermal_wall --var wall=yes --var laws=varying)
set(variant_dirichlet_wall --var wall=dirichlet --var laws=varying)
foreach(variant harmonic_eta0 arithmetic varying_k isothermal_wall dirichlet_wall)
  sphthermal_state_test(conduction.rates.cubic.${variant} state ${rates_input}
    ARGS --var kernel=cubic ${variant_${variant}} REF conduction/rates.cubic.${variant}.ref)
endforeach()

# desph at step 0 against Cleary 1998, eq 6, evaluated independently in Python
foreach(kernel ${kernels})
  sphthermal_state_test(conduction.eq6.${kernel} eq6 ${rates_input} ARGS --kernel ${kernel})
endforeach()
sphthermal_state_test(conduction.eq6.wendland.harmonic_eta0 eq6 ${rates_input}
  ARGS --kernel wendland --eta 0)
sphthermal_state_test(conduction.eq6.quintic.arithmetic eq6 ${rates_input}
  ARGS --kernel quintic --mean arithmetic --eta 0)
sphthermal_state_test(conduction.eq6.cubic.varying_k eq6 ${rates_input}
  ARGS --kernel cubic --laws varying)

# ------------------------------------------------------------ energy
set(drift_message "relative drift of sum\\(m esph\\)")
# sum(m esph) conserved to 1e-12 over 1000 steps, adiabatic boundaries
foreach(mass pertype peratom)
  sphthermal_lammps_test(conduction.energy.${mass}_mass conduction/in.conservation
    VARS mass ${mass} LABELS validation PASS ${drift_message})
endforeach()
# a k = 0 column (Reece et al. 2024, eq 17) passes no heat: each side keeps its energy
sphthermal_lammps_test(conduction.energy.zero_k_wall conduction/in.conservation
  VARS wall k0 LABELS validation PASS ${drift_message})

# isothermal and Dirichlet walls on 1, 2 and 4 ranks
foreach(wall isothermal_wall dirichlet_wall)
  foreach(np 2 4)
    sphthermal_state_test(conduction.mpi.${wall}.np${np} same ${rates_input}
      ARGS --var kernel=cubic ${variant_${wall}} NP ${np} RTOL 1e-12)
  endforeach()
endforeach()

# ------------------------------------------------------------ disorder
# pair sph/cleary/heat correction consistent on jittered particles
# (conduction/in.disorder): the Laplacian of a linear field vanishes once the
# sweeps have converged, and with the default 5 sweeps it and the quadratic
# field's error stay within their measured values (plain: 0.46 and 5.0);
# correction second (sph_second_moment.h, regularised) within twice its
# measured errors (linear 5.2e-4, quadratic 6.0e-3)
foreach(case "linear_exact;linear;consistent;3000;1e-10"
             "linear_5_sweeps;linear;consistent;5;0.03"
             "quadratic_5_sweeps;quadratic;consistent;5;0.35"
             "quadratic_converged;quadratic;consistent;3000;0.18"
             "second_linear;linear;second;5;1e-3" "second_quadratic;quadratic;second;5;0.012")
  list(GET case 0 name)
  list(GET case 1 field)
  list(GET case 2 correction)
  list(GET case 3 sweeps)
  list(GET case 4 max_error)
  sphthermal_lammps_test(conduction.disorder.${name} conduction/in.disorder
    VARS field ${field} correction ${correction} sweeps ${sweeps} max_error ${max_error}
    LABELS unit PASS "largest relative error")
endforeach()
# volumes that do not tile the plane (in.conservation's random m and rho):
# no weights have the lattice's moments, and correction second says so
sphthermal_lammps_test(conduction.disorder.second_not_converged conduction/in.conservation
  VARS correction second LABELS unit
  PASS "WARNING: Pair style sph/cleary/heat: correction second: the multipliers reached a residual of")
# sum(m esph) to 1e-12 over 1000 steps with the correction (jittered, three
# materials, k(T), per-atom mass)
sphthermal_lammps_test(conduction.disorder.energy conduction/in.conservation
  VARS correction consistent LABELS validation PASS ${drift_message})
# the same state on 1, 2 and 4 ranks, with newton on and off, and across a
# restart (correction second: a restart here; ranks and newton with
# conduction/in.interface, whose volumes tile the plane so that the
# multipliers converge)
foreach(np 2 4)
  sphthermal_state_test(conduction.disorder.mpi.np${np} same ${rates_input}
    ARGS --var correction=consistent --var steps=20 NP ${np} RTOL 1e-12)
endforeach()
sphthermal_state_test(conduction.disorder.newton_off same ${rates_input}
  ARGS --var correction=consistent --var2 newton=off RTOL 1e-12)
# the restart tests of one input write the same file next to it: one at a time
set(restart_lock RESOURCE_LOCK conduction_restart_file)
sphthermal_state_test(conduction.disorder.restart same conduction/in.restart
  ARGS --var correction=consistent --var2 split=yes RTOL 0 ${restart_lock})
sphthermal_state_test(conduction.disorder.restart.second same conduction/in.restart
  ARGS --var correction=second --var2 split=yes RTOL 0 ${restart_lock})
sphthermal_state_test(conduction.disorder.newton_off.second same conduction/in.interface
  ARGS --var steps=5 --var jitter=0.2 --var correction=second --var2 newton=off RTOL 1e-12)

# ------------------------------------------------------------ interface
# pair sph/cleary/heat mean interface (conduction/in.interface): the distance
# from the interface is exact on a lattice cut between two columns (and given
# to exactly the 48 atoms with a neighbour of the other material), within a
# tenth of a spacing on particles jittered by 0.2 spacings (measured 0.047)
# (estimated); with 'distance d_interface' the true distances, as given
foreach(case "lattice;0;1e-10;estimated" "jitter;0.2;0.1;estimated" "given;0.2;1e-12;given")
  list(GET case 0 name)
  list(GET case 1 jitter)
  list(GET case 2 max_error)
  list(GET case 3 distance)
  sphthermal_lammps_test(conduction.interface.${name} conduction/in.interface
    VARS jitter ${jitter} max_error ${max_error} distance ${distance}
    LABELS unit PASS "largest error of the interface distance")
endforeach()
# sum(m esph) to 1e-12 with the interface conductance (three materials, k(T),
# with and without the correction)
foreach(correction none consistent second)
  sphthermal_lammps_test(conduction.interface.energy_${correction} conduction/in.conservation
    VARS mean interface correction ${correction} LABELS validation PASS ${drift_message})
endforeach()
# the same state on 1, 2 and 4 ranks (constant and temperature-dependent
# conductivities), with newton on and off, and across a restart
foreach(np 2 4)
  foreach(laws constant varying)
    sphthermal_state_test(conduction.interface.mpi.${laws}.np${np} same ${rates_input}
      ARGS --var mean=interface --var laws=${laws} --var steps=20 NP ${np} RTOL 1e-12)
  endforeach()
endforeach()
# moving particles (conduction/in.interface, steps 50): the distances and the
# correction's factors made anew every step, atoms changing ranks
# (correction second: 5 steps, each a new solve of 1 s on one rank)
foreach(np 2 4)
  foreach(correction none consistent second)
    set(steps 50)
    if(correction STREQUAL "second")
      set(steps 5)
    endif()
    sphthermal_state_test(conduction.interface.mpi.moving_${correction}.np${np} same
      conduction/in.interface NP ${np} RTOL 1e-12
      ARGS --var steps=${steps} --var jitter=0.2 --var correction=${correction})
  endforeach()
endforeach()
sphthermal_state_test(conduction.interface.newton_off same ${rates_input}
  ARGS --var mean=interface --var correction=consistent --var2 newton=off RTOL 1e-12)
sphthermal_state_test(conduction.interface.restart same conduction/in.restart
  ARGS --var mean=interface --var2 split=yes RTOL 0 ${restart_lock})
# the given distances (fix property/atom) come back from the restart file
sphthermal_state_test(conduction.interface.restart.given same conduction/in.restart
  ARGS --var mean=interface --var distance=given --var2 split=yes RTOL 0 ${restart_lock})

# ------------------------------------------------------------ heat flux, surface
# compute sph/heatflux/atom: exact flux of a linear field with the correction
sphthermal_lammps_test(conduction.heatflux.linear_field conduction/in.gradient
  LABELS unit PASS "largest deviation of -k grad T")

# fix sph/surface/flux: heat added = energy gained (in.surface), and T against
# the finite-volume solution (thresholds: measured 0.21 % and 0.10 %)
foreach(mode_limit flux:0.4 convection:0.3)
  string(REPLACE ":" ";" pair_ "${mode_limit}")
  list(GET pair_ 0 mode)
  list(GET pair_ 1 limit)
  sphthermal_python_test(conduction.surface.${mode} tools/check_surface_flux.py LAMMPS
    ARGS --mode ${mode} --max-error ${limit} LABELS validation)
endforeach()

# ------------------------------------------------------------ restart, ranks
# a restart continues exactly (bitwise) as a second run would
sphthermal_state_test(conduction.restart same conduction/in.restart
  ARGS --var2 split=yes RTOL 0 ${restart_lock})

# mpi: 2 and 4 ranks give the 1-rank result (to round-off)
foreach(np 2 4)
  sphthermal_state_test(conduction.mpi.np${np} same ${rates_input}
    ARGS --var kernel=wendland --var laws=varying NP ${np} RTOL 1e-12)
endforeach()

# ------------------------------------------------------------ bad input
add_error_cases(conduction conduction/errors.in)

# ------------------------------------------------------------ validation
# the finite-volume reference of the validation tests, against exact solutions
sphthermal_python_test(conduction.reference.fv1d tools/test_fv1d.py LABELS unit)

# jittered two-material slab (examples/conduction-disorder): correction consistent
# within its measured error (0.94 % of the jump; plain 2.8 %), energy to 1e-12
add_example_test(conduction.disorder.slab_jitter conduction-disorder quick disorder_slab)
# the steel/water slab on the lattice, plain with h = dx: below 0.5 % of the jump at t1
# and 10 t1 (measured 0.469 % and 0.054 %; 0.73 % at t1 with h = 1.3 dx)
add_example_test(conduction.disorder.steel_water conduction-disorder steel-water
  disorder_steel_water)

add_example_test(conduction.validation.erf_40x10 conduction-erf quick erf_40x10)

add_example_test(conduction.validation.sinusoid_20x20 conduction-sinusoid quick sinusoid_20x20)
add_example_test(conduction.mpi.sinusoid_20x20.np2 conduction-sinusoid quick sinusoid_20x20_np2
  ENV NP=2 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 LABELS mpi PROCESSORS 2)

add_example_test(conduction.validation.two_materials_40x10 conduction-two-materials quick
  two_materials_40x10)
add_example_test(conduction.validation.dirichlet_square conduction-dirichlet-square quick
  dirichlet_square)
add_example_test(conduction.validation.exp_k_40x4 conduction-exp-k quick exp_k_40x4)
add_example_test(conduction.validation.cooled_slab_20x20 conduction-cooled-slab quick
  cooled_slab_20x20)
add_example_test(conduction.validation.three_solids_40x10 conduction-three-solids quick
  three_solids_40x10)
# mean interface on the composite wall with h = 1.3 dx (pairs reach two columns
# across each interface): steady error below 0.02 % (harmonic mean: 0.087 %)
add_example_test(conduction.interface.three_solids_40x10 conduction-three-solids interface
  three_solids_interface)

# the boundary set-up tool (Cleary 1998, section 3.5) and the disc it builds
sphthermal_test(conduction.setup.sph_boundary LABELS unit
  COMMAND ${CMAKE_COMMAND} -E env LMP=${SPHTHERMAL_LMP}
          ${PYTHON_NUMPY} ${SPHTHERMAL_TESTS_DIR}/tools/test_sph_boundary.py)
add_example_test(conduction.validation.disc_30 conduction-disc quick disc_30)
