"""scripts/batch.sh: a folder of meshes through the bimdf CLI with GNU parallel (docs/batch.md).

Environment: BIMDF_CLI (the built CLI; default build/bin/bimdf), BIMDF_SHARED_DATA_DIR (the shared
data folder; default ../shared/data beside the repository). Run from the repository root:
    BIMDF_CLI=build/bin/bimdf python3 -m pytest python/tests/test_batch.py -q
"""

import csv
import os
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import bimdf

from helpers import REPO, cli, shared_data

BATCH = REPO / "scripts" / "batch.sh"
SUMMARY_COLUMNS = ["name", "kind", "status", "exit_code", "quads", "sj_min", "sj_mean", "sj_p5",
                   "inverted", "time_s"]


def run_batch(*args, jobs=2):
    if shutil.which("parallel") is None:
        pytest.skip("GNU parallel is not installed")
    env = dict(os.environ, BIMDF=str(cli()), JOBS=str(jobs))
    return subprocess.run(["bash", str(BATCH), *map(str, args)], env=env, capture_output=True,
                          text=True, timeout=600)


def read_summary(out: Path):
    with open(out / "summary.csv", newline="") as f:
        reader = csv.DictReader(f)
        assert reader.fieldnames == SUMMARY_COLUMNS
        return list(reader)


def face_sizes(obj: Path):
    return [len(line.split()) - 1 for line in obj.read_text().splitlines() if line.startswith("f ")]


def check_good_row(row, out: Path, kind: str):
    assert row["kind"] == kind
    assert row["status"] == "optimal"
    assert row["exit_code"] == "0"
    sizes = face_sizes(out / f"{row['name']}.obj")
    assert sizes and all(n == 4 for n in sizes), "output mesh is empty or not all-quad"
    assert int(row["quads"]) == len(sizes)
    assert float(row["sj_min"]) <= float(row["sj_mean"]) <= 1.0
    assert int(row["inverted"]) >= 0
    assert float(row["time_s"]) > 0
    assert not (out / f"{row['name']}.err").exists()


def test_batch_remeshes_layouts_and_records_the_broken_one_as_failed(tmp_path):
    layouts = shared_data("layouts")
    smallest = sorted((d for d in layouts.iterdir() if (d / f"{d.name}.obj").is_file()
                       and (d / f"{d.name}.patch").is_file()),
                      key=lambda d: (d / f"{d.name}.obj").stat().st_size)[:3]
    assert len(smallest) == 3, f"fewer than three layouts in {layouts}"
    good = sorted(d.name for d in smallest)
    inp, out = tmp_path / "in", tmp_path / "out"
    for d in smallest:
        (inp / d.name).mkdir(parents=True)
        for f in d.iterdir():
            shutil.copyfile(f, inp / d.name / f.name)
    (inp / "broken").mkdir()
    (inp / "broken" / "broken.obj").write_text("this is not an OBJ file\n")
    (inp / "broken" / "broken.patch").write_text("garbage\n")

    r = run_batch(inp, out)
    assert r.returncode == 1, r.stdout + r.stderr
    assert f"4 meshes: 3 done, 1 failed; summary {out}/summary.csv" in r.stdout

    for name in good:
        obj = out / f"{name}.obj"
        assert obj.is_file() and obj.stat().st_size > 0
        assert (out / f"{name}.json").is_file()
    assert not (out / "broken.obj").exists()
    assert (out / "broken.err").read_text().strip()
    assert (out / "joblog.tsv").is_file()

    failed = (out / "failed.log").read_text().splitlines()
    assert len(failed) == 1
    name, code, message = failed[0].split("\t")
    assert name == "broken" and int(code) != 0 and message

    rows = read_summary(out)
    assert [row["name"] for row in rows] == sorted(good + ["broken"])
    for row in rows:
        if row["name"] == "broken":
            assert row == {**{c: "" for c in SUMMARY_COLUMNS}, "name": "broken",
                           "kind": "remesh", "status": "failed", "exit_code": code}
        else:
            check_good_row(row, out, "remesh")


def test_batch_requantizes_an_obj_without_patch_file(tmp_path):
    layout = REPO / "examples" / "npm_bunny" / "npm_bunny.obj"
    inp, out = tmp_path / "in", tmp_path / "out"
    inp.mkdir()
    quads = inp / "bunny_quads.obj"
    made = subprocess.run([str(cli()), "remesh", str(layout), "-o", str(quads)],
                          capture_output=True, text=True, timeout=600)
    assert made.returncode == 0, made.stderr

    r = run_batch(inp, out, "--smooth-iterations", "5")
    assert r.returncode == 0, r.stdout + r.stderr
    assert (out / "failed.log").read_text() == ""
    rows = read_summary(out)
    assert [row["name"] for row in rows] == ["bunny_quads"]
    check_good_row(rows[0], out, "requantize")


def test_batch_refuses_missing_in_dir_with_exit_2(tmp_path):
    missing = tmp_path / "no_such_folder"
    r = subprocess.run(["bash", str(BATCH), str(missing), str(tmp_path / "out")],
                       capture_output=True, text=True, timeout=60)
    assert r.returncode == 2
    assert str(missing) in r.stderr
    assert not (tmp_path / "out").exists()


def test_batch_refuses_out_dir_equal_to_in_dir(tmp_path):
    (tmp_path / "mesh.obj").write_text("v 0 0 0\n")
    r = subprocess.run(["bash", str(BATCH), str(tmp_path), str(tmp_path)],
                       capture_output=True, text=True, timeout=60)
    assert r.returncode == 2
    assert "OUT_DIR" in r.stderr
    assert (tmp_path / "mesh.obj").read_text() == "v 0 0 0\n"


def test_python_loop_of_batch_md_remeshes_like_the_cli(tmp_path):
    """The concurrent.futures loop that docs/batch.md shows, run as written on three layouts."""
    layouts = shared_data("layouts")
    text = (REPO / "docs" / "batch.md").read_text()
    start = text.index("```python\nimport csv, json, sys") + len("```python\n")
    script = tmp_path / "batch_remesh.py"
    script.write_text(text[start:text.index("```\n", start)])
    inp, out = tmp_path / "in", tmp_path / "out"
    names = ["dragknob", "eight", "mushroom"]
    for name in names:
        shutil.copytree(layouts / name, inp / name)
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))
    r = subprocess.run([sys.executable, str(script), str(inp), str(out)], env=env,
                       capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stdout + r.stderr
    assert r.stdout.strip() == "3 meshes: 3 done, 0 failed"
    with open(out / "summary.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    assert [row["name"] for row in rows] == names
    for row in rows:
        cli_obj = tmp_path / f"{row['name']}_cli.obj"
        subprocess.run([str(cli()), "remesh", str(inp / row["name"] / f"{row['name']}.obj"),
                        "-o", str(cli_obj)], check=True, capture_output=True, timeout=600)
        V, F = bimdf.read_obj(str(out / f"{row['name']}.obj"))
        V_cli, F_cli = bimdf.read_obj(str(cli_obj))
        np.testing.assert_array_equal(F, F_cli)
        np.testing.assert_array_equal(V, V_cli)
        assert row["status"] == "optimal" and int(row["quads"]) == len(F_cli)
