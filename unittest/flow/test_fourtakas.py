"""Fourtakas's density diffusion keeps a hydrostatic column's density rate
at zero where Molteni's does not (unittest/flow/in.hydrostatic_drho), under
fix gravity's weight, fix sph/boussinesq's buoyancy (T0 given or 'mean'),
or both.
usage: test_fourtakas.py <sph_state driver> <plugin> [gravity|buoyancy|both] [<T0>|mean]"""

import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
import sphtest


def largest_fluid_drho(driver, plugin, diffusion, force, t0):
    state = sphtest.parse_state(sphtest.run_state(
        driver, os.path.join(here, "in.hydrostatic_drho"),
        [f"plugin={plugin}", f"diffusion={diffusion}", f"force={force}", f"t0={t0}"]))
    return max(abs(d) for d, t in zip(state["drho"], state["type"]) if t == 1)


def main():
    driver, plugin = sys.argv[1], sys.argv[2]
    force = sys.argv[3] if len(sys.argv) > 3 else "gravity"
    t0 = sys.argv[4] if len(sys.argv) > 4 else "300.0"
    molteni = largest_fluid_drho(driver, plugin, "molteni", force, t0)
    fourtakas = largest_fluid_drho(driver, plugin, "fourtakas", force, t0)
    print(f"{force}, T0 {t0}: largest |drho| of the fluid at rest: Molteni {molteni:.3e}, "
          f"Fourtakas {fourtakas:.3e}")
    ok = molteni > 1e-3 and fourtakas < 1e-9 * molteni
    print("PASS" if ok else "FAIL: Fourtakas's diffusion should vanish at hydrostatic balance")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
