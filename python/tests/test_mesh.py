"""bimdf.quantize / remesh / requantize / metrics / OBJ files: the same meshes and numbers as the
CLI, layouts from arrays, and the documented errors."""

import json

import numpy as np
import pytest

import bimdf
from helpers import BUNNY_LAYOUT, run_cli


def assert_same_numbers(ours, theirs, path="report"):
    """Every key of `theirs` is in `ours` with the same value (floats to 1e-9 relative)."""
    if isinstance(theirs, dict):
        for key, value in theirs.items():
            assert key in ours, f"{path}: missing {key}"
            assert_same_numbers(ours[key], value, f"{path}.{key}")
    elif isinstance(theirs, float):
        assert ours == pytest.approx(theirs, rel=1e-9), path
    else:
        assert ours == theirs, path


def layout_triangles():
    lines = BUNNY_LAYOUT.read_text().splitlines()
    V = np.array([[float(x) for x in l.split()[1:4]] for l in lines if l.startswith("v ")])
    F = np.array([[int(x.split("/")[0]) - 1 for x in l.split()[1:]] for l in lines
                  if l.startswith("f ")])
    return V, F


def read_cli_report(tmp_path, *args):
    report = tmp_path / "report.json"
    run_cli(*args, "--report", report)
    return json.loads(report.read_text())


@pytest.fixture(scope="module")
def bunny_remeshed(tmp_path_factory):
    """The bundled layout remeshed by the CLI: (OBJ path, its report)."""
    folder = tmp_path_factory.mktemp("remesh")
    out = folder / "bunny.obj"
    report = folder / "report.json"
    run_cli("remesh", BUNNY_LAYOUT, "-o", out, "--report", report)
    return out, json.loads(report.read_text())


def test_remesh_equals_the_cli_mesh(bunny_remeshed):
    cli_obj, cli_report = bunny_remeshed
    V, F, report = bimdf.remesh(str(BUNNY_LAYOUT))
    V_cli, F_cli = bimdf.read_obj(str(cli_obj))
    assert V.dtype == np.float64 and F.dtype == np.int64 and F.shape[1] == 4
    np.testing.assert_array_equal(F, F_cli)
    np.testing.assert_array_equal(V, V_cli)  # the OBJ writer round-trips doubles exactly
    assert report["quads"] == len(F) == cli_report["metrics"]["faces"]
    assert_same_numbers(report["metrics"], cli_report["metrics"])
    assert report["quantization"]["objective"] == pytest.approx(
        cli_report["quantization"]["objective"], rel=1e-12)


def test_remesh_without_polishing_equals_the_cli(tmp_path):
    out = tmp_path / "plain.obj"
    run_cli("remesh", BUNNY_LAYOUT, "-o", out, "--quality-rounds", "0")
    V, F, report = bimdf.remesh(str(BUNNY_LAYOUT), quality_rounds=0)
    V_cli, F_cli = bimdf.read_obj(str(out))
    np.testing.assert_array_equal(F, F_cli)
    np.testing.assert_array_equal(V, V_cli)
    assert report["time"]["polish_s"] < 1e-3  # nothing to do but return


def test_remesh_of_a_bare_mesh_equals_the_cli(tmp_path):
    """A bare mesh (the layout's triangles alone, as (V, F) or as a file with no NAME.patch
    beside it) gets its own cross field and layout, exactly as `bimdf remesh MESH` makes them."""
    bare = tmp_path / "bare.obj"
    bare.write_text(BUNNY_LAYOUT.read_text())
    out = tmp_path / "quads.obj"
    cli_report = read_cli_report(tmp_path, "remesh", bare, "-o", out)
    V_cli, F_cli = bimdf.read_obj(str(out))
    for arg in (layout_triangles(), bare):
        V, F, report = bimdf.remesh(arg)
        np.testing.assert_array_equal(F, F_cli)
        np.testing.assert_array_equal(V, V_cli)
        assert report["quads"] == len(F) == cli_report["metrics"]["faces"]
        assert_same_numbers(report["metrics"], cli_report["metrics"])
        for key in ("traced_along", "folded_faces", "attempts", "patches", "pairing_radius",
                    "candidates", "spare", "cancelled_pairs"):
            assert report["layout"][key] == cli_report["layout"][key], key
        assert report["layout"]["field_singularities"] == cli_report["field"]["singularities"]
        assert report["layout"]["sharp_edges"] == cli_report["input"]["sharp_edges"]


