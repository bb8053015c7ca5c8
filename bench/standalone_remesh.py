#!/usr/bin/env python3
"""The standalone remesher on the shared models (issue 51): each layout's triangle mesh alone
(NAME.obj copied where no NAME.patch is beside it) through `bimdf remesh`, beside QuadWild's
final meshes (../shared/data/layouts/quadwild_quality.tsv). Prints a markdown table, with each
model's verdict against issue 51's bar: exit 0; a manifold mesh with the input's Euler
characteristic and no border on a closed input; quads 0.5-2x QuadWild's; singular vertices at
most 1.25x; mean and 5th-percentile scaled Jacobian at least QuadWild's; no inverted quad
(and no flat one).

Usage: bench/standalone_remesh.py [--bimdf build/bin/bimdf] [--data ../shared/data]
       [--only NAME,NAME] [--timeout SECONDS] [--keep DIR]
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--bimdf", default=os.path.join(root, "build", "bin", "bimdf"))
    p.add_argument("--data", default=os.path.join(root, "..", "shared", "data"))
    p.add_argument("--only", default="")
    p.add_argument("--timeout", type=float, default=600)
    p.add_argument("--keep", default="", help="folder to keep the quad meshes and reports in")
    a = p.parse_args()
    layouts = os.path.join(a.data, "layouts")
    quality = {}
    with open(os.path.join(layouts, "quadwild_quality.tsv")) as f:
        header = f.readline().split()
        for line in f:
            row = dict(zip(header, line.split()))
            quality[row["mesh"]] = row
    names = sorted(quality)
    if a.only:
        names = [n for n in names if n in a.only.split(",")]
    work = a.keep or tempfile.mkdtemp(prefix="bimdf_standalone_")
    os.makedirs(work, exist_ok=True)
    print("| model | triangles | exit | quads | QuadWild | ratio | singular | QuadWild | ratio "
          "| SJ min | SJ mean | SJ p5 | QuadWild min / mean / p5 | inverted | Hausdorff % "
          "| traced along | field | param. | trace | cut | patches | quantize | tessellate "
          "| total s | topology | issue bar |")
    print("|" + "---|" * 26)
    for name in names:
        bare = os.path.join(work, name + ".obj")
        shutil.copyfile(os.path.join(layouts, name, name + ".obj"), bare)
        out = os.path.join(work, name + ".quads.obj")
        start = time.time()
        try:
            r = subprocess.run([a.bimdf, "remesh", bare, "-o", out, "--json"],
                               capture_output=True, text=True, timeout=a.timeout)
            code, report = r.returncode, r.stdout
        except subprocess.TimeoutExpired:
            code, report = "timeout", ""
        wall = time.time() - start
        q = quality[name]
        if code != 0:
            print(f"| {name} | | {code} | | {q['quads']} | | | {q['singular_interior']} | | | | | "
                  f"{q['msj_min']} / {q['msj_mean']} / {q['msj_p05']} | | | | | | | | | | | "
                  f"{wall:.1f} | | not: exit {code} |")
            continue
        j = json.loads(report)
        m, t = j["metrics"], j["time"]
        sj = m["scaled_jacobian"]
        singular = sum(m["interior_singularities"].values())
        layout = j.get("layout", {})
        traced = f"{layout.get('traced_along', '')} ({layout.get('folded_faces', '')} folded)"
        if layout.get("candidates", 1) > 1:
            traced += f", pairing radius {layout.get('pairing_radius')}"
            if layout.get("spare"):
                traced += ", fewer lines"
        tess = sum(t.get(k, 0) for k in ("patterns_s", "mapping_s", "smoothing_s", "polish_s"))
        closed_in = j["input"]["border_loops"] == 0
        topology = []
        if not m["manifold"]:
            topology.append("non-manifold")
        if m["euler_characteristic"] != j["input"]["euler_characteristic"]:
            topology.append(f"χ {m['euler_characteristic']} (input {j['input']['euler_characteristic']})")
        if closed_in and m["boundary_edges"] > 0:
            topology.append(f"{m['boundary_edges']} border edges")
        misses = [] if not topology else ["topology"]
        if not 0.5 <= m["faces"] / int(q["quads"]) <= 2:
            misses.append("quads")
        if singular > 1.25 * int(q["singular_interior"]):
            misses.append("singular")
        if sj["mean"] < float(q["msj_mean"]):
            misses.append("mean")
        if sj["p5"] < float(q["msj_p05"]):
            misses.append("p5")
        if m["inverted"] > 0:
            misses.append("inverted")
        if m["degenerate"] > 0:  # flat quads are not counted as inverted, nor are they fine
            misses.append("flat quads")
        verdict = "not: " + ", ".join(misses) if misses else "**met**"
        print(f"| {name} | {j['input']['triangles']} | 0 | {m['faces']} | {q['quads']} | "
              f"{m['faces'] / int(q['quads']):.2f} | {singular} | {q['singular_interior']} | "
              f"{singular / max(1, int(q['singular_interior'])):.2f} | {sj['min']:.4f} | "
              f"{sj['mean']:.4f} | {sj['p5']:.4f} | {q['msj_min']} / {q['msj_mean']} / "
              f"{q['msj_p05']} | {m['inverted']} | {100 * m['hausdorff_relative']:.3f} | "
              f"{traced} | {t['field_s']:.2f} | {t.get('parametrization_s', 0):.2f} | "
              f"{t['trace_s']:.2f} | {t['cut_s']:.2f} | "
              f"{t['patches_s']:.2f} | {t['quantize_s']:.2f} | {tess:.2f} | {t['total_s']:.1f} | "
              f"{'; '.join(topology) or 'ok'} | {verdict} |")
        sys.stdout.flush()
    if not a.keep:
        shutil.rmtree(work)


if __name__ == "__main__":
    main()
