"""Test runner for USER-SPHTHERMAL (called by ctest, see unittest/CMakeLists.txt).

  state   run an input through a sph_state driver and compare every atom's
          T, desph, rho, drho with a stored reference (--generate writes it)
  same    run an input through two drivers (or rank counts) and compare them
  error   run one case of an error-case file and expect its LAMMPS error
          (or, with '## warning:', its WARNING and a run that goes on)
  branches  every error and warning call of the package's sources is raised
          by an error case (the sites the cases recorded)
  styles  load the plugin and check that 'plugin list' shows every style
          the package's headers declare
  exports check that the plugin exports lammpsplugin_init and no LAMMPS symbol
  eq6     recompute desph of in.rates at step 0 from Cleary 1998, eq 6, in plain
          Python (an independent oracle for the pair style)
"""

import argparse
import math
import os
import re
import subprocess
import sys
import tempfile

import numpy as np

COLUMNS = ["T", "desph", "rho", "drho"]
RATES = ["desph", "drho", "fx", "fy"]


def mpi_prefix(np_, mpirun):
    if np_ <= 1:
        return []
    return [mpirun, "--oversubscribe", "-np", str(np_)]


def lammps_arguments(parser, mpi=True, ranks=True):
    """The options every test that runs LAMMPS takes: --lmp, --plugin and, with mpi, --np, --mpirun.
    ranks=False leaves --np out (for a script that declares it on a subcommand)."""
    parser.add_argument("--lmp", required=True)
    parser.add_argument("--plugin", required=True)
    if mpi:
        if ranks:
            parser.add_argument("--np", type=int, default=1)
        parser.add_argument("--mpirun", default="mpirun")
    return parser


class Checks:
    """check(ok, message): prints each check and keeps the failed ones."""

    def __init__(self):
        self.failures = []

    def __call__(self, ok, message):
        print(("ok   " if ok else "FAIL ") + message)
        if not ok:
            self.failures.append(message)


def finish(failures):
    """Exit with the failed checks named, or print ok."""
    if failures:
        sys.exit("FAIL: " + ", ".join(failures))
    print("ok")


def mpi_env():
    env = dict(os.environ)
    # Open MPI refuses root unless told; CI containers often run as root
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    env.setdefault("OMP_NUM_THREADS", "1")
    return env


def run_script(lmp, text):
    """Run an input given as text in a scratch directory; (return code, output)."""
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "in.script")
        with open(path, "w") as f:
            f.write(text)
        proc = subprocess.run([lmp, "-log", "none", "-in", path], cwd=tmp, capture_output=True,
                              text=True, env=mpi_env())
    return proc.returncode, proc.stdout + proc.stderr


def run_state(driver, input_file, lmp_vars, np_=1, mpirun="mpirun"):
    """Run the driver; return {column: [values]} sorted by atom id."""
    fd, out = tempfile.mkstemp(suffix=".state")
    os.close(fd)
    values = dict(v.split("=", 1) for v in lmp_vars)  # a later name=value overrides
    args = [word for name, value in values.items() for word in ("-var", name, value)]
    cmd = mpi_prefix(np_, mpirun) + [os.path.abspath(driver), out, os.path.abspath(input_file)] + args
    proc = subprocess.run(cmd, cwd=os.path.dirname(os.path.abspath(input_file)),
                          env=mpi_env(), capture_output=True, text=True)
    if proc.returncode != 0:
        sys.stderr.write(proc.stdout + proc.stderr)
        sys.exit(f"FAIL: {' '.join(cmd)} exited with {proc.returncode}")
    with open(out) as f:
        text = f.read()
    os.unlink(out)
    return text


def parse_state(text):
    """Columns by the names of the '# id type ...' header line (older
    references have fewer columns than the driver writes now)."""
    lines = text.splitlines()
    header = lines[0].lstrip("# ").split() if lines and lines[0].startswith("#") else \
        ["id", "type", "x", "y", "z"] + COLUMNS
    rows = [line.split() for line in lines if line and not line.startswith("#")]
    return {name: [float(r[c]) for r in rows] for c, name in enumerate(header)}


