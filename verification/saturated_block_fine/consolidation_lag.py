#!/usr/bin/env python3
"""How much of this case's friction ratio the continuum's own consolidation lag takes.

The closed form of README.md (a(0.2) / a(0) = 1 - mu / tan(theta) = 0.5711) assumes that the
block's pore pressure follows the hydrostatic pressure of the water around it at every
instant. The block slides down the slope, so the water above it deepens at the rate
R = rho_w g sin(theta) v. With a compressible pore water the block responds to that rise of the
surrounding pressure as a soil to an all-round load: undrained, its pore water takes only the
share B = (1/K) / (n/K_w + 1/K) of it (Skempton's B; K the skeleton's drained modulus); the
rest flows in from the block's top by consolidation, at the coefficient
c_v = (k / mu_w) / (n/K_w + 1/K). Until it has, the pore pressure at the bed lags the
hydrostatic one, and the difference, a downward seepage force on the grains, is carried by the
skeleton and the bed: it adds its resultant to the effective normal force and mu times that to
the friction.

One-dimensional model across the block's thickness H (z = 0 the impermeable bed, z = H its
drained top), for the lag u = p - p_hydrostatic:

    du/dt = c_v d2u/dz2 - (1 - B) R(t),   u(H) = 0,   du/dz(0) = 0,

and the block's motion, m_eff dv/dt = F_0 - mu (N_0 - u(0) L), F_0 and N_0 the buoyant
weight's components along and normal to the slope. The unknown effective mass (block plus
added mass) is set by a(0) = 1.4 m/s2 (about what the solver gives); the ratio hardly depends
on it. The same least-squares fit s = a t^2 / 2 over outputs every 10 ms as the case.

Prints, for the case's water (K_w = 2.15e6 Pa, a tenth of real water's), ten times it, and
real water, the lag at the bed after 0.3 s and the ratio the continuum gives. Two choices of
K bracket the skeleton's constraint: the oedometric modulus M and the plane-strain bulk
modulus. Kozeny-Carman (eq. 24) gives the permeability k.

Usage: python3 consolidation_lag.py [duration_s]   (0.3 for the quick variant, 0.5 full)
"""
import math
import sys

RHO_W, RHO_SAT, G = 1000.0, 1990.0, 9.81
THETA = math.radians(25.0)
POROSITY, YOUNGS, POISSON = 0.4, 2.0e7, 0.3
GRAIN_DIAMETER, VISCOSITY = 1.0e-4, 1.0e-3
THICKNESS, LENGTH = 0.06, 0.8
PERMEABILITY = POROSITY**3 * GRAIN_DIAMETER**2 / (150.0 * (1.0 - POROSITY) ** 2)
OEDOMETRIC = YOUNGS * (1 - POISSON) / ((1 + POISSON) * (1 - 2 * POISSON))
PLANE_STRAIN_BULK = YOUNGS / (2 * (1 + POISSON) * (1 - 2 * POISSON))


def slide(mu, skeleton_modulus, water_modulus, duration, a_free=1.4, cells=30):
    """Returns the fitted acceleration, the lag at the bed at the end, c_v and B."""
    storage = POROSITY / water_modulus + 1.0 / skeleton_modulus
    c_v = PERMEABILITY / VISCOSITY / storage
    skempton_b = (1.0 / skeleton_modulus) / storage
    weight = (RHO_SAT - RHO_W) * G * LENGTH * THICKNESS  # buoyant weight per metre
    drive, normal = weight * math.sin(THETA), weight * math.cos(THETA)
    mass = drive / a_free
    dz = THICKNESS / cells
    dt = 0.4 * dz * dz / c_v
    lag = [0.0] * (cells + 1)
    v = s = t = 0.0
    samples, next_sample = [], 0.0
    while t < duration + 1e-12:
        if t >= next_sample - 1e-12:
            samples.append((t, s))
            next_sample += 0.01
        rate = RHO_W * G * math.sin(THETA) * v
        new = lag[:]
        for i in range(cells):
            below = lag[1] if i == 0 else lag[i - 1]  # mirror at the impermeable bed
            new[i] = lag[i] + dt * (c_v * (lag[i + 1] - 2 * lag[i] + below) / dz**2
                                    - (1.0 - skempton_b) * rate)
        new[cells] = 0.0
        lag = new
        a = (drive - mu * (normal - lag[0] * LENGTH)) / mass
        v += a * dt
        s += v * dt
        t += dt
    fit = sum(si * ti**2 / 2 for ti, si in samples) / sum((ti**2 / 2) ** 2 for ti, _ in samples)
    return fit, -lag[0], c_v, skempton_b


def main():
    duration = float(sys.argv[1]) if len(sys.argv) > 1 else 0.3
    print(f"closed form without lag: {1 - 0.2 / math.tan(THETA):.4f}; duration {duration} s")
    print("K_w (Pa) | skeleton modulus | c_v (m2/s) | B | bed lag at the end (Pa) | ratio")
    for water_modulus in (2.15e6, 2.15e7, 2.15e9):
        for name, modulus in (("oedometric", OEDOMETRIC), ("plane-strain bulk", PLANE_STRAIN_BULK)):
            a_free = slide(0.0, modulus, water_modulus, duration)[0]
            a_mu, lag, c_v, b = slide(0.2, modulus, water_modulus, duration)
            print(f"{water_modulus:.3g} | {name} | {c_v:.3g} | {b:.3f} | {lag:.1f} | "
                  f"{a_mu / a_free:.4f}")


if __name__ == "__main__":
    main()
