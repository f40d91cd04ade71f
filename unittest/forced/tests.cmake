# forced-convection tests (included by unittest/CMakeLists.txt after
# convection/tests.cmake, whose test_convection_terms they run; helpers:
# cmake/sphthermal_tests.cmake)
add_error_cases(forced forced/errors.in)
# fix sph/flowrate: a periodic channel from rest held at U, the drive
# against Poiseuille's 12 nu U / H^2 (measured -3.3 % at 20 across, -5.1 %
# at 10, -2.8 % at 40: Adami's walls and the viscous operator at h = 1.3 dx;
# with the walls' surface -2.7 %), the mean within 1.5e-4 of U; restart and ranks
set(flowrate_input ${CMAKE_CURRENT_LIST_DIR}/in.flowrate)
sphthermal_lammps_test(forced.flowrate.hold ${flowrate_input}
  VARS check hold n 20 steps 4000 tol 0.04 LABELS validation PASS "flowrate: hold passed")
sphthermal_state_test(forced.flowrate.restart same ${flowrate_input}
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}
  ARGS --var check=state --var steps=400 --var split=two --var2 split=yes RTOL 1e-12)
foreach(np 2 4)
  sphthermal_state_test(forced.flowrate.mpi.np${np} same ${flowrate_input}
    ARGS --var check=state --var steps=400 NP ${np} RTOL 1e-10)
endforeach()
sphthermal_unit_checks(forced.terms test_convection_terms deltaplus)
# the delta-plus shift: no shift on a lattice, a clustered set evens out,
# walls stay, T follows exactly for a linear field, rho the volume
foreach(check lattice spread linear follow volume)
  sphthermal_python_test(forced.shift.${check} convection/test_shift.py LAMMPS
    ARGS ${check} --form delta-plus LABELS unit)
endforeach()
sphthermal_python_test(forced.reference.channel_fv tools/test_channel_fv.py LABELS unit)
# Wendland C2, h = 2 dx at 40 across stays laminar with dt = 0.15 h / c0 and shifting
add_example_test(forced.validation.poiseuille_wendland_40 flow-poiseuille wendland
  poiseuille_wendland_40)
# the heated channel at Re = 65.2, 10 across, to t = 800 s against the
# finite-volume reference (measured with in.channel's defaults, the walls'
# surface, the fluid's volume held, no background pressure, the consistent
# conduction on the shifted fluid, fix sph/dt/reset's timestep, the
# shift's C = 0.5: 1.65 % of T_w - T_in at x = 5 m, 0.54 % at 50 m, 0.12 %
# at 100 m, |v| 0.023 % of u_max, flow rate -0.10 %; with C = 1 1.67, 0.55,
# 0.12 %; with the plain conduction (C = 1) 1.77, 0.70, 0.16 %;
# with Adami's mean and the mean density held by the shift 2.70, 1.30,
# 0.31 %, |v| 0.18 %, flow rate +2.84 %. The inlet ghosts held at T_inlet
# gave 1.06 % at x = 5 m with Adami's mean here but 1.47 % at 20 across)
add_example_test(forced.validation.channel_re65_10 forced-channel quick forced_channel_re65_10
  ENV MAX_T_ERROR=3.2 MAX_VY=0.3)
# the same channel with a true inlet and outlet (fix sph/open; in.channel's
# inlet = open: the parabolic profile and T_in enter at x = 0, the outlet at
# the background pressure, no body force; the shift's continuity on, the
# default for an open boundary's fluid; the walls beside the inlet's buffer
# at T_in), against the same reference (measured: 1.69 % of T_w - T_in at
# x = 5 m, 0.63 % at 50 m, 0.19 % at 100 m; |v| 2.1 % of u_max within a
# kernel of the outlet, 0.5 % elsewhere; flow rate +0.70 %)
add_example_test(forced.validation.open_re65_10 forced-channel quick forced_open_re65_10
  ENV INLET=open MAX_T_ERROR=3.2 MAX_VY=4)
