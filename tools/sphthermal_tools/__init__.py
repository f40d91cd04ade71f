"""USER-SPHTHERMAL's Python tools, one package for examples, tests and benchmarks.

  log     thermo tables of a LAMMPS log or screen output, the cavity's Nusselt lines
  dump    LAMMPS 'dump custom' text files
  series  'fix ave/time' / 'fix print' files; time averages and steady state
  bench   the benchmarks' cost measure: CPU time of LAMMPS runs per particle-step

Put <repo>/tools on PYTHONPATH (the tests, the examples' run.sh and
tools/sphpython do; see tools/README.md) and import e.g. 'from sphthermal_tools.dump import read_frames'.
"""
