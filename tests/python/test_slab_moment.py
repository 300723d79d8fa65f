"""The slab model and the Monte Carlo estimate of Miyata et al. (2002)
Fig. 36 (dem.slab_moment): a simply supported strip's moments against
statics worked by hand and on a fine grid, and the draws' densities."""

import numpy as np
import pytest

from dem.force_distribution import mueth_density
from dem.slab_moment import (PlateLoads, maximum_moments, moment_ratio, monte_carlo_ratios, sample_mueth,
                             sample_q_model, uniform_moment)


def moments_on_a_grid(span, positions, loads, points=200001):
    """M(x) = R_A x - sum_{x_i < x} P_i (x - x_i), evaluated everywhere."""
    x = np.linspace(0.0, span, points)
    reaction = np.sum(loads * (span - positions)) / span
    arms = np.clip(x[:, None] - positions[None, :], 0.0, None)
    return reaction * x - arms @ loads


def test_a_point_load_gives_p_a_b_over_l():
    # Statics: P at a of a span L carries M = P a (L - a) / L under the load.
    assert maximum_moments(4.0, [2.0], [10.0]) == pytest.approx(10.0 * 2.0 * 2.0 / 4.0)
    assert maximum_moments(4.0, [1.0], [10.0]) == pytest.approx(10.0 * 1.0 * 3.0 / 4.0)
    # At midspan the moment is twice the uniform load's: P L / 4 against (P / L) L^2 / 8.
    assert moment_ratio(4.0, [2.0], [10.0]) == pytest.approx(2.0)
    assert uniform_moment(10.0, 4.0) == pytest.approx(5.0)


def test_the_largest_moment_matches_the_moment_line_everywhere():
    rng = np.random.default_rng(31)
    span = 2.5
    positions = rng.uniform(0.0, span, 40)
    loads = rng.exponential(1000.0, 40)
    grid = moments_on_a_grid(span, positions, loads)
    assert maximum_moments(span, positions, loads) == pytest.approx(grid.max(), rel=1e-6)
    # Rows of loads are independent trials.
    rows = np.stack([loads, loads[::-1], np.ones(40)])
    expected = [moments_on_a_grid(span, positions, row).max() for row in rows]
    np.testing.assert_allclose(maximum_moments(span, positions, rows), expected, rtol=1e-6)


def test_evenly_spread_equal_loads_approach_the_uniform_moment():
    n = 200
    positions = (np.arange(n) + 0.5) / n * 3.0
    assert moment_ratio(3.0, positions, np.full(n, 7.0)) == pytest.approx(1.0, rel=1e-3)
    # Per unit width: the width divides the moment and the uniform load alike.
    assert moment_ratio(3.0, positions, np.full(n, 7.0), width=2.0) == pytest.approx(1.0, rel=1e-3)


def test_the_draws_have_the_densities_asked_for():
    rng = np.random.default_rng(2002)
    q = sample_q_model(rng, 200000)
    assert q.mean() == pytest.approx(1.0, abs=0.01)       # eq. (62) has mean 1
    assert q.var() == pytest.approx(1.0 / 3.0, abs=0.01)  # and variance 1/N
    f = sample_mueth(rng, 200000)
    grid = np.linspace(0.0, 20.0, 20001)
    density = mueth_density(grid)
    mean = np.trapz(grid * density, grid) / np.trapz(density, grid)
    assert f.mean() == pytest.approx(mean, rel=0.01)
    assert np.mean(f < 1.0) == pytest.approx(np.trapz(density[grid < 1.0], grid[grid < 1.0])
                                             / np.trapz(density, grid), abs=0.005)


def test_monte_carlo_keeps_each_snapshots_positions_and_load():
    snapshots = [PlateLoads(np.array([0.5, 1.0, 2.0]), np.array([1.0, 3.0, 2.0])),
                 PlateLoads(np.array([1.25]), np.array([6.0]))]
    # Equal forces: each snapshot's own ratio, nothing random left.
    equal = monte_carlo_ratios(snapshots, 2.5, density="equal", trials=400)
    values = {round(moment_ratio(2.5, s.positions, np.ones(len(s.forces))), 12) for s in snapshots}
    assert set(np.round(equal, 12)) == values
    # One contact takes the whole load whatever f is drawn: the ratio is 2 at midspan.
    measured = monte_carlo_ratios([snapshots[1]], 2.5, density="measured", trials=50)
    np.testing.assert_allclose(measured, 2.0)
    # The same seed, the same draws.
    np.testing.assert_array_equal(monte_carlo_ratios(snapshots, 2.5, trials=100, seed=7),
                                  monte_carlo_ratios(snapshots, 2.5, trials=100, seed=7))
    with pytest.raises(ValueError, match="unknown density"):
        monte_carlo_ratios(snapshots, 2.5, density="gaussian")
    with pytest.raises(ValueError, match="no snapshot with contacts"):
        monte_carlo_ratios([PlateLoads(np.empty(0), np.empty(0))], 2.5)
