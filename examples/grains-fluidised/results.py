"""The table of examples/grains-fluidised (run.sh): the bed's pressure drop
against the superficial velocity for both forms of the fluid's force on the
grains, against Ergun's equation at the bed's porosity; the minimum
fluidisation velocity (where the fixed bed's pressure drop reaches the
bed's weight less buoyancy) against Ergun's and Wen and Yu's
(tools/grain_exact.py); the plot fluidised.png (written where it runs).
usage: results.py fluidised.txt OUT > results.md"""

import math
import re
import sys

from grain_exact import ergun_fluidisation, ergun_gradient, wen_yu_fluidisation

NAMES = ["U", "dP", "weight", "bed height", "fluid speed", "grain speed", "grain porosity", "grains", "area",
         "d", "rho_p", "rho_f", "g", "mu"]
# the fixed bed: the points whose pressure drop is below this share of the
# weight (above it, the bed's top begins to lift)
FIXED = 0.85


def fields(line):
    """The label and named numbers of one printed line."""
    label, rest = line.split(":", 1)
    values = {name: float(re.search(rf"(?:^|, ){name} (-?[0-9.eE+-]+)", rest.strip()).group(1)) for name in NAMES}
    return label.split()[1], values


def porosity(v):
    """The bed's porosity from its height: 1 - N V / (A H)."""
    return 1.0 - v["grains"] * math.pi * v["d"] ** 3 / 6.0 / (v["area"] * v["bed height"])


def onset(points, weight):
    """U where the least-squares a U + b U^2 through the fixed bed's points
    reaches the weight."""
    s11 = sum(u ** 2 for u, _ in points)
    s12 = sum(u ** 3 for u, _ in points)
    s22 = sum(u ** 4 for u, _ in points)
    r1 = sum(u * p for u, p in points)
    r2 = sum(u * u * p for u, p in points)
    det = s11 * s22 - s12 * s12
    a, b = (r1 * s22 - r2 * s12) / det, (s11 * r2 - s12 * r1) / det
    if abs(b) < 1e-12 * abs(a):
        return weight / a
    return (-a + math.sqrt(a * a + 4.0 * b * weight)) / (2.0 * b)