def compare(ref, new, rtol, label):
    """Largest deviation per column, scaled by the column's largest magnitude."""
    if len(ref["id"]) != len(new["id"]):
        print(f"FAIL {label}: {len(new['id'])} atoms, reference has {len(ref['id'])}")
        return False
    ok = True
    for name in [c for c in ref if c not in ("id", "z")]:
        if name not in new:
            print(f"FAIL {label}: no column {name}")
            return False
        scale = max(abs(v) for v in ref[name]) or 1.0
        worst = max(abs(a - b) for a, b in zip(ref[name], new[name])) / scale
        status = "ok" if worst <= rtol else "FAIL"
        ok = ok and worst <= rtol
        print(f"{status:4} {label}: {name:6} largest deviation {worst:.3e} of max |{name}| = {scale:.6g}"
              f" (tolerance {rtol:.1e})")
    return ok


def cmd_state(a):
    text = run_state(a.driver, a.input, a.var, a.np, a.mpirun)
    if a.generate:
        with open(a.ref, "w") as f:
            f.write(text)
        print("wrote", a.ref)
        return 0
    with open(a.ref) as f:
        ref = parse_state(f.read())
    new = parse_state(text)
    # the test must be able to fail: rates the reference has must not vanish
    for name in RATES:
        if name in ref and max(abs(v) for v in ref[name]) > 0.0 and \
                max(abs(v) for v in new[name]) == 0.0:
            print(f"FAIL: every {name} is zero")
            return 1
    return 0 if compare(ref, new, a.rtol, os.path.basename(a.ref)) else 1


def cmd_same(a):
    first = parse_state(run_state(a.driver, a.input, a.var, a.np, a.mpirun))
    second = parse_state(run_state(a.driver2 or a.driver, a.input, a.var + a.var2, a.np2, a.mpirun))
    return 0 if compare(first, second, a.rtol, "second run against first") else 1


def read_error_cases(path):
    """Cases: '## name: X' and '## expect: regex' lines, then input lines.
    Lines before the first case are the preamble, used unless '## preamble: no'."""
    preamble, cases, current = [], {}, None
    with open(path) as f:
        for line in f.read().splitlines():
            m = re.match(r"##\s*(name|expect|warning|preamble):\s*(.*)$", line)
            if m and m.group(1) == "name":
                current = {"expect": None, "warning": None, "preamble": True, "lines": []}
                cases[m.group(2).strip()] = current
            elif m and current is not None:
                if m.group(1) in ("expect", "warning"):
                    current[m.group(1)] = m.group(2).strip()
                else:
                    current["preamble"] = m.group(2).strip() != "no"
            elif current is None:
                preamble.append(line)
            else:
                current["lines"].append(line)
    return preamble, cases


def cmd_error(a):
    preamble, cases = read_error_cases(a.cases)
    if a.list:
        print("\n".join(cases))
        return 0
    case = cases[a.name]
    defines = [f"variable plugin index {a.plugin}", f"variable potentials index {a.potentials}",
               f"variable cases_dir index {os.path.dirname(os.path.abspath(a.cases))}"]
    lines = defines + preamble if case["preamble"] else defines
    script = "\n".join(lines + case["lines"]) + "\n"
    with tempfile.NamedTemporaryFile("w", suffix=".in") as f:
        f.write(script)
        f.flush()
        proc = subprocess.run(mpi_prefix(a.np, a.mpirun) +
                              [a.lmp, "-log", "none", "-echo", "screen", "-in", f.name], text=True,
                              capture_output=True, env=mpi_env())
    output = proc.stdout + proc.stderr
    lines = output.splitlines()
    errors = [line for line in lines if line.startswith("ERROR")]
    record = record_path(a.record, a.cases, a.name) if a.record else None
    if record and os.path.exists(record):
        os.remove(record)

    def passed(line):
        # the package's call site that raised the expected message
        if record:
            record_site(record, a.plugin, output, line)
        print(f"ok {a.name}: {line}")
        return 0

    if case["warning"]:
        # a misuse that can be legitimate: the run goes on, with this warning
        warnings = [line for line in output.splitlines() if line.startswith("WARNING")]
        found = [w for w in warnings if re.search(case["warning"], w)]
        if errors or proc.returncode != 0 or not found:
            print(output)
            print(f"FAIL {a.name}: expected a WARNING /{case['warning']}/ and a run without error")
            return 1
        return passed(found[0])
    if not errors:
        print(output)
        print(f"FAIL {a.name}: no LAMMPS error, expected /{case['expect']}/")
        return 1
    if not re.search(case["expect"], errors[0]):
        print(output)
        print(f"FAIL {a.name}: first error is\n  {errors[0]}\nexpected /{case['expect']}/")
        return 1
    if a.np > 1 and not errors[0].startswith("ERROR on proc"):
        # a stop on one rank of several names that rank (SPHCheck::stop)
        print(output)
        print(f"FAIL {a.name}: on {a.np} ranks the first error does not name its rank:\n  {errors[0]}")
        return 1
    return passed(errors[0])


