#!/usr/bin/env python3
"""The worked example of docs/python.md: a Bi-MDF problem from numpy arrays, solved and checked;
then the bundled bunny layout remeshed, measured and drawn with matplotlib.

    PYTHONPATH=build/python python3 examples/python/worked_example.py [OUT.png]
"""

import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # draw to a file, no display needed
import matplotlib.pyplot as plt
import numpy as np
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

import bimdf

# 1. A small problem from arrays: four edges, each with a target it would like to carry.
#    Edge 0 runs from node 0 (head) to node 1 (tail), edge 1 is two-headed (nodes 1 and 2),
#    edges 2 and 3 are outer edges with a single end. Conservation: the flows of the ends at a
#    node, heads counted +1 and tails −1, sum to its demand.
ends = np.array([[0, 1], [1, 2], [2, -1], [0, -1]])
kinds = np.array([[1, -1], [1, 1], [-1, 0], [1, 0]])  # +1 head, -1 tail, 0: no second end
problem = bimdf.Problem(
    3,
    ends=ends,
    kinds=kinds,
    lower=[0, 0, 0, -5],
    upper=[10, 10, np.inf, 5],
    cost={"kind": "quad", "target": [3.4, 1.2, 2.5, 0.0], "weight": [1.0, 1.0, 2.0, 0.5]},
    demand=[3, -2, 0],
)
solution = bimdf.solve(problem)
print(f"status {solution.status}, objective {solution.objective:.4f}, flow {solution.flow}")
check = bimdf.check(problem, solution.flow)
print(f"check: feasible {check.feasible}, objective {check.objective:.4f}")

# 2. Remesh the bundled QuadWild layout and look at the result.
layout = Path(__file__).resolve().parents[1] / "npm_bunny" / "npm_bunny.obj"
V, F, report = bimdf.remesh(str(layout), scale=1.5)
m = report["metrics"]
print(f"remesh: {len(F)} quads, {m['singular_vertices']} singular vertices, scaled Jacobian "
      f"min {m['scaled_jacobian']['min']:.3f} mean {m['scaled_jacobian']['mean']:.3f}, "
      f"{m['inverted']} inverted")
V2, F2, report2 = bimdf.requantize(V, F, coarse=True)
print(f"requantize --coarse: {len(F2)} quads, base complex "
      f"{report2['metrics']['base_complex_faces']} patches (input "
      f"{bimdf.metrics(V, F)['base_complex_faces']})")

fig = plt.figure(figsize=(6, 6))
ax = fig.add_subplot(projection="3d")
ax.add_collection3d(Poly3DCollection(V[F], facecolor="lightsteelblue", edgecolor="k",
                                     linewidth=0.2))
ax.set_xlim(V[:, 0].min(), V[:, 0].max())
ax.set_ylim(V[:, 1].min(), V[:, 1].max())
ax.set_zlim(V[:, 2].min(), V[:, 2].max())
ax.set_box_aspect(np.ptp(V, axis=0))
ax.view_init(elev=100, azim=-90)
ax.set_axis_off()
out = sys.argv[1] if len(sys.argv) > 1 else "bunny_quads.png"
fig.savefig(out, dpi=120, bbox_inches="tight")
print(f"drawn to {out}")
