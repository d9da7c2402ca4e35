"""The chart of a sweep: any two columns, coloured by a third, its unusable rows and its Pareto front.

The chart takes the table as columns (name -> values), their units, which rows are usable and which
are on the front (positions in the table), so it draws a sweep's written file as well as one just
solved; it computes nothing of the front itself (the caller's :func:`cams.sweep.pareto.pareto_front`).

matplotlib is imported inside the functions (figures built with ``matplotlib.figure.Figure``, no
pyplot state).

Artists, by label (what the tests read back): ``"designs"`` (the usable rows, a scatter coloured by
the third column when one is given), ``"unusable"`` (grey x markers: rows with an error, failures or a check not passed,
at their values when they have them), ``"Pareto front"`` (the front's points, highlighted) and
``"front (step)"`` (the staircase through them, for two minimised or maximised objectives).
"""

from __future__ import annotations

import os
from collections.abc import Mapping, Sequence
from pathlib import Path

import numpy as np

from laws.errors import InputError

__all__ = ["FORMATS", "sweep_chart", "save_chart"]

#: The chart's file formats, chosen by the output's extension.
FORMATS = ("png", "svg", "pdf")


def _numbers(columns: Mapping[str, Sequence], name: str, field: str) -> np.ndarray:
    if name not in columns:
        raise InputError(field, f"{name!r} is not a column; the columns are: {', '.join(columns)}")
    try:
        return np.array(
            [np.nan if v is None or (isinstance(v, str) and v == "") else v for v in columns[name]], dtype=float
        )
    except (TypeError, ValueError):
        raise InputError(field, f"{name!r} is not a column of numbers") from None


def _label(name: str, units: Mapping[str, str]) -> str:
    u = units.get(name, "")
    return f"{name} ({u})" if u else name


def sweep_chart(
    columns: Mapping[str, Sequence],
    units: Mapping[str, str],
    x: str,
    y: str,
    *,
    colour: str | None = None,
    usable: Sequence[bool] | np.ndarray | None = None,
    front: Sequence[int] | np.ndarray | None = None,
    step: bool = False,
    maximise: tuple[bool, bool] = (False, False),
    title: str | None = None,
):
    """A scatter of column ``y`` against column ``x`` of a sweep's rows.

    Parameters
    ----------
    columns : mapping of str to sequence
        The table's columns (all one length); ``x``, ``y`` and ``colour`` numeric (None or NaN: empty).
    units : mapping of str to str
        Each column's unit (``"mm"``, ``"deg"``; missing or ``""``: none), shown in the axes' labels and on
        the colour bar.
    x, y : str
        The columns on the horizontal and vertical axes.
    colour : str, optional
        The column colouring the usable rows (a colour bar with its unit).
    usable : sequence of bool, optional
        Which rows are usable; the others are drawn as grey x markers (``"unusable"``, in the legend).
        Default: every row.
    front : sequence of int, optional
        Positions of the rows on the Pareto front, highlighted (``"Pareto front"``).
    step : bool
        Draw the staircase through the front's points (``"front (step)"``), the edge of what the front
        dominates: for a front over exactly the objectives ``x`` and ``y``.
    maximise : (bool, bool)
        Whether larger ``x``, ``y`` are better (the direction of the staircase).
    title : str, optional
        The chart's title.

    Returns
    -------
    matplotlib.figure.Figure

    Raises
    ------
    InputError
        Naming ``--x``, ``--y`` or ``--colour``: a column that does not exist or holds no numbers.
    """
    from matplotlib.figure import Figure

    xs = _numbers(columns, x, "--x")
    ys = _numbers(columns, y, "--y")
    cs = _numbers(columns, colour, "--colour") if colour else None
    n = len(xs)
    ok = np.ones(n, dtype=bool) if usable is None else np.asarray(usable, dtype=bool)
    drawn = np.isfinite(xs) & np.isfinite(ys)
    fig = Figure(figsize=(7.0, 5.0), layout="constrained")
    ax = fig.add_subplot()
    good = ok & drawn
    if cs is not None:
        sc = ax.scatter(xs[good], ys[good], c=cs[good], s=22, cmap="viridis", label="designs", zorder=2)
        fig.colorbar(sc, ax=ax, label=_label(colour or "", units))
    else:
        ax.scatter(xs[good], ys[good], s=22, color="tab:blue", label="designs", zorder=2)
    bad = ~ok & drawn
    n_bad = int(np.sum(~ok))
    if n_bad:
        where = "" if np.all(bad == ~ok) else f", {int(np.sum(~ok & ~drawn))} without values not drawn"
        ax.scatter(
            xs[bad],
            ys[bad],
            marker="x",
            color="0.6",
            s=26,
            linewidths=1.0,
            zorder=1,
            label=f"unusable ({n_bad}: an error, failures or a check not passed{where})",
        )
    if front is not None and len(front):
        f = np.asarray(front, dtype=int)
        fx, fy = xs[f], ys[f]
        ax.scatter(
            fx,
            fy,
            s=70,
            facecolors="none",
            edgecolors="tab:red",
            linewidths=1.6,
            zorder=3,
            label=f"Pareto front ({len(f)})",
        )
        if step:
            # the edge of the dominated region: level at each point's y until the next point's x
            order = np.argsort(-fx if maximise[0] else fx, kind="stable")
            ax.step(fx[order], fy[order], where="post", color="tab:red", linewidth=1.0, zorder=2, label="front (step)")
    ax.set_xlabel(_label(x, units))
    ax.set_ylabel(_label(y, units))
    if title:
        ax.set_title(title)
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best", fontsize="small")
    return fig


def save_chart(fig, path: str | os.PathLike, field: str = "--plot") -> Path:
    """Write ``fig`` to ``path`` in the format its extension names (PNG, SVG or PDF), whole or not at all.

    Raises
    ------
    InputError
        Naming ``field``: another extension, or the file cannot be written.
    """
    from functools import partial

    from cams.io.files import atomic_write

    ext = Path(path).suffix.lower().lstrip(".")
    if ext not in FORMATS:
        raise InputError(field, f"{os.fspath(path)!r}: the chart is written as .png, .svg or .pdf")
    return atomic_write(path, field, partial(fig.savefig, format=ext, dpi=150), suffix=f".{ext}")
