"""Exact values of the exchange laws of fix sph/grains for one grain, from
the laws as published (not from the package's sph_grain_laws.h):
  terminal_slip(drag, weight, d, rho, mu, eps): the slip speed at which the
      drag balances a steady force 'weight' (Stokes: closed form; Di Felice
      1994: Cd = (0.63 + 4.8 / sqrt(Re))^2, F = Cd rho (pi d^2 / 4) eps^2 w^2
      eps^-chi / 2, solved by bisection on a log scale to 1e-15 relative)
  lumped_temperature(t, T0, Tf, d, rho_p, cp, k, nu_number): a grain of
      uniform temperature (lumped capacitance) in fluid held at Tf,
      T = Tf + (T0 - Tf) exp(-t / tau), tau = m cp / (Nu k pi d)
  nusselt(law, re, pr, eps): Ranz and Marshall 1952, Gunn 1978
  ergun_gradient(U, d, eps, rho, mu): the pressure drop per length of a
      fixed bed at superficial velocity U (Ergun, Chem. Eng. Prog. 48 (1952)
      89-94), dP/L = 150 (1-eps)^2 mu U / (eps^3 d^2) + 1.75 (1-eps) rho U^2
      / (eps^3 d); ergun_superficial(gradient, ...) its inverse (the positive
      root of the quadratic)
  ergun_fluidisation(d, eps, rho_f, rho_p, mu, g): the minimum fluidisation
      velocity of a bed of porosity eps by Ergun's equation: the superficial
      velocity at which the bed's pressure drop per length equals its weight
      less buoyancy per volume, (1 - eps)(rho_p - rho_f) g
  wen_yu_fluidisation(d, rho_f, rho_p, mu, g): Wen and Yu's estimate (Chem.
      Eng. Prog. Symp. Ser. 62 (1966) 100-111), Re_mf = sqrt(33.7^2 +
      0.0408 Ar) - 33.7, Ar = d^3 rho_f (rho_p - rho_f) g / mu^2: Ergun's
      with its porosity and sphericity terms replaced by constants fitted
      to measured beds, 1 / (phi eps^3) = 14 and (1 - eps) / (phi^2 eps^3)
      = 11 (for spheres, eps = 0.415 and 0.383)
  bed_superficial(drag, gradient, d, eps, rho, mu): the superficial velocity
      U through a fixed bed of grains of diameter d at porosity eps whose
      drag law (difelice; gidaspow: Ergun's below eps = 0.8, Wen and Yu's
      above, Gidaspow 1994) balances the pressure gradient: n F(U / eps) =
      eps gradient, n = (1 - eps) / (pi d^3 / 6) grains per volume
      (bisection on a log scale to 1e-15)"""

import math


def difelice_force(w, d, rho, mu, eps):
    re = eps * rho * d * w / mu
    cd = (0.63 + 4.8 / math.sqrt(re)) ** 2
    chi = 3.7 - 0.65 * math.exp(-0.5 * (1.5 - math.log10(re)) ** 2)
    return 0.5 * cd * rho * math.pi * d * d / 4.0 * eps * eps * w * w * eps ** (-chi)


def gidaspow_force(w, d, rho, mu, eps):
    if eps < 0.8:
        beta_v = 150.0 * (1.0 - eps) ** 2 * mu / (eps * d * d) + 1.75 * (1.0 - eps) * rho * w / d
    else:
        re = eps * rho * d * w / mu
        cd = 24.0 / re * (1.0 + 0.15 * re ** 0.687) if re < 1000.0 else 0.44
        beta_v = 0.75 * cd * eps * (1.0 - eps) * rho * w * eps ** (-2.65) / d
    return beta_v * w * (math.pi * d ** 3 / 6.0) / (1.0 - eps)


def bisect(force, target):
    lo, hi = 1e-15, 1e3
    for _ in range(300):
        mid = math.sqrt(lo * hi)
        if force(mid) < target:
            lo = mid
        else:
            hi = mid
    return math.sqrt(lo * hi)


def bed_superficial(drag, gradient, d, eps, rho, mu):
    laws = {"difelice": difelice_force, "gidaspow": gidaspow_force}
    if drag not in laws:
        raise ValueError(f"unknown drag law {drag}")
    per_volume = (1.0 - eps) / (math.pi * d ** 3 / 6.0)
    slip = bisect(lambda w: per_volume * laws[drag](w, d, rho, mu, eps), eps * gradient)
    return eps * slip


def terminal_slip(drag, weight, d, rho, mu, eps=1.0):
    if drag == "stokes":
        return weight / (3.0 * math.pi * mu * d)
    if drag != "difelice":
        raise ValueError(f"unknown drag law {drag}")
    return bisect(lambda w: difelice_force(w, d, rho, mu, eps), weight)


def ergun_gradient(U, d, eps, rho, mu):
    e3 = eps ** 3
    return (150.0 * (1.0 - eps) ** 2 * mu * U / (e3 * d * d)
            + 1.75 * (1.0 - eps) * rho * U * U / (e3 * d))


def ergun_superficial(gradient, d, eps, rho, mu):
    e3 = eps ** 3
    a = 1.75 * (1.0 - eps) * rho / (e3 * d)
    b = 150.0 * (1.0 - eps) ** 2 * mu / (e3 * d * d)
    return 2.0 * gradient / (b + math.sqrt(b * b + 4.0 * a * gradient))


def nusselt(law, re, pr, eps=1.0):
    if law == "ranz-marshall":
        return 2.0 + 0.6 * math.sqrt(re) * pr ** (1.0 / 3.0)
    if law == "gunn":
        return ((7.0 - 10.0 * eps + 5.0 * eps * eps) * (1.0 + 0.7 * re ** 0.2 * pr ** (1.0 / 3.0))
                + (1.33 - 2.4 * eps + 1.2 * eps * eps) * re ** 0.7 * pr ** (1.0 / 3.0))
    raise ValueError(f"unknown heat law {law}")


def lumped_temperature(t, t0, tf, d, rho_p, cp, k, nu_number):
    mass = rho_p * math.pi * d ** 3 / 6.0
    tau = mass * cp / (nu_number * k * math.pi * d)
    return tf + (t0 - tf) * math.exp(-t / tau), tau


def ergun_fluidisation(d, eps, rho_f, rho_p, mu, g):
    return ergun_superficial((1.0 - eps) * (rho_p - rho_f) * g, d, eps, rho_f, mu)


def wen_yu_fluidisation(d, rho_f, rho_p, mu, g):
    archimedes = d ** 3 * rho_f * (rho_p - rho_f) * g / mu ** 2
    return (math.sqrt(33.7 ** 2 + 0.0408 * archimedes) - 33.7) * mu / (rho_f * d)
