"""The numbers of examples/grains-hot-pour (run.sh) from the line its run
printed: the thermal energy of oil, tank and grains against the
integrators' half-step term, and the state at the end.
usage: results.py log.hot-pour > results.md"""

import re
import sys

NUMBER = r"(-?[0-9.]+(?:[eE][+-]?[0-9]+)?)"


def main():
    line = [l for l in open(sys.argv[1]) if l.startswith("hot-pour: ")][-1]

    def value(name):
        return float(re.search(rf"(?:: |, |first \S+ ){name} {NUMBER}", line).group(1))

    dt, first, last = value("dt"), value("heat into the grains first"), value("last")
    change, heat = value("energy change"), value("heat from the grains")
    half_step = dt * (last - first) / 2.0
    print("# Hot grains poured into a tank of cold oil (run.sh)")
    print()
    print(f"{value('grains'):.0f} glass grains (1 mm, 400 K) poured into {value('oil'):.0f} oil particles (300 K) in a closed")
    print(f"steel tank (20 x 24 mm, 6 mm thick, periodic across), to t = {value('time'):.4g} s.")
    print()
    print("| quantity | value |")
    print("|---|---|")
    print(f"| heat the grains gave (J) | {heat:.6g} |")
    print(f"| change of the thermal energy of oil, tank and grains (J) | {change:.6g} |")
    print(f"| the integrators' half-step term dt (Q_N - Q_0) / 2 (J) | {half_step:.6g} |")
    print(f"| their difference, over the heat the grains gave | {abs(change - half_step) / heat:.2e} |")
    print(f"| grains' mean temperature at the end (K) | {value('grains mean T'):.5g} |")
    print(f"| oil's mean temperature at the end (K) | {value('oil mean T'):.5g} |")
    print(f"| grains' mean height, start and end (mm) | {1e3 * value('grains mean height first'):.4g}, "
          f"{1e3 * value('grains mean height'):.4g} |")
    print(f"| oil's largest speed at the end (mm/s) | {1e3 * value('oil largest speed'):.3g} |")


if __name__ == "__main__":
    main()
