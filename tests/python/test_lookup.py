"""dspbr.lookup (the generated renderer-layout lookup headers, vectorised) against exact values:
the published-layout generator's deterministic quadrature at off-grid points of the renderer
layout (a different integration, no interpolation), within the renderer lookups' accuracy over
the domain (docs/luts.md: at most ~2.2e-3, Glass_inv_E at grazing; 1e-3 elsewhere), and
numpy broadcasting and dtype; the average lookups against the cosine averages of the directional
ones (what the renderer layout makes them)."""
import numpy as np
import pytest

import dspbr

def grid(name, size):
    axes = dspbr.lut.axes(name, size=size)
    return [x for _, x in axes]


def exact(name, size):
    return dspbr.lut.generate([name], {name: size}, layout="published")[name]


@pytest.mark.parametrize("name, fn, tol", [("GGX_E", "ggx_E", 1.2e-3), ("Sheen_E", "sheen_E", 1.2e-3),
                                           ("Sheen_ash_E", "sheen_ash_E", 1.2e-3)])
def test_directional_lookups_match_the_quadrature(name, fn, tol):
    size = (7, 9)
    a, mu = grid(name, size)
    want = exact(name, size)
    got = getattr(dspbr.lookup, fn)(mu[None, :], a[:, None])
    assert got.shape == want.shape and got.dtype == np.float32
    err = np.abs(got - want)
    assert err.max() < tol, (name, err.max())
    assert err.max() > 0  # a float table, not the quadrature itself


def test_base_and_average_lookups_match_the_quadrature():
    size = (3, 5, 6)
    f0, r, mu = grid("Base_E", size)
    got = dspbr.lookup.base_E(mu[None, None, :], r[None, :, None], f0[:, None, None])
    assert np.abs(got - exact("Base_E", size)).max() < 1.2e-3
    size_avg = (3, 5)
    f0, r = grid("Base_E_avg", size_avg)
    got = dspbr.lookup.base_E_avg(r[None, :], f0[:, None])
    assert np.abs(got - exact("Base_E_avg", size_avg)).max() < 1.2e-3
    r = grid("GGX_E_avg", (11,))[0]
    want = exact("GGX_E_avg", (11,))
    assert np.abs(dspbr.lookup.ggx_E_avg(r) - want).max() < 1e-3

def test_missing_average_is_the_cosine_average_of_the_lookups():
    # The renderer layout's 1 - E_m,avg is the cosine average of its own E_m lookups (so that the
    # multiple-scattering lobe restores exactly the energy the lookups say is missing; docs/luts.md),
    # kept to its relative precision as r -> 0 where it vanishes like r^4. Integrated here with
    # Gauss-Legendre in t = sqrt(mu) from the float lookups (their rounding: ~2e-3 relative at r = 0.02).
    x, w = np.polynomial.legendre.leggauss(16)
    edges = np.linspace(0, 1, 257)
    half = 0.5 * (edges[1:] - edges[:-1])[:, None]
    t = (half * x + 0.5 * (edges[1:] + edges[:-1])[:, None]).ravel()
    wt = (half * w).ravel()
    for r in [0.02, 0.05, 0.1, 0.3, 0.6, 0.9]:
        e = dspbr.lookup.ggx_E(t * t, r).astype(np.float64)
        average = 2 * np.sum((1 - e) * 2 * t**3 * wt)  # 2 Integral (1 - E) mu dmu, mu = t^2
        assert dspbr.lookup.ggx_E_avg_missing(r) == pytest.approx(average, rel=3e-3, abs=1e-8), r


@pytest.mark.parametrize("name, inside", [("Glass_E", 0), ("Glass_inv_E", 1)])
def test_glass_lookups_match_the_quadrature(name, inside):
    size = (4, 5, 7)
    x, r, mu = grid(name, size)
    ior = (2 + x) / (2 - x)
    want = exact(name, size)
    got = dspbr.lookup.glass_E(mu[None, None, :], r[None, :, None], ior[:, None, None], inside)
    keep = np.broadcast_to(mu[None, None, :] > 0.02, want.shape)  # away from the grazing end point
    assert np.abs(got - want)[keep].max() < 2.5e-3


def test_broadcasting_and_scalars():
    assert isinstance(dspbr.lookup.ggx_E(0.5, 0.3), float)
    out = dspbr.lookup.glass_E([0.2, 0.7], 0.4, 1.5, [[0], [1]])
    assert out.shape == (2, 2) and out.dtype == np.float32
    # The composite terms from the same header agree with their parts (spec eq. b_c, M_r,ms).
    cv, cl, r, f0 = 0.3, 0.8, 0.5, 0.04
    bc = (1 - dspbr.lookup.base_E(cv, r, f0)) * (1 - dspbr.lookup.base_E(cl, r, f0)) / (
        np.pi * (1 - dspbr.lookup.base_E_avg(r, f0)))
    assert dspbr.lookup.diffuse_bc(cv, cl, r, f0) == pytest.approx(bc, rel=1e-5)

