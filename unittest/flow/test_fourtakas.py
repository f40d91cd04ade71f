"""Fourtakas's density diffusion keeps a hydrostatic column's density rate
at zero where Molteni's does not (unittest/flow/in.hydrostatic_drho).
usage: test_fourtakas.py <sph_state driver> <plugin>"""

import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
import sphtest


def largest_fluid_drho(driver, plugin, diffusion):
    state = sphtest.parse_state(sphtest.run_state(driver, os.path.join(here, "in.hydrostatic_drho"),
                                                  [f"plugin={plugin}", f"diffusion={diffusion}"]))
    return max(abs(d) for d, t in zip(state["drho"], state["type"]) if t == 1)


def main():
    driver, plugin = sys.argv[1], sys.argv[2]
    molteni = largest_fluid_drho(driver, plugin, "molteni")
    fourtakas = largest_fluid_drho(driver, plugin, "fourtakas")
    print(f"largest |drho| of the fluid at rest: Molteni {molteni:.3e}, Fourtakas {fourtakas:.3e}")
    ok = molteni > 1e-3 and fourtakas < 1e-9 * molteni
    print("PASS" if ok else "FAIL: Fourtakas's diffusion should vanish at hydrostatic balance")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
