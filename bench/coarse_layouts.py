#!/usr/bin/env python3
"""Coarse layouts on the shared layouts (issue 52): the paper's Table 1 on our data. Each shared
QuadWild layout is remeshed once (`bimdf remesh LAYOUT.obj -o IN.obj --feature-out IN.feature`,
kept in --inputs so that every run starts from the same meshes), the bundled bunny too; then
`bimdf requantize IN.obj --coarse --max-angle A --feature IN.feature --sharp-angle 180` runs at
each angle: the feature curves are the layout's own, not guessed from the quad mesh's dihedral
angles. Prints a markdown table (base complex in and out, their ratio, patches per singular
vertex, scaled Jacobian, inverted and degenerate quads, time) and a summary per angle against
issue 52's bar: median base-complex ratio <= 0.25 at 45 degrees and <= 0.5 at 20, median mean
scaled Jacobian within 0.05 of the input's, every singularity and border loop kept, no inverted
quad the input does not have, the bunny at 45 degrees with at most 3 patches per singular vertex.

Usage: bench/coarse_layouts.py [--bimdf build/bin/bimdf] [--data ../shared/data]
       [--inputs DIR] [--angles 10,20,35,45] [--only NAME,NAME] [--timeout SECONDS]
       [--extra "ARGS"] [--keep DIR]
"""
import argparse
import json
import os
import shlex
import statistics
import subprocess
import sys
import tempfile
import time

BUNNY = "bunny (bundled)"


def border_loops(obj_path):
    """Loops of border edges (edges of one face) of an OBJ's faces."""
    count = {}
    with open(obj_path) as f:
        for line in f:
            if not line.startswith("f "):
                continue
            ids = [int(t.split("/")[0]) for t in line.split()[1:]]
            for a, b in zip(ids, ids[1:] + ids[:1]):
                key = (min(a, b), max(a, b))
                count[key] = count.get(key, 0) + 1
    parent = {}

    def find(x):
        while parent.setdefault(x, x) != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    border = [e for e, n in count.items() if n == 1]
    for a, b in border:
        parent[find(a)] = find(b)
    return len({find(a) for a, _ in border})


def run(cmd, timeout):
    start = time.time()
    try:
        r = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return "timeout", None, time.time() - start, ""
    report = None
    if r.returncode == 0:
        try:
            report = json.loads(r.stdout)
        except json.JSONDecodeError:
            pass
    return r.returncode, report, time.time() - start, r.stderr.strip().splitlines()[-1:] or [""]