# the place in the package's sources where a message was raised: LAMMPS ends
# every ERROR and WARNING with "(path/file.cpp:line)", the FLERR of the call
SITE = re.compile(r"\(([^()\s:]+\.(?:cpp|h)):(\d+)\)")


def message_site(output, first_line):
    """The site (file name, line) at the end of the message that starts at
    output line first_line (a message may span lines), or None."""
    lines = output.splitlines()
    for k in range(first_line, len(lines)):
        if k > first_line and re.match(r"(ERROR|WARNING)", lines[k]):
            break
        m = SITE.search(lines[k])
        if m:
            return os.path.basename(m.group(1)), int(m.group(2))
    return None


# the calls of the package that stop a run or warn, each with the FLERR of
# its line: LAMMPS's error->all/one/warning and the package's own helpers
# that raise with the caller's FLERR (SPHCheck::..., SPHCompat::...)
CALL = re.compile(r"(?:error->(?:all|one|warning)|SPHCheck::\w+|SPHCompat::\w+)\s*\(\s*"
                  r"(?:(?:lmp|error)\s*,\s*)?FLERR\b")


def error_sites(package):
    """Every (file name, line) of an error or warning call in the package's
    sources, with the text of that line."""
    sites = {}
    for name in sorted(os.listdir(package)):
        if not name.endswith((".cpp", ".h")):
            continue
        with open(os.path.join(package, name)) as f:
            text = f.read()
        lines = text.splitlines()
        for m in CALL.finditer(text):
            line = text.count("\n", 0, m.end()) + 1    # the line of FLERR
            sites[(name, line)] = lines[line - 1].strip()
    return sites


def plugin_stamp(plugin):
    """The build of the plugin a site was recorded with (a rebuilt plugin may
    have its calls on other lines)."""
    st = os.stat(plugin)
    return f"{st.st_mtime_ns}:{st.st_size}"


def record_path(records, cases, name):
    area = os.path.basename(os.path.dirname(os.path.abspath(cases)))
    stem = os.path.splitext(os.path.basename(cases))[0]
    return os.path.join(records, f"{area}.{stem}.{name}.site")


def record_site(record, plugin, output, message):
    """For robust.error_branches: write to the file 'record' the package's
    source line that raised the ERROR or WARNING line of 'output' holding
    'message', with the build of the plugin; a test that checks a message
    outside the case files calls this (with a record path of its own in the
    records directory). Returns the site or None."""
    lines = output.splitlines()
    for k, line in enumerate(lines):
        if message in line and re.match(r"(ERROR|WARNING)", line):
            site = message_site(output, k)
            if site:
                os.makedirs(os.path.dirname(record), exist_ok=True)
                with open(record, "w") as f:
                    f.write(f"{site[0]} {site[1]} {plugin_stamp(plugin)}\n")
            return site
    return None


def cmd_branches(a):
    """Every error and warning call of the package's sources is raised by
    one of the error cases at least: the sites (file:line) the cases'
    messages were raised at, recorded by 'error --record', cover every
    call site. A case that failed or did not run records nothing; a record
    of another build of the plugin does not count."""
    sites = error_sites(a.package)
    stamp = plugin_stamp(a.plugin)
    covered = {}
    # the error cases' records, and those of the tests that check a message
    # outside the case files (e.g. flow.restart.version_head)
    for name in sorted(os.listdir(a.records)) if os.path.isdir(a.records) else []:
        try:
            with open(os.path.join(a.records, name)) as f:
                fname, line, built = f.read().split()
        except (OSError, ValueError):
            continue
        if built == stamp:
            covered.setdefault((fname, int(line)), []).append(name)
    unrecorded = [name for path in a.cases for name in read_error_cases(path)[1]
                  if not os.path.exists(record_path(a.records, path, name))]
    if unrecorded:
        print(f"{len(unrecorded)} cases recorded no site with this build of the plugin (failed or "
              f"not run; run the '.error.' tests first): {' '.join(unrecorded[:20])}"
              f"{' ...' if len(unrecorded) > 20 else ''}")
    missing = sorted(set(sites) - set(covered))
    for fname, line in missing:
        print(f"no case raises {fname}:{line}: {sites[(fname, line)]}")
    ok = bool(sites) and not missing
    print(f"{'ok' if ok else 'FAIL'}: {len(sites) - len(missing)} of {len(sites)} error and warning "
          f"calls of {a.package} raised by the {sum(map(len, covered.values()))} recorded cases")
    return 0 if ok else 1