def main():
    runs = {}
    for line in open(sys.argv[1]):
        label, v = fields(line)
        form = label.rsplit("-", 1)[0]
        runs.setdefault(form, []).append(v)
    first = next(iter(runs.values()))[0]
    d, rho_f, rho_p, mu, g = first["d"], first["rho_f"], first["rho_p"], first["mu"], first["g"]
    wen_yu = wen_yu_fluidisation(d, rho_f, rho_p, mu, g)
    print("# A fluidised bed (run.sh): fix sph/grains against Ergun's equation and the minimum fluidisation velocity")
    print()
    print(f"{first['grains']:.0f} glass grains (d = {1e3 * d:g} mm, {rho_p:g} kg/m^3) poured at random through liquid")
    print(f"({rho_f:g} kg/m^3, {1e3 * mu:g} mPa s) onto a grid in a periodic box of 8 x 8 x 36 mm (fluid spacing")
    print("1 mm, Wendland support 3 mm, Gidaspow's drag), then an upward flow of superficial velocity U")
    print("held for 1.5 s (the means over the last 0.5 s). dP / W: the bed's pressure drop over its weight")
    print("less buoyancy per area; 'Ergun' at the bed's porosity 1 - N V / (A H), H twice the grains' mean")
    print("height; 'fluid speed' the largest in the liquid at the end.")
    print()
    print("| pressure | U (mm/s) | dP / W | Ergun dP / W | dP vs Ergun (%) | porosity | H (mm) | fluid speed (mm/s) |")
    print("|---|---|---|---|---|---|---|---|")
    summary = {}
    for form, rows in runs.items():
        rows.sort(key=lambda v: v["U"])
        fixed, lifting = [], []
        for v in rows:
            eps = porosity(v)
            ergun = ergun_gradient(v["U"], d, eps, rho_f, mu) * v["bed height"]
            ratio = v["dP"] / v["weight"]
            if ratio < FIXED:
                fixed.append((v["U"], v["dP"], eps, ergun))
            else:
                lifting.append(eps)
            print(f"| {form} | {1e3 * v['U']:g} | {ratio:.3f} | {ergun / v['weight']:.3f} | "
                  f"{100.0 * (v['dP'] / ergun - 1.0):+.1f} | {eps:.4f} | {1e3 * v['bed height']:.2f} | "
                  f"{1e3 * v['fluid speed']:.3g} |")
        if len(fixed) < 2 or min(p for _, p, _, _ in fixed) <= 0.0:
            continue    # no fixed bed to fit (the gradient form's grains stay suspended)
        eps_fixed = sum(p[2] for p in fixed) / len(fixed)
        summary[form] = {"U": [v["U"] for v in rows], "ratio": [v["dP"] / v["weight"] for v in rows],
                         "onset": onset([(u, p) for u, p, _, _ in fixed], rows[0]["weight"]),
                         "eps": eps_fixed, "ergun_onset": ergun_fluidisation(d, eps_fixed, rho_f, rho_p, mu, g),
                         "eps_lift": lifting[0] if lifting else float("nan"),
                         "ergun_lift": ergun_fluidisation(d, lifting[0], rho_f, rho_p, mu, g) if lifting else float("nan"),
                         "plateau": sum(v["dP"] / v["weight"] for v in rows if v["dP"] / v["weight"] >= FIXED)
                         / max(1, len(lifting)),
                         "worst": max(abs(p / e - 1.0) for _, p, _, e in fixed)}
    print()
    print("Minimum fluidisation velocity: the fixed bed's dP = a U + b U^2 (least squares over the points")
    print(f"below {FIXED:g} W) at dP = W; Ergun's at the fixed bed's mean porosity and at the porosity of the")
    print(f"first bed above {FIXED:g} W (beginning to lift); Wen and Yu's estimate {1e3 * wen_yu:.3f} mm/s (Ergun's with")
    print("fitted constants in place of the porosity). 'lifted dP / W': the mean over the beds above")
    print(f"{FIXED:g} W (the grains on the grid, whose kernel reaches the liquid below it, stay).")
    print()
    print("| pressure | fixed-bed dP vs Ergun, largest (%) | lifted dP / W | U_mf (mm/s) | porosity | Ergun (mm/s) | "
          "vs Ergun (%) | lifting porosity | Ergun (mm/s) | vs Ergun (%) | vs Wen-Yu (%) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for form, s in summary.items():
        print(f"| {form} | {100.0 * s['worst']:.1f} | {s['plateau']:.3f} | {1e3 * s['onset']:.3f} | {s['eps']:.4f} | "
              f"{1e3 * s['ergun_onset']:.3f} | {100.0 * (s['onset'] / s['ergun_onset'] - 1.0):+.1f} | "
              f"{s['eps_lift']:.4f} | {1e3 * s['ergun_lift']:.3f} | "
              f"{100.0 * (s['onset'] / s['ergun_lift'] - 1.0):+.1f} | {100.0 * (s['onset'] / wen_yu - 1.0):+.1f} |")
    plot(summary, first, wen_yu)


def plot(summary, first, wen_yu):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    d, rho_f, mu = first["d"], first["rho_f"], first["mu"]
    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    for (form, s), style in zip(summary.items(), ["o", "s"]):
        ax.plot([1e3 * u for u in s["U"]], s["ratio"], style + "-", mfc="none", lw=0.8,
                label=f"SPH, pressure {form}")
    s = next(iter(summary.values()))
    us = [i * 1e-4 for i in range(1, 131)]
    weight_per_length = (1.0 - s["eps"]) * (first["rho_p"] - rho_f) * first["g"]
    ax.plot([1e3 * u for u in us], [min(ergun_gradient(u, d, s["eps"], rho_f, mu) / weight_per_length, 1.0)
                                    for u in us], "k-", lw=1, label=f"Ergun, porosity {s['eps']:.3f}")
    ax.axvline(1e3 * wen_yu, color="grey", ls="--", lw=1, label="Wen and Yu's U_mf")
    ax.set_xlabel("superficial velocity U (mm/s)")
    ax.set_ylabel("dP / W")
    ax.set_ylim(0.0, 1.15)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig("fluidised.png", dpi=120)


if __name__ == "__main__":
    main()
