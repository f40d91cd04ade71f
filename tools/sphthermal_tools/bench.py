"""Cost measures of the benchmarks (bench/flow, bench/forced): CPU time of
LAMMPS runs per particle-step."""

import os
import re
import resource
import subprocess

from .log import loop_runs


def cpu_seconds(cmd, workdir):
    """CPU time of a child process: on a shared machine wall time counts the
    waiting too."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(cmd, cwd=workdir, check=True, capture_output=True,
                   env=dict(os.environ, OMP_NUM_THREADS="1"))
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def cost(input_file, args, workdir, lmp_vars, whole_run=False):
    """Pair CPU time per particle-step (s) of input_file with lmp_vars, the
    fastest of args.repeat runs of args.lmp with args.plugin: the
    CPU time of the run (set-up included, a few % of it) times the pair's
    share of the loop time in LAMMPS's timing breakdown (whole_run: the
    run's CPU time per particle-step)."""
    cmd = [args.lmp, "-in", input_file, "-var", "plugin", args.plugin]
    for k, v in lmp_vars.items():
        if k != "steps":
            cmd += ["-var", k, str(v)]
    best = None
    for _ in range(args.repeat):
        total = cpu_seconds(cmd + ["-var", "steps", str(lmp_vars["steps"]), "-log", "log.lammps"],
                            workdir)
        log = open(os.path.join(workdir, "log.lammps")).read()
        _, steps, natoms = loop_runs(log)[-1]
        share = 1.0 if whole_run else \
            float(re.findall(r"^Pair\s+\|.*\|\s+([0-9.]+)\s*$", log, re.M)[-1]) / 100.0
        c = total * share / (steps * natoms)
        best = c if best is None or c < best else best
    return best
