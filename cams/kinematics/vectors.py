"""Planar vectors: arrays whose last axis holds the components ``(x, y)``.

The one representation of a planar vector in the product's kernel: an array of
shape ``(..., 2)``, vectorized over the leading axes. Angles are radians,
positive counter-clockwise; :func:`perp` is the rotation ``J`` by +90 degrees.
"""

from __future__ import annotations

import numpy as np

__all__ = ["xy", "cross", "dot", "norm", "perp", "rotate"]


def xy(x: np.ndarray | float, y: np.ndarray | float) -> np.ndarray:
    """Vectors of shape ``broadcast(x, y).shape + (2,)`` from their components.

    Examples
    --------
    >>> xy(np.array([1.0, 2.0]), 0.0).tolist()
    [[1.0, 0.0], [2.0, 0.0]]
    """
    x, y = np.broadcast_arrays(np.asarray(x, dtype=float), np.asarray(y, dtype=float))
    out = np.empty((*x.shape, 2))
    out[..., 0] = x
    out[..., 1] = y
    return out


def cross(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """The scalar cross product ``a x b = a_x b_y - a_y b_x`` (positive: ``b`` counter-clockwise of ``a``).

    Examples
    --------
    >>> float(cross(np.array([1.0, 0.0]), np.array([0.0, 2.0])))
    2.0
    """
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


def dot(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """The dot product ``a . b`` over the last axis."""
    return a[..., 0] * b[..., 0] + a[..., 1] * b[..., 1]


def norm(a: np.ndarray) -> np.ndarray:
    """The length ``|a|`` over the last axis."""
    return np.sqrt(a[..., 0] * a[..., 0] + a[..., 1] * a[..., 1])


def perp(a: np.ndarray) -> np.ndarray:
    """``J a``: ``a`` turned by +90 degrees (counter-clockwise), ``(-a_y, a_x)``."""
    return xy(-a[..., 1], a[..., 0])


def rotate(v: np.ndarray, angle: np.ndarray | float) -> np.ndarray:
    """``R(angle) v``: vectors turned by ``angle`` (radians, positive counter-clockwise).

    Parameters
    ----------
    v : ndarray, shape (..., 2)
    angle : array_like
        Broadcasts against ``v.shape[:-1]``.

    Examples
    --------
    >>> rotate(np.array([1.0, 0.0]), np.pi / 2).round(12).tolist()
    [0.0, 1.0]
    """
    c, s = np.cos(angle), np.sin(angle)
    x, y = v[..., 0], v[..., 1]
    return xy(c * x - s * y, s * x + c * y)
