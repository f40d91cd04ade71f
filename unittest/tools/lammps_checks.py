"""Shared by the convection checks: run an input script through LAMMPS and
read what it wrote (the readers of tools/)."""

import argparse
import os
import subprocess
import sys
import tempfile

from sphthermal_tools.dump import read_frames
from cavity_fv import DE_VAHL_DAVIS  # noqa: F401
from sphthermal_tools import log as lammps_log
from sphthermal_tools.log import late_rows, longest_thermo_table, thermo_tables  # noqa: F401

from sphtest import Checks, lammps_arguments, mpi_env, mpi_prefix  # noqa: F401


def serial_check(doc):
    """The arguments of a serial check (--lmp, --plugin) and its Checks."""
    parser = argparse.ArgumentParser(description=doc)
    lammps_arguments(parser, ranks=False)
    return parser.parse_args(), Checks()


def final_nusselt(out, gradient=True):
    """sphthermal_tools.log.final_nusselt of a run's output; stops the check when
    the numbers are missing. gradient=False for a run that has no gradient
    estimate (in.cavity's zero-order walls)."""
    final = lammps_log.final_nusselt(out)
    if final is None or (gradient and final["gradient"] is None):
        sys.exit("FAIL: no final Nusselt numbers in the run's output")
    return final


def run_input(lmp, input_file, variables, cwd, np_=1, mpirun="mpirun", log="none"):
    """Run an input file with LAMMPS in cwd (on np_ ranks) with the given
    -var values; stop the check on an error."""
    command = mpi_prefix(np_, mpirun) + [os.path.abspath(lmp), "-log", log, "-in", input_file]
    for name, value in variables.items():
        command += ["-var", name, str(value)]
    proc = subprocess.run(command, cwd=cwd, text=True, capture_output=True, env=mpi_env())
    if proc.returncode != 0 or "ERROR" in proc.stdout:
        sys.stdout.write(proc.stdout + proc.stderr)
        sys.exit("FAIL: LAMMPS run failed")
    return proc.stdout


def run_lammps(lmp, script, cwd, np_=1, mpirun="mpirun"):
    """Run script (text) with LAMMPS in cwd (on np_ ranks); stop the check on
    an error."""
    with tempfile.NamedTemporaryFile("w", suffix=".in", dir=cwd, delete=False) as f:
        f.write(script)
        path = f.name
    try:
        return run_input(lmp, path, {}, cwd, np_, mpirun)
    finally:
        os.unlink(path)


def read_dump(path):
    """The last frame of a dump custom file: {column: array}, by atom id."""
    return read_frames(path)[-1][1]
