"""The non-dimensional parameters of an oblique impact of a sphere on a wall
(Maw, Barber & Fawcett 1976, as Randall 1989, 5.3.2 and 5.4 uses them)."""

import math


def maw_chi(poisson_ratio, radius_of_gyration_squared=0.4):
    """chi = (1 - nu)(1 + 1/K^2)/(2 - nu), K^2 = I/(M R^2) (2/5 for a solid
    sphere) - Randall 1989, eq. (5.14)."""
    nu = poisson_ratio
    return (1.0 - nu) * (1.0 + 1.0 / radius_of_gyration_squared) / (2.0 - nu)


def maw_psi(poisson_ratio, friction, tangential_over_normal):
    """psi = 2(1 - nu)/(mu (2 - nu)) V_T/V_N - Randall 1989, eq. (5.15); with
    V_T/V_N = tan(theta), theta the angle of incidence (5.16)."""
    nu = poisson_ratio
    return 2.0 * (1.0 - nu) / (friction * (2.0 - nu)) * tangential_over_normal


def psi1_of_angle(poisson_ratio, friction, angle_deg):
    """psi_1 for an impact angle_deg from the wall's normal (5.15, 5.16)."""
    return maw_psi(poisson_ratio, friction, math.tan(math.radians(angle_deg)))


def rigid_body_psi2(psi1, chi):
    """psi_2 by rigid-body theory with a restitution of 1: the contact point
    stops (psi_2 = 0) unless it slides throughout, when the friction impulse
    2 mu m V_N slows it by 4 chi in psi: psi_2 = psi_1 - 4 chi (Randall 1989,
    5.4: the exact theory agrees with this for psi_1 >= 4 chi)."""
    return max(psi1 - 4.0 * chi, 0.0)