def test_remesh_of_a_bare_mesh_refuses_a_non_manifold_one():
    V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1]], dtype=float)
    F = np.array([[0, 1, 2], [1, 0, 3], [0, 1, 4]])
    with pytest.raises(bimdf.InputError) as e:
        bimdf.remesh((V, F))
    assert str(e.value) == ("<arrays>: the mesh edge between vertices 0 and 1 has 3 faces, "
                            "expected at most 2 (non-manifold)")
    with pytest.raises(ValueError, match="sharp_angle must be in"):
        bimdf.remesh((V, F), sharp_angle=200)
    with pytest.raises(ValueError, match="pairing_radii must be a non-empty list"):
        bimdf.remesh((V, F), pairing_radii=[])
    with pytest.raises(ValueError, match=r"spare_radii must be a list of numbers in \[0, 100\]"):
        bimdf.remesh((V, F), spare_radii=[-1])
    with pytest.raises(ValueError, match=r"cancel_pairs must be in \[0, 100\]"):
        bimdf.remesh((V, F), cancel_pairs=-1)


def test_quantize_equals_the_cli_and_layouts_from_arrays_equal_files(tmp_path):
    cli = json.loads(run_cli("quantize", BUNNY_LAYOUT, "--json").stdout)
    q = bimdf.quantize(str(BUNNY_LAYOUT))
    np.testing.assert_array_equal(q["lengths"], cli["subside_lengths"])
    assert q["objective"] == pytest.approx(cli["objective"], rel=1e-12)
    assert q["status"] == cli["status"] == "optimal"

    # The same layout handed over as arrays: triangles, face → patch, each patch's corners.
    V, F = layout_triangles()
    patch = np.loadtxt(BUNNY_LAYOUT.with_suffix(".patch"), dtype=np.int64)[1:]
    numbers = [int(x) for x in BUNNY_LAYOUT.with_suffix(".corners").read_text().split()]
    corners, i = [], 1
    for _ in range(numbers[0]):
        corners.append(numbers[i + 1:i + 1 + numbers[i]])
        i += 1 + numbers[i]
    from_arrays = bimdf.quantize((V, F, patch, corners))
    np.testing.assert_array_equal(from_arrays["lengths"], q["lengths"])


def test_requantize_equals_the_cli(bunny_remeshed, tmp_path):
    cli_obj, _ = bunny_remeshed
    V_in, F_in = bimdf.read_obj(str(cli_obj))
    for args, kwargs in [(["--scale", "2"], {"scale": 2.0}),
                         (["--coarse", "--max-angle", "35"], {"coarse": True, "max_angle": 35.0})]:
        out = tmp_path / "rq.obj"
        cli_report = read_cli_report(tmp_path, "requantize", cli_obj, "-o", out, *args)
        V, F, report = bimdf.requantize(V_in, F_in.astype(np.int32), **kwargs)
        V_cli, F_cli = bimdf.read_obj(str(out))
        np.testing.assert_array_equal(F, F_cli)
        np.testing.assert_array_equal(V, V_cli)
        for key in ("status", "quads", "zero_arcs", "tmesh_patches", "nonzero_paths", "half_arc"):
            assert report[key] == cli_report[key], key
        assert report.get("coarse_lengths") == cli_report.get("coarse_lengths")
        assert report.get("feature_traces") == cli_report.get("feature_traces")
        assert ("feature_traces" in report) == ("max_angle" in kwargs)
        assert_same_numbers(report["metrics"], cli_report["metrics"])
        assert report["separatrix_deviation"] == cli_report["separatrix_deviation"]
        assert ("over_bound" in report["separatrix_deviation"]) == ("max_angle" in kwargs)


def test_metrics_equal_the_cli(bunny_remeshed):
    cli_obj, _ = bunny_remeshed
    cli = json.loads(run_cli("metrics", cli_obj, "--reference", BUNNY_LAYOUT, "--json").stdout)
    V, F = bimdf.read_obj(str(cli_obj))
    m = bimdf.metrics(V, F, reference=str(BUNNY_LAYOUT))
    assert_same_numbers(m, {k: v for k, v in cli.items() if k not in ("mesh", "reference")})
    # The reference handed over as arrays measures the same.
    assert_same_numbers(bimdf.metrics(V, F, reference=layout_triangles()), m)