def declared_styles(pkg_dir):
    styles = []
    for name in sorted(os.listdir(pkg_dir)):
        if name.endswith(".h"):
            with open(os.path.join(pkg_dir, name)) as f:
                for m in re.finditer(r"^(Pair|Fix|Compute|Command)Style\(([^,]+),", f.read(), re.M):
                    styles.append((m.group(1).lower(), m.group(2).strip()))
    return styles


def cmd_styles(a):
    script = f"plugin load {a.plugin}\nplugin list\n"
    proc = subprocess.run([a.lmp, "-log", "none"], input=script, text=True, capture_output=True,
                          env=mpi_env())
    output = proc.stdout + proc.stderr
    styles = declared_styles(a.package)
    if not styles:
        print(f"FAIL: no styles declared in {a.package}")
        return 1
    missing = [f"{kind} style {name}" for kind, name in styles
               if not re.search(rf"{kind} style plugin {re.escape(name)}\b", output)]
    if missing or proc.returncode != 0:
        print(output)
        print("FAIL: plugin list lacks " + ", ".join(missing))
        return 1
    for kind, name in styles:
        print(f"ok {kind} style {name}")
    return 0


def cmd_exports(a):
    proc = subprocess.run(["nm", "-DC", "--defined-only", a.plugin], capture_output=True, text=True)
    if proc.returncode != 0:
        print(proc.stderr)
        return 1
    lines = proc.stdout.splitlines()
    lammps = [line for line in lines if "LAMMPS_NS::" in line]
    code = [line for line in lines if re.search(r" [TtWw] ", line)]
    names = [line.split(" ", 2)[-1] for line in code]
    ok = not lammps and names == ["lammpsplugin_init"]
    print("\n".join(lines))
    if not ok:
        print("FAIL: expected only lammpsplugin_init exported and no LAMMPS_NS:: symbol")
    return 0 if ok else 1


# 2-D kernel derivatives dW/dr on q = r/h, written out independently of sph_kernels.h
KERNEL_2D = {
    "lucy": (1.0, 5.0 / math.pi, lambda q: -12.0 * q * (1 - q) ** 2),
    "cubic": (2.0, 10.0 / (7.0 * math.pi),
              lambda q: -3.0 * q + 2.25 * q * q if q < 1 else -0.75 * (2 - q) ** 2),
    "quintic": (3.0, 7.0 / (478.0 * math.pi),
                lambda q: -5 * (3 - q) ** 4 + (30 * (2 - q) ** 4 if q < 2 else 0)
                - (75 * (1 - q) ** 4 if q < 1 else 0)),
    "wendland": (2.0, 7.0 / (4.0 * math.pi), lambda q: -5.0 * q * (1 - 0.5 * q) ** 3),
}


# conductivity laws of in.rates, written out independently of sph_material_laws.h
RATES_K = {
    "constant": {1: lambda T: 1.0, 2: lambda T: 3.0, 3: lambda T: 0.5},
    "varying": {1: lambda T: math.exp(0.2 * T), 2: lambda T: 3.0 + 0.5 * (T - 2.0),
                3: lambda T: float(np.interp(T, [0.0, 2.0, 5.0], [0.4, 0.6, 0.9]))},
}


