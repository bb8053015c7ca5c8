"""bimdf: exact minimum-deviation flows in bidirected graphs (Bi-MDF), and quad meshing with them.

Solve a problem built from numpy arrays::

    import numpy as np, bimdf
    p = bimdf.Problem(2, ends=[[0, 1]], kinds=[[1, 1]], upper=[10],
                      cost={"kind": "quad", "target": [3.5]}, demand=[4, 4])
    s = bimdf.solve(p)          # s.flow, s.objective, s.status == "optimal"

Remesh a QuadWild layout, requantize a quad mesh, measure a mesh::

    V, F, report = bimdf.remesh("bunny/bunny.obj", scale=1.0)
    V2, F2, report2 = bimdf.requantize(V, F, coarse=True)
    bimdf.metrics(V2, F2)["scaled_jacobian"]

See docs/python.md for the whole API; every function's docstring says what it takes.
"""

from ._bimdf import (  # noqa: F401  (the public API)
    INF,
    CollapseError,
    Cost,
    FlowCheck,
    Infeasible,
    InputError,
    Problem,
    Solution,
    SolverError,
    __version__,
    base_complex_patches,
    check,
    metrics,
    parse,
    quantize,
    read,
    read_obj,
    remesh,
    requantize,
    solve,
    write_obj,
)

__all__ = [
    "INF", "CollapseError", "Cost", "FlowCheck", "Infeasible", "InputError", "Problem",
    "Solution", "SolverError", "__version__", "base_complex_patches", "check", "metrics", "parse",
    "quantize", "read", "read_obj", "remesh", "requantize", "solve", "write_obj",
]