def make_input(a, name, layout, inputs):
    """IN.obj, IN.feature and the remesh report of one layout, made once."""
    mesh = os.path.join(inputs, name.replace(" ", "_") + ".obj")
    features = mesh[:-4] + ".feature"
    report = mesh[:-4] + ".remesh.json"
    if not (os.path.exists(mesh) and os.path.exists(features) and os.path.exists(report)):
        code, j, _, err = run([a.bimdf, "remesh", layout, "-o", mesh, "--feature-out", features,
                               "--json"], a.timeout)
        if code != 0 or j is None:
            print("remesh of %s failed (%s): %s" % (name, code, err[0]), file=sys.stderr)
            return None
        with open(report, "w") as f:
            json.dump(j, f)
    with open(report) as f:
        j = json.load(f)
    return mesh, features, j["metrics"]


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--bimdf", default=os.path.join(root, "build", "bin", "bimdf"))
    p.add_argument("--data", default=os.path.join(root, "..", "shared", "data"))
    p.add_argument("--inputs", default=os.path.join(root, "build", "coarse_inputs"),
                   help="folder of the remeshed inputs (made when missing)")
    p.add_argument("--angles", default="10,20,35,45")
    p.add_argument("--only", default="")
    p.add_argument("--timeout", type=float, default=900)
    p.add_argument("--extra", default="", help="more requantize arguments, e.g. \"--half-arc off\"")
    p.add_argument("--keep", default="", help="folder to keep the coarse meshes and reports in")
    a = p.parse_args()
    layouts = os.path.join(a.data, "layouts")
    names = sorted(d for d in os.listdir(layouts)
                   if os.path.exists(os.path.join(layouts, d, d + ".patch")))
    models = [(n, os.path.join(layouts, n, n + ".obj")) for n in names]
    models.append((BUNNY, os.path.join(root, "examples", "npm_bunny", "npm_bunny.obj")))
    if a.only:
        models = [m for m in models if m[0] in a.only.split(",")]
    angles = [float(x) for x in a.angles.split(",")]
    os.makedirs(a.inputs, exist_ok=True)
    work = a.keep or tempfile.mkdtemp(prefix="bimdf_coarse_")
    os.makedirs(work, exist_ok=True)

    print("| model | angle | exit | BC in | BC out | ratio | singular | patches per singular "
          "| singularities kept | border loops kept | SJ mean in | SJ min | SJ mean | SJ p5 "
          "| inverted (in) | degenerate | max deviation between singular (to border) "
          "| above the bound | total s |")
    print("|" + "---|" * 19)
    rows = {angle: [] for angle in angles}
    for name, layout in models:
        made = make_input(a, name, layout, a.inputs)
        if made is None:
            for angle in angles:
                rows[angle].append({"name": name, "ok": False})
            continue
        mesh, features, metrics_in = made
        loops_in = border_loops(mesh)
        for angle in angles:
            out = os.path.join(work, "%s_%g.obj" % (name.replace(" ", "_"), angle))
            cmd = [a.bimdf, "requantize", mesh, "--coarse", "--max-angle", "%g" % angle,
                   "--feature", features, "--sharp-angle", "180", "-o", out, "--json"]
            cmd += shlex.split(a.extra)
            code, j, wall, err = run(cmd, a.timeout)
            row = {"name": name, "ok": code == 0 and j is not None}
            rows[angle].append(row)
            if not row["ok"]:
                print("| %s | %g° | %s | | | | | | | | | | | | | | | | %.1f |"
                      % (name, angle, code, wall))
                print("%s at %g°: %s" % (name, angle, err[0]), file=sys.stderr)
                continue
            m, sj = j["metrics"], j["metrics"]["scaled_jacobian"]
            singular = m["singular_vertices"]
            row.update(
                bc_in=j["base_complex_in"], bc_out=j["base_complex_out"],
                ratio=j["base_complex_out"] / j["base_complex_in"],
                per_singular=j["base_complex_out"] / singular if singular else float("nan"),
                singularities=j["singularities_in"] == j["singularities_out"],
                loops=border_loops(out) == loops_in,
                sj_in=metrics_in["scaled_jacobian"]["mean"], sj=sj["mean"],
                inverted=m["inverted"], inverted_in=metrics_in["inverted"],
                degenerate=m["degenerate"],
                deviation=j["separatrix_deviation"]["max_deg"],
                over_bound=j["separatrix_deviation"]["over_bound"])
            print("| %s | %g° | 0 | %d | %d | %.3f | %d | %.2f | %s | %s | %.3f | %.3f | %.3f "
                  "| %.3f | %d (%d) | %d | %.1f° (%.1f°) | %d | %.1f |"
                  % (name, angle, row["bc_in"], row["bc_out"], row["ratio"], singular,
                     row["per_singular"], "yes" if row["singularities"] else "**no**",
                     "yes" if row["loops"] else "**no**", row["sj_in"], sj["min"], sj["mean"],
                     sj["p5"], m["inverted"], metrics_in["inverted"], m["degenerate"],
                     row["deviation"], j["separatrix_deviation"]["max_to_border_deg"],
                     row["over_bound"], j["time"]["total_s"]))
            sys.stdout.flush()

    print()
    print("| angle | runs ok | median BC ratio | median patches per singular | median SJ mean in "
          "→ out | singularities kept | border loops kept | inverted beyond the input's "
          "| max deviation between singular | runs above the bound | bunny patches per singular |")
    print("|" + "---|" * 11)
    for angle in angles:
        ok = [r for r in rows[angle] if r["ok"]]
        shared = [r for r in ok if r["name"] != BUNNY]

        def median(key):
            return statistics.median(r[key] for r in shared) if shared else float("nan")

        bunny = [r for r in ok if r["name"] == BUNNY]
        print("| %g° | %d of %d | %.3f | %.2f | %.3f → %.3f | %d | %d | %d | %.1f° | %d | %s |"
              % (angle, len(ok), len(rows[angle]), median("ratio"), median("per_singular"),
                 median("sj_in"), median("sj"), sum(r["singularities"] for r in ok),
                 sum(r["loops"] for r in ok),
                 sum(max(0, r["inverted"] - r["inverted_in"]) for r in ok),
                 max((r["deviation"] for r in ok), default=float("nan")),
                 sum(r["over_bound"] > 0 for r in ok),
                 "%.2f" % bunny[0]["per_singular"] if bunny else "–"))


if __name__ == "__main__":
    main()
