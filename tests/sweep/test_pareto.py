"""The Pareto front against its definition, checked pair by pair (O(n^2)), on random data with ties and duplicates."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from cams.sweep.pareto import Objective, non_dominated, pareto_front, parse_objectives, usable_mask
from laws.errors import InputError


def brute_front(p: np.ndarray, maximise=None) -> np.ndarray:
    """The definition: a point is on the front when no point is <= on every objective and < on one."""
    q = [[(-v if maximise and maximise[j] else v) for j, v in enumerate(row)] for row in p.tolist()]
    on = []
    for a in q:
        dominated = any(
            all(bj <= aj for aj, bj in zip(a, b, strict=True)) and any(bj < aj for aj, bj in zip(a, b, strict=True))
            for b in q
        )
        on.append(not dominated)
    return np.array(on, dtype=bool)


# few distinct values: many ties on one objective and whole duplicated points
values = st.integers(min_value=0, max_value=5).map(float) | st.floats(-1e3, 1e3, allow_nan=False)


@st.composite
def tables(draw):
    k = draw(st.integers(1, 4))
    n = draw(st.integers(0, 40))
    rows = draw(st.lists(st.lists(values, min_size=k, max_size=k), min_size=n, max_size=n))
    if rows and draw(st.booleans()):  # duplicates of existing points
        rows += [rows[i] for i in draw(st.lists(st.integers(0, len(rows) - 1), max_size=5))]
    maximise = draw(st.lists(st.booleans(), min_size=k, max_size=k))
    return np.array(rows, dtype=float).reshape(len(rows), k), maximise


@settings(max_examples=100, deadline=None)
@given(tables())
def test_front_is_the_definitions(t):
    p, maximise = t
    assert np.array_equal(non_dominated(p, maximise), brute_front(p, maximise))


@settings(max_examples=50, deadline=None)
@given(tables())
def test_minimising_is_the_default(t):
    p, _ = t
    assert np.array_equal(non_dominated(p), brute_front(p))


def test_equal_points_are_both_on_the_front():
    p = np.array([[1.0, 2.0], [1.0, 2.0], [2.0, 1.0], [2.0, 3.0]])
    assert non_dominated(p).tolist() == [True, True, True, False]
    f = pareto_front({"a": p[:, 0], "b": p[:, 1]}, parse_objectives("a,b"), usable=np.ones(len(p), dtype=bool))
    assert f.rows.tolist() == [0, 1, 2]
    assert f.ties == ((0, 1),)


def test_a_tie_on_one_objective_is_decided_by_the_other():
    # (1, 2) dominates (1, 3): equal on the first, better on the second
    assert non_dominated(np.array([[1.0, 3.0], [1.0, 2.0]])).tolist() == [False, True]
    assert non_dominated(np.array([[1.0, 3.0, 0.0], [1.0, 2.0, 0.0]])).tolist() == [False, True]


def test_large_table_is_quick_and_right_on_a_known_front():
    """100,000 random points plus points on the line x + y = -1 (below all random ones, in [0, 1)^2): the front is
    exactly those points, in both algorithms (two objectives; three with a constant third)."""
    rng = np.random.default_rng(1)
    cloud = rng.random((100_000, 2))
    t = np.linspace(0.0, 1.0, 50)
    line = np.column_stack([t - 1.0, -t])
    p = np.vstack([cloud, line])
    on = non_dominated(p)
    assert np.flatnonzero(on).tolist() == list(range(100_000, 100_050))
    p3 = np.column_stack([p, np.zeros(len(p))])
    assert np.array_equal(non_dominated(p3), on)


def test_unusable_and_empty_rows_are_left_out_and_counted():
    cols = {
        "R0": [1.0, 0.5, None, 2.0, 0.1, float("nan")],
        "L": [1.0, 0.5, 0.0, 0.5, 0.1, 0.0],
        "error": [None, None, None, None, "no admissible centre", None],
        "failures": ["", "curvature", None, None, None, None],
    }
    f = pareto_front(cols, parse_objectives("R0,L"))
    # rows 1 and 4 are unusable (failures, error), rows 2 and 5 have an empty R0: of rows 0 and 3, 3 wins on L, 0 on R0
    assert (f.unusable, f.empty, f.compared) == (2, 2, 2)
    assert f.rows.tolist() == [0, 3]
    assert usable_mask(cols).tolist() == [True, False, True, True, False, True]


def test_maximise_one_objective():
    cols = {"R0": [1.0, 2.0, 3.0], "L": [1.0, 3.0, 2.0], "error": [None] * 3, "failures": [None] * 3}
    assert pareto_front(cols, parse_objectives("R0,max:L")).rows.tolist() == [0, 1]
    assert pareto_front(cols, parse_objectives("R0,L")).rows.tolist() == [0]


def test_a_flag_not_true_makes_a_row_unusable():
    """``verified``/``buildable`` False, empty or a word, ``failures`` left empty: not usable, as ``cams front``
    has it (row 0 would dominate every other row). Without the flags, error and failures alone decide."""
    cols = {
        "R0": [1.0, 2.0, 3.0, 4.0, 5.0],
        "L": [1.0, 2.0, 3.0, 4.0, 5.0],
        "error": [None] * 5,
        "failures": [None] * 5,
        "verified": [False, True, None, "yes", True],
        "buildable": np.array([True, True, True, True, False]),
    }
    assert usable_mask(cols).tolist() == [False, True, False, False, False]
    f = pareto_front(cols, parse_objectives("R0,L"))
    assert (f.rows.tolist(), f.unusable) == ([1], 4)
    bare = {k: cols[k] for k in ("R0", "L", "error", "failures")}
    assert pareto_front(bare, parse_objectives("R0,L")).rows.tolist() == [0]


@pytest.mark.parametrize("drop", ["error", "failures"])
def test_a_table_that_cannot_say_which_rows_are_usable_is_refused(drop):
    """The API's default is the command's rule: without ``error`` or ``failures`` no row is known usable; a
    caller with other rows says which are (``usable``)."""
    cols = {"R0": [1.0, 2.0], "L": [2.0, 1.0], "error": [None, None], "failures": [None, None]}
    del cols[drop]
    with pytest.raises(InputError, match=f"^--pareto: the table has no '{drop}' column"):
        pareto_front(cols, parse_objectives("R0,L"))
    assert pareto_front(cols, parse_objectives("R0,L"), usable=np.ones(2, dtype=bool)).rows.tolist() == [0, 1]


def test_objectives_parsed():
    assert parse_objectives("R0, max:L ,min:offset") == (Objective("R0"), Objective("L", True), Objective("offset"))
    for bad in ("", "R0,,L", "R0,R0", "max:"):
        with pytest.raises(InputError, match="^--pareto: "):
            parse_objectives(bad)


def test_objective_not_a_column_lists_the_columns():
    with pytest.raises(InputError, match=r"^--pareto: 'Rb' is not a column; the columns are: R0, L$"):
        pareto_front({"R0": [1.0], "L": [2.0]}, parse_objectives("Rb"))
    with pytest.raises(InputError, match="not a column of numbers"):
        pareto_front({"R0": [1.0], "name": ["a"]}, parse_objectives("name"))


def test_non_finite_points_refused():
    with pytest.raises(InputError, match="finite"):
        non_dominated(np.array([[1.0, np.nan]]))