def test_base_complex_patches_are_the_ones_metrics_counts(bunny_remeshed):
    V, F = bimdf.read_obj(str(bunny_remeshed[0]))
    patches = bimdf.base_complex_patches(V, F)
    assert patches.shape == (len(F),)
    count = bimdf.metrics(V, F)["base_complex_faces"]
    # Numbered in the order of their first quads: 0, then each new one the next number.
    firsts = np.unique(patches, return_index=True)[1]
    np.testing.assert_array_equal(np.unique(patches), np.arange(count))
    assert list(np.sort(firsts)) == list(firsts)
    # A cube: six patches, one per quad.
    cube_V = np.array([[i & 1, i >> 1 & 1, i >> 2] for i in range(8)], dtype=np.float64)
    cube_F = np.array([[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2],
                       [1, 3, 7, 5]])
    np.testing.assert_array_equal(bimdf.base_complex_patches(cube_V, cube_F), np.arange(6))


def test_obj_round_trip(tmp_path):
    V = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], dtype=np.float64)
    F = np.array([[0, 1, 2, 3]])
    bimdf.write_obj(str(tmp_path / "q.obj"), V, F)
    V2, F2 = bimdf.read_obj(str(tmp_path / "q.obj"))
    np.testing.assert_array_equal(V2, V)
    np.testing.assert_array_equal(F2, F)


def test_mesh_errors_are_the_documented_exceptions(tmp_path):
    V = np.zeros((4, 3))
    with pytest.raises(ValueError, match=r"^F: expected shape \(m, 4\), got \(1, 3\)$"):
        bimdf.metrics(V, np.array([[0, 1, 2]]))
    with pytest.raises(ValueError, match=r"^F\[0\]: vertex 4 out of range \(V has 4 rows\)$"):
        bimdf.metrics(V, np.array([[0, 1, 2, 4]]))
    with pytest.raises(ValueError, match=r"^V: expected shape \(n, 3\), got \(4, 2\)$"):
        bimdf.metrics(np.zeros((4, 2)), np.array([[0, 1, 2, 3]]))
    with pytest.raises(TypeError, match=r"^F: expected an integer array, got dtype float64$"):
        bimdf.requantize(V, np.array([[0.0, 1.0, 2.0, 3.0]]))
    with pytest.raises(ValueError, match=r"^the half-arc mode must be auto, exact, bounded or off, "
                                         r"not 'both'$"):
        bimdf.requantize(V, np.array([[0, 1, 2, 3]]), half_arc="both")
    with pytest.raises(ValueError, match=r"^reorder_weight and keep_crossings need bounded "
                                         r"half-arc quantization$"):
        bimdf.requantize(V, np.array([[0, 1, 2, 3]]), reorder_weight=2.0)
    with pytest.raises(ValueError, match=r"^hold_angle_bound needs half-arc quantization and an "
                                         r"angle bound \(coarse or max_angle\)$"):
        bimdf.requantize(V, np.array([[0, 1, 2, 3]]), hold_angle_bound=True)
    with pytest.raises(ValueError, match=r"^feature_traces must be 'cross', 'stop' or 'auto'$"):
        bimdf.requantize(V, np.array([[0, 1, 2, 3]]), feature_traces="both")
    with pytest.raises(ValueError, match=r"^feature_traces applies to the angle-bounded traces"):
        bimdf.requantize(V, np.array([[0, 1, 2, 3]]), feature_traces="stop")
    with pytest.raises(ValueError, match=r"^scale must be > 0$"):
        bimdf.remesh(str(BUNNY_LAYOUT), scale=0.0)
    with pytest.raises(ValueError, match=r"^give at most one of scale, edge_length, target_faces$"):
        bimdf.remesh(str(BUNNY_LAYOUT), scale=2.0, target_faces=100)
    with pytest.raises(ValueError, match=r"^quality_rounds must be >= 0$"):
        bimdf.remesh(str(BUNNY_LAYOUT), quality_rounds=-1)
    with pytest.raises(FileNotFoundError, match="no such file"):
        bimdf.remesh(str(tmp_path / "missing.obj"))
    broken = tmp_path / "broken.obj"
    broken.write_text("v 0 0 0\nf 1 2 3\n")
    with pytest.raises(bimdf.InputError, match="broken.obj"):
        bimdf.remesh(str(broken))
