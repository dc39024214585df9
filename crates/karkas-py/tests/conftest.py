import numpy as np
import pytest


@pytest.fixture
def rng():
    return np.random.default_rng(20261122)


@pytest.fixture
def wavy3d():
    """A wavy open 3-D polygon of 40 points."""
    s = np.linspace(0.0, 3.0, 40)
    return np.column_stack([np.cos(s) * (1 + 0.3 * np.sin(7 * s)), np.sin(s), 0.2 * np.cos(3 * s)])


@pytest.fixture
def circle2d():
    """24 points on the unit circle, not repeating the first."""
    a = np.linspace(0.0, 2 * np.pi, 24, endpoint=False)
    return np.column_stack([np.cos(a), np.sin(a)])