def cmd_eq6(a):
    """in.rates: periodic 0.12 x 0.10 box, masses 0.1, 0.05, 0.3 by type."""
    state = parse_state(run_state(a.driver, a.input, a.var + [
        "steps=0", f"kernel={a.kernel}", f"mean={a.mean}", f"eta={a.eta}", f"laws={a.laws}"]))
    cut = {"lucy": 0.013, "quintic": 0.039}.get(a.kernel, 0.026)
    q_max, sigma, dfdq = KERNEL_2D[a.kernel]
    h = cut / q_max
    eta2 = (a.eta * h) ** 2
    m = {1: 0.10, 2: 0.05, 3: 0.30}
    box = (0.12, 0.10)
    n = len(state["id"])
    k = [RATES_K[a.laws][int(t)](T) for t, T in zip(state["type"], state["T"])]
    worst = scale = 0.0
    for i in range(n):
        rate = 0.0
        for j in range(n):
            if i == j:
                continue
            d = [state["x"][i] - state["x"][j], state["y"][i] - state["y"][j]]
            d = [c - L * round(c / L) for c, L in zip(d, box)]
            r = math.hypot(*d)
            if r >= cut:
                continue
            dwdr = sigma / h ** 3 * dfdq(r / h)
            if a.mean == "harmonic":
                kij = 4 * k[i] * k[j] / (k[i] + k[j])
            else:
                kij = k[i] + k[j]
            rate += (m[int(state["type"][j])] * kij / (state["rho"][i] * state["rho"][j])
                     * (state["T"][i] - state["T"][j]) * r * dwdr / (r * r + eta2))
        worst = max(worst, abs(rate - state["desph"][i]))
        scale = max(scale, abs(rate))
    ok = scale > 0 and worst <= a.rtol * scale
    print(f"{'ok' if ok else 'FAIL'} {a.kernel}, {a.mean} mean, eta {a.eta}, {a.laws} k: desph against "
          f"Cleary 1998 eq 6 in Python: largest deviation {worst:.3e} of max |desph| = {scale:.6g}"
          f" (tolerance {a.rtol:.1e})")
    return 0 if ok else 1


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = p.add_subparsers(dest="cmd", required=True)

    s = sub.add_parser("state")
    s.add_argument("--driver", required=True)
    s.add_argument("--input", required=True)
    s.add_argument("--ref", required=True)
    s.add_argument("--var", action="append", default=[], help="name=value for LAMMPS -var")
    s.add_argument("--np", type=int, default=1)
    s.add_argument("--mpirun", default="mpirun")
    s.add_argument("--rtol", type=float, default=1e-12)
    s.add_argument("--generate", action="store_true")

    s = sub.add_parser("same")
    s.add_argument("--driver", required=True)
    s.add_argument("--driver2")
    s.add_argument("--input", required=True)
    s.add_argument("--var", action="append", default=[])
    s.add_argument("--var2", action="append", default=[], help="extra -var for the second run")
    s.add_argument("--np", type=int, default=1)
    s.add_argument("--np2", type=int, default=1)
    s.add_argument("--mpirun", default="mpirun")
    s.add_argument("--rtol", type=float, default=1e-12)

    s = sub.add_parser("error")
    s.add_argument("--lmp", required=True)
    s.add_argument("--plugin", required=True)
    s.add_argument("--cases", required=True)
    s.add_argument("--potentials", default=os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                                        "..", "..", "potentials"))
    s.add_argument("--name")
    s.add_argument("--list", action="store_true")
    s.add_argument("--record", help="write the site (file line) of the expected message here")
    s.add_argument("--np", type=int, default=1, help="MPI ranks (above 1: the error names its rank)")
    s.add_argument("--mpirun", default="mpirun")

    s = sub.add_parser("styles")
    s.add_argument("--lmp", required=True)
    s.add_argument("--plugin", required=True)
    s.add_argument("--package", required=True)

    s = sub.add_parser("exports")
    s.add_argument("--plugin", required=True)

    s = sub.add_parser("eq6")
    s.add_argument("--driver", required=True)
    s.add_argument("--input", required=True)
    s.add_argument("--kernel", required=True, choices=sorted(KERNEL_2D))
    s.add_argument("--mean", default="harmonic", choices=["harmonic", "arithmetic"])
    s.add_argument("--eta", type=float, default=0.1)
    s.add_argument("--laws", default="constant", choices=sorted(RATES_K))
    s.add_argument("--var", action="append", default=[])
    s.add_argument("--rtol", type=float, default=1e-12)

    s = sub.add_parser("branches")
    s.add_argument("--package", required=True)
    s.add_argument("--records", required=True)
    s.add_argument("--plugin", required=True)
    s.add_argument("--cases", nargs="+", required=True)

    a = p.parse_args()
    return {"state": cmd_state, "same": cmd_same, "error": cmd_error, "styles": cmd_styles,
            "exports": cmd_exports, "eq6": cmd_eq6, "branches": cmd_branches}[a.cmd](a)


if __name__ == "__main__":
    sys.exit(main())
