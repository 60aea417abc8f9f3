"""The soft-sphere twin of a hard-contact run: the settings of gran/hertz/history that give a
chosen overlap, restitution and time step, so that hard and soft runs of one scene compare."""

import math


def hertz_params(d, v, overlap, load, restitution, steps_per_contact):
    """Coefficients of gran/hertz/history for spheres of diameter d (density 1).

    kn        a static load `load` between two of them overlaps by `overlap` x d
              (F = kn sqrt(R_eff) delta^1.5)
    gamma_n   the restitution at impact speed v (the fit of potentials/glass_beads.params)
    gamma_w   the same for a sphere on a wall (R_eff = R, m_eff = m)
    t_c, dt   Hertz's contact time of a pair impact at v, and t_c / steps_per_contact
    impact_overlap  that impact's largest overlap / d
    """
    m = math.pi / 6.0 * d ** 3
    m_eff, r_eff = m / 2.0, d / 4.0
    delta = overlap * d
    kn = load / (math.sqrt(r_eff) * delta ** 1.5)
    delta_m = (m_eff * v * v / (kn * math.sqrt(r_eff))) ** 0.4
    ln_e = -math.log(restitution)
    b = 2.8031 * ln_e * (1.0 + 0.091785 * ln_e) / math.sqrt(10.425 + ln_e * ln_e)
    gamma_n = b * v / (math.sqrt(r_eff) * delta_m ** 1.5)
    delta_w = (m * v * v / (kn * math.sqrt(2 * r_eff))) ** 0.4
    gamma_w = b * v / (math.sqrt(2 * r_eff) * delta_w ** 1.5)
    t_c = 3.2181 * delta_m / v
    return dict(kn=kn, gamma_n=gamma_n, gamma_w=gamma_w, t_c=t_c, dt=t_c / steps_per_contact,
                impact_overlap=delta_m / d)
