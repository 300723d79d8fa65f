"""The physics helpers behind the plots: the force-distribution densities of
Miyata et al. (2002), eqs. 61-62, the normalised force and its histogram,
and Maw's impact parameters (Randall 1989, eqs. 5.14-5.15)."""

import math

import numpy as np
import pytest

from dem.force_distribution import ForceDistribution, mueth_density, normalised_forces, q_model_density
from dem.impact import maw_chi, maw_psi, psi1_of_angle, rigid_body_psi2

F = np.linspace(0.0, 40.0, 400001)


def integral(values):
    return float(np.sum(0.5 * (values[1:] + values[:-1]) * np.diff(F)))


def test_the_q_model_is_a_density_of_mean_one():
    # Eq. (62) with N = 3: 27/2 f^2 exp(-3 f), a Gamma density of mean 1.
    density = q_model_density(F, 3)
    assert integral(density) == pytest.approx(1.0, abs=1e-9)
    assert integral(F * density) == pytest.approx(1.0, abs=1e-9)
    assert q_model_density(1.0, 3) == pytest.approx(13.5 * math.exp(-3.0))
    assert q_model_density(0.0, 3) == 0.0


def test_the_mueth_fit():
    # Eq. (61) with a = 3, b = 0.75, beta = 1.5: P(0) = a (1 - b).
    assert mueth_density(0.0) == pytest.approx(0.75)
    assert mueth_density(2.0) == pytest.approx(3.0 * (1 - 0.75 * math.exp(-4.0)) * math.exp(-3.0))
    # The seed's fit is not normalised exactly; it is close to a density.
    assert integral(mueth_density(F)) == pytest.approx(1.0, abs=0.05)


def test_normalised_forces_and_the_pooled_histogram():
    f = normalised_forces([1.0, 2.0, 3.0, 6.0])
    assert f.mean() == pytest.approx(1.0)
    assert list(f) == [1 / 3, 2 / 3, 1.0, 2.0]
    with pytest.raises(ValueError, match="mean contact force"):
        normalised_forces([0.0, 0.0])
    distribution = ForceDistribution("top")
    distribution.add_snapshot([1.0, 2.0, 3.0, 6.0])
    distribution.add_snapshot([10.0, 30.0])  # another moment: normalised by its own mean
    assert distribution.snapshots == 2 and distribution.f.size == 6
    edges, density = distribution.histogram(0.25)
    assert edges[0] == 0.0 and edges[1] == 0.25 and edges[-1] >= distribution.f.max()
    assert float(np.sum(density) * 0.25) == pytest.approx(1.0)
    with pytest.raises(ValueError, match="no contacts on bottom"):
        ForceDistribution("bottom").histogram()


def test_maws_parameters():
    # Randall 5.4: nu = 0.28 gives chi = 1.465; the 30 degree case of
    # cases/validation has psi1 = 4.03, below 4 chi - 1 = 4.86.
    assert maw_chi(0.28) == pytest.approx(1.465, abs=5e-4)
    assert psi1_of_angle(0.28, 0.12, 30.0) == pytest.approx(4.03, abs=5e-3)
    assert maw_psi(0.28, 0.12, 0.0) == 0.0
    chi = maw_chi(0.28)
    assert rigid_body_psi2(2.0, chi) == 0.0
    assert rigid_body_psi2(10.0, chi) == pytest.approx(10.0 - 4.0 * chi)
