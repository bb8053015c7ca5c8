"""bimdf.Problem and bimdf.Cost: arrays in and out, element by element, files, validation errors."""

import itertools

import numpy as np
import pytest

import bimdf
from helpers import BUNNY_PROBLEM


def small_problem():
    # Node 0 supplies 4 through a head-head edge with node 1 (needs 4 too), an outer tail edge
    # at node 1 with a quadratic target, and a tail-tail loop at node 2 fixed by its demand.
    return bimdf.Problem(
        3,
        ends=[[0, 1], [1, -1], [2, 2]],
        kinds=[[1, 1], [-1, 0], [-1, -1]],
        lower=[0, -5, 0],
        upper=[10, np.inf, 3],
        cost={"kind": "quad", "target": [3.5, 1.0, 0.0], "weight": [1.0, 2.0, 0.5]},
        demand=[4, 2, -2],
    )


def test_arrays_round_trip_through_the_properties():
    p = small_problem()
    assert (p.num_nodes, p.num_edges) == (3, 3)
    np.testing.assert_array_equal(p.ends, [[0, 1], [1, -1], [2, 2]])
    np.testing.assert_array_equal(p.kinds, [[1, 1], [-1, 0], [-1, -1]])
    np.testing.assert_array_equal(p.lower, [0, -5, 0])
    np.testing.assert_array_equal(p.upper, [10, bimdf.INF, 3])
    np.testing.assert_array_equal(p.demand, [4, 2, -2])
    assert p.lower.dtype == np.int64 and p.ends.dtype == np.int64
    assert [c.kind for c in p.costs] == ["quad"] * 3
    assert [(c.target, c.weight) for c in p.costs] == [(3.5, 1.0), (1.0, 2.0), (0.0, 0.5)]
    # Rebuilding from the properties gives the same problem.
    again = bimdf.Problem(p.num_nodes, ends=p.ends, kinds=p.kinds, lower=p.lower, upper=p.upper,
                          cost=p.costs, demand=p.demand)
    assert again == p


def test_element_by_element_equals_arrays():
    p = bimdf.Problem()
    for d in (4, 2, -2):
        p.add_node(d)
    assert p.add_edge((0, "head"), (1, "head"), 0, 10, bimdf.Cost.quad(3.5, 1.0)) == 0
    assert p.add_edge((1, "tail"), None, -5, float("inf"), bimdf.Cost.quad(1.0, 2.0)) == 1
    assert p.add_edge((2, False), (2, False), 0, 3, bimdf.Cost.quad(0.0, 0.5)) == 2
    assert p == small_problem()


@pytest.mark.parametrize("suffix", [".json", ".bimdf"])
def test_files_round_trip(tmp_path, suffix):
    p = small_problem()
    path = tmp_path / ("p" + suffix)
    p.write(str(path))
    assert bimdf.read(str(path)) == p
    assert bimdf.parse(path.read_text()) == p


def test_shared_example_survives_both_formats(tmp_path):
    p = bimdf.read(str(BUNNY_PROBLEM))
    assert (p.num_nodes, p.num_edges) == (672, 1796)
    for fmt in ("json", "bimdf"):
        path = tmp_path / f"bunny.{fmt}"
        p.write(str(path), format=fmt)
        assert bimdf.read(str(path)) == p


def test_cost_functions_evaluate_like_their_formulas():
    assert bimdf.Cost.quad(3.5, 2.0)(5) == pytest.approx(2.0 * 1.5**2)
    assert bimdf.Cost.abs(3.0, 0.5)(-1) == pytest.approx(2.0)
    assert bimdf.Cost.asym_abs(3.0, 1.0, 4.0)(4) == pytest.approx(4.0)
    assert bimdf.Cost.piecewise(0, [3.0, 1.0, 0.0, 2.0])(2) == 0.0
    assert bimdf.Cost.sum([bimdf.Cost.linear(1.0), bimdf.Cost.quad(0.0)])(3) == pytest.approx(12.0)


def test_shape_and_dtype_errors_name_the_argument():
    ends, kinds = [[0, 1]], [[1, 1]]
    with pytest.raises(ValueError, match=r"^ends: expected shape \(m, 2\), got \(1, 3\)$"):
        bimdf.Problem(2, ends=[[0, 1, 1]], kinds=kinds)
    with pytest.raises(TypeError, match=r"^ends: expected an integer array, got dtype float64$"):
        bimdf.Problem(2, ends=[[0.0, 1.0]], kinds=kinds)
    with pytest.raises(TypeError, match=r"^lower: expected an array of numbers, got dtype <U1$"):
        bimdf.Problem(2, ends=ends, kinds=kinds, lower=["a"])
    with pytest.raises(ValueError, match=r"^upper: expected 1 values, got 2$"):
        bimdf.Problem(2, ends=ends, kinds=kinds, upper=[1, 2])
    with pytest.raises(ValueError, match=r"^upper\[0\]: expected an integer or ±inf, got 0.5$"):
        bimdf.Problem(2, ends=ends, kinds=kinds, upper=[0.5])
    with pytest.raises(ValueError, match=r"^demand: expected 2 values, got 3$"):
        bimdf.Problem(2, ends=ends, kinds=kinds, demand=[1, 2, 3])
    with pytest.raises(ValueError, match=r"^kinds\[0\]: expected \+1 \(head\) or -1 \(tail\), got 2$"):
        bimdf.Problem(2, ends=ends, kinds=[[1, 2]])
    with pytest.raises(ValueError, match=r"^cost: kind 'quad' needs 'target'$"):
        bimdf.Problem(2, ends=ends, kinds=kinds, cost={"kind": "quad"})
    with pytest.raises(ValueError, match=r"^cost: unknown key 'tagret'$"):
        bimdf.Problem(2, ends=ends, kinds=kinds, cost={"kind": "quad", "tagret": [1]})
    with pytest.raises(ValueError, match=r"^a: end kind must be 'head' or 'tail', got 'hed'$"):
        bimdf.Problem(1).add_edge((0, "hed"))


def test_validate_raises_input_error_naming_the_edge():
    p = bimdf.Problem(2, ends=[[0, 5]], kinds=[[1, 1]])
    with pytest.raises(bimdf.InputError, match=r"^<problem>: edge 0: node id 5 is out of range \[0, 2\)$"):
        p.validate()
    bad_bounds = bimdf.Problem(2, ends=[[0, 1]], kinds=[[1, -1]], lower=[3], upper=[1])
    with pytest.raises(ValueError, match="edge 0: lower bound 3 is greater than upper bound 1"):
        bad_bounds.validate()
    small_problem().validate()  # a valid one passes


def test_bad_files_raise_the_documented_exceptions(tmp_path):
    with pytest.raises(FileNotFoundError, match="no such file"):
        bimdf.read(str(tmp_path / "missing.bimdf"))
    broken = tmp_path / "broken.bimdf"
    broken.write_text("2 1\n0 0\n0 1 x\n")
    with pytest.raises(bimdf.InputError) as e:
        bimdf.read(str(broken))
    assert str(e.value).startswith(str(broken) + ":")
    assert isinstance(e.value, ValueError)
