# Melting and solidification (fix sph/phase), included by unittest/CMakeLists.txt.

# the enthalpy law (sph_phase_laws.h) against the law written out, from C
add_header_test(test_phase_laws phase/test_phase_laws.c)
sphthermal_test(phase.laws LABELS unit COMMAND test_phase_laws)

# Neumann's Stefan problem (tools/stefan.py) on in.stefan: the melt's depth
# and T against the exact solution, the energy through the wall against the
# change of the particles' energies
set(phase_test phase/test_phase.py)
sphthermal_python_test(phase.stefan.one_phase ${phase_test} LAMMPS ARGS --check one_phase LABELS unit)
sphthermal_python_test(phase.stefan.two_phase ${phase_test} LAMMPS ARGS --check two_phase LABELS unit)
sphthermal_python_test(phase.stefan.conductivity_jump ${phase_test} LAMMPS ARGS --check conductivity_jump
  LABELS unit)
# the liquid's specific heat 2 and 0.5 times the solid's (cv_liquid)
sphthermal_python_test(phase.stefan.heat_capacity_jump ${phase_test} LAMMPS ARGS --check heat_capacity_jump
  LABELS unit)
sphthermal_python_test(phase.stefan.converging ${phase_test} LAMMPS ARGS --check converging
  LABELS regression)
sphthermal_python_test(phase.energy.mushy ${phase_test} LAMMPS ARGS --check mushy LABELS unit)
sphthermal_python_test(phase.energy.freezing ${phase_test} LAMMPS ARGS --check freezing LABELS unit)
# keyword mushy: the Carman-Kozeny damping as specified, solids held
sphthermal_python_test(phase.damping ${phase_test} LAMMPS ARGS --check damping LABELS unit)
# melting of gallium heated from one side, coarse (examples/phase-gallium):
# the melted volume and the fronts against the experiment and conduction,
# the solid at rest
sphthermal_python_test(phase.gallium phase/test_gallium.py LAMMPS LABELS validation)
# freezing in a cavity cooled from one side, coarse (examples/phase-freezing):
# with convection against the finite-volume reference (tools/phase_fv.py),
# without gravity against Neumann and the linear steady state
sphthermal_python_test(phase.freezing.convection phase/test_freezing.py LAMMPS ARGS --check convection
  LABELS validation)
sphthermal_python_test(phase.freezing.conduction phase/test_freezing.py LAMMPS ARGS --check conduction
  LABELS regression)
# the casting-like scene, coarse (examples/phase-casting): a shell on the
# chilled stretch only, thicker downstream, symmetric, at rest; the flow through
sphthermal_python_test(phase.casting phase/test_casting.py LAMMPS LABELS regression)
# a melt poured into a cold mould, coarse (examples/phase-casting/in.pour): the
# run-out against Martin and Moyce, the shell from the mould's walls, solids
# at rest, every particle kept, the energy books to round-off
sphthermal_python_test(phase.pour phase/test_pour.py LAMMPS LABELS regression)
sphthermal_python_test(phase.mpi.pour_np2 phase/test_pour.py LAMMPS
  ARGS --np 2 --mpirun ${MPIRUN} LABELS mpi PROCESSORS 2)
foreach(np 2 4)
  sphthermal_python_test(phase.mpi.np${np} ${phase_test} LAMMPS
    ARGS --check mpi --np ${np} --mpirun ${MPIRUN} LABELS mpi PROCESSORS ${np})
endforeach()

add_error_cases(phase ${CMAKE_CURRENT_LIST_DIR}/errors.in)