# the thick-wall channel (10 m slabs, k_s = k) at Re = 65.2, 10 across, to
# t = 800 s against the conjugate finite-volume reference, fluid and slabs
# (measured with in.channel's defaults: 2.60 % of T_w - T_in at x = 5 m,
# 0.20, 0.13, 0.12, 0.10 % at x = 50 to 195 m, |v| 0.023 % of u_max, the
# same to 0.01 % with the shift's C = 1; with C = 1 and the plain
# conduction 2.57, 0.21, 0.35, 0.27, 0.20 %; with Adami's mean
# and the plain conduction 2.28, 1.13, 1.20, 0.87, 0.59 %. With the slab's outer
# dummies at the fluid's conductivity instead of the slab's, 5 % at 20
# across)
add_example_test(forced.validation.thick_re65_10 forced-channel thick forced_thick_re65_10
  ENV N=10 RE=65.2 TEND=800 KSK=1 MAX_T_ERROR=3.0 MAX_VY=0.3)
# Re = 652 stays laminar with delta-plus shifting (measured with in.channel's
# defaults, the shift's C = 0.5: |v| 0.0195 % of u_max at t = 60 s, 0.022 %
# at most; with C = 1 0.020 and 0.023 %; with a background pressure of 1 %
# 0.45 %; without shifting 24 %)
sphthermal_test(forced.validation.laminar_652 LABELS validation
  COMMAND ${CMAKE_CURRENT_LIST_DIR}/laminar.sh ${SPHTHERMAL_LMP} ${SPHTHERMAL_PLUGIN}
          ${PYTHON_NUMPY} ${CMAKE_CURRENT_BINARY_DIR}/forced_laminar_652 0.2)
# in.channel keeps the fluid's volume at every Reynolds number (no rule on
# Re); without it the mean density drifts under shifting
sphthermal_test(forced.examples.channel_volume LABELS regression
  COMMAND ${CMAKE_CURRENT_LIST_DIR}/channel_volume.sh ${SPHTHERMAL_LMP} ${SPHTHERMAL_PLUGIN}
          ${PYTHON_NUMPY} ${CMAKE_CURRENT_BINARY_DIR}/forced_channel_volume)
# a solid plate and a fluid-like one are the same wall to the flow (1 and 2 ranks)
foreach(np 1 2)
  set(labels unit)
  if(np GREATER 1)
    set(labels unit mpi)
  endif()
  sphthermal_python_test(forced.walls.solid_plate_np${np} forced/test_solid_plate.py LAMMPS
    ARGS --np ${np} --mpirun ${MPIRUN} LABELS ${labels} PROCESSORS ${np})
endforeach()
# in.exchanger goes on from its own restart file without setting its start again
sphthermal_python_test(forced.examples.exchanger_resume forced/test_exchanger_resume.py LAMMPS
  LABELS regression)
sphthermal_python_test(forced.examples.channel_resume forced/test_exchanger_resume.py LAMMPS
  ARGS --input channel LABELS regression)
foreach(check reservoir reenter balance walls restart mirror)
  sphthermal_python_test(forced.inlet.${check} forced/test_inlet.py LAMMPS ARGS ${check}
    LABELS unit)
endforeach()
# the inlet plane split between ranks along the flow; the shift's
# corrected rho and v with ghosts that only the shift brings up to date
foreach(np 2 4)
  sphthermal_python_test(forced.mpi.shift_follow_np${np} convection/test_shift.py LAMMPS
    ARGS follow --form delta-plus --np ${np} --mpirun ${MPIRUN} LABELS mpi PROCESSORS ${np})
  foreach(check reservoir balance mirror)
    sphthermal_python_test(forced.mpi.inlet_${check}_np${np} forced/test_inlet.py LAMMPS
      ARGS ${check} --np ${np} --mpirun ${MPIRUN} LABELS mpi PROCESSORS ${np})
  endforeach()
endforeach()
