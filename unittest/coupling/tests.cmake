# coupling tests (included by unittest/CMakeLists.txt after flow/tests.cmake,
# whose test_flow_terms they run; helpers: cmake/sphthermal_tests.cmake)

# the heating and expansion terms of sph_flow.h
sphthermal_unit_checks(coupling.terms test_flow_terms heating expansion)

# viscous heating (pair sph/harmonic/visc heating): at the first force
# evaluation the heating rate is the viscous work, to round-off
foreach(case adami:pertype morris:pertype cleary:pertype adami:peratom)
  string(REPLACE ":" ";" parts ${case})
  list(GET parts 0 viscosity)
  list(GET parts 1 mass)
  sphthermal_lammps_test(coupling.heating.balance.${viscosity}.${mass} coupling/in.heating
    VARS viscosity ${viscosity} mass ${mass} heating 0.7 LABELS unit PASS "balance: heating rate")
endforeach()
# ... and kinetic + thermal + elastic energy of a decaying shear wave stays
# within 1e-5 of the energy dissipated (6e-6 at dt = 5e-4, 4e-6 at 2.5e-4:
# the time integration's; without heating the change is -1.02)
foreach(case 0.0005:400 0.00025:800)
  string(REPLACE ":" ";" parts ${case})
  list(GET parts 0 dt)
  list(GET parts 1 steps)
  sphthermal_lammps_test(coupling.heating.energy.dt${dt} coupling/in.heating
    VARS check energy dt ${dt} steps ${steps} jitter 0 fraction2 0 viscous 1000
         pressure symmetric background 50
    LABELS validation PASS "energy: kinetic energy lost")
endforeach()
# the flow regression system (two fluids, fixed and sliding Adami walls,
# gravity) with heating: 2 and 4 ranks give the 1-rank state
foreach(np 2 4)
  sphthermal_state_test(coupling.mpi.heating.np${np} same ${flow_input}
    ARGS --var heating=1 --var body=-0.5 --var steps=20 NP ${np} RTOL 1e-12)
endforeach()
# ... and with thermal expansion in every equation of state (temperatures
# varying by 10 %)
foreach(np 2 4)
  sphthermal_state_test(coupling.mpi.expansion.np${np} same ${flow_input}
    ARGS --var expansion=1e-3 --var body=-0.5 --var steps=20 NP ${np} RTOL 1e-12)
endforeach()
# the reference of the cooling cylinder (radial conjugate conduction)
sphthermal_python_test(coupling.reference.conjugate_cylinder tools/test_conjugate_cylinder.py
  LABELS unit)
# the reference of the settling disc (Taylor-Hood Stokes drag in a channel)
sphthermal_python_test(coupling.reference.cylinder_stokes tools/test_cylinder_stokes.py
  LABELS unit)
# a hot steel disc (a rigid body) cooling in water against the radial
# conjugate reference: within 1 % of the 60 K difference (measured 0.45 %)
add_example_test(coupling.validation.cooling_cylinder_10 coupling-cooling-cylinder quick
  cooling_cylinder_10)
# the showcase at 3 particles per radius: three hot discs with a contact pair
# settle onto the floor without overlapping (closest approach above 0.6 dx; measured 0.78)
# and the heat they give off rises above them
add_example_test(coupling.showcase.bodies_3 coupling-hot-bodies quick bodies_3)
# a neutral disc held in a tank of water under gravity for 0.2 s: its SPH
# pressure force equals the exact force of the water's own (linear) pressure
# field on its area to 0.5 % of its weight (measured 0.21 %; against
# rho0 g V, the exact buoyancy, it is 5 % off: the water's gradient is)
add_example_test(coupling.validation.neutral_force coupling-settling quick neutral_force)
# a neutral disc released into a tank of water at rest under gravity (the
# hydrostatic set-up, no settling) stays at rest: with correction gradient
# it moves less than 0.1 dx in 0.25 s (measured 0.048 dx); with the plain
# gradient it rises 0.62 dx (the control, which must fail)
add_example_test(coupling.validation.neutral_rest coupling-settling rest neutral_rest)
add_example_test(coupling.validation.neutral_rest_plain coupling-settling rest_plain
  neutral_rest_plain WILL_FAIL)
# a steel disc settling in a closed channel of viscous oil (R = 4 dx, the oil
# weightless, its mean pressure held): its speed from 0.05 to 0.15 s after
# the release within 8 % of the Stokes reference of tools/cylinder_stokes.py
# (measured +6.4 to +6.8 %) and steady (its error drifts by -0.06 %; without
# mean_pressure by -2.6 %, which fails the 1.5 % bound)
add_example_test(coupling.validation.settling_channel_4 coupling-settling-channel quick
  settling_channel_4)
# rigid bodies of SPH particles (fix rigid, fix rigid/small) in a periodic
# box of fluid: momentum of bodies plus fluid and their thermal energy kept
# to round-off, 2 and 4 ranks as 1, a restart continues bitwise
set(body_input ${CMAKE_CURRENT_LIST_DIR}/in.body)
set(in_build_dir WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
foreach(rigid rigid rigid/small)
  string(REPLACE "/" "_" name ${rigid})
  sphthermal_lammps_test(coupling.body.momentum.${name} ${body_input} ${in_build_dir}
    VARS rigid ${rigid} LABELS validation PASS "momentum: relative change")
endforeach()
sphthermal_lammps_test(coupling.body.thermal ${body_input} ${in_build_dir}
  VARS check thermal LABELS validation PASS "thermal: heat given off")
foreach(np 2 4)
  sphthermal_state_test(coupling.mpi.body.np${np} same ${body_input}
    ARGS --var check=state --var steps=100 NP ${np} RTOL 1e-12)
endforeach()
sphthermal_state_test(coupling.body.restart same ${body_input} ${in_build_dir}
  ARGS --var check=state --var steps=100 --var split=no --var2 split=yes RTOL 0)
add_error_cases(coupling coupling/errors.in)
