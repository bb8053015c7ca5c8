# Type stubs of the compiled module bimdf._bimdf (python/src/*.cpp); docs/python.md explains
# each function. Arrays: vertices float64 (n, 3), quads int64 (m, 4), flows int64 (m,).
import os
from typing import Any, Callable, Sequence, Union

import numpy as np
import numpy.typing as npt

__version__: str
INF: int  # the explicit infinite bound (int64 max); ±inf floats are accepted as bounds too

class InputError(ValueError): ...  # invalid problem or file; message names file, line, node/edge
class SolverError(RuntimeError): ...
class CollapseError(RuntimeError): ...
class Infeasible(Exception): ...  # proven infeasible; the message gives the proof

ArrayLike = npt.ArrayLike
PathLike = Union[str, os.PathLike[str]]

class Cost:
    def __init__(self) -> None: ...
    @staticmethod
    def zero(guess: int = 0) -> Cost: ...
    @staticmethod
    def linear(slope: float) -> Cost: ...
    @staticmethod
    def abs(target: float, weight: float = 1.0) -> Cost: ...
    @staticmethod
    def asym_abs(target: float, weight_below: float, weight_above: float) -> Cost: ...
    @staticmethod
    def quad(target: float, weight: float = 1.0) -> Cost: ...
    @staticmethod
    def piecewise(first: int, values: Sequence[float]) -> Cost: ...
    @staticmethod
    def scale_factor(target: float, weight: float = 1.0, eps: float = 0.1) -> Cost: ...
    @staticmethod
    def sum(terms: Sequence[Cost]) -> Cost: ...
    @property
    def kind(self) -> str: ...
    @property
    def target(self) -> float: ...
    @property
    def weight(self) -> float: ...
    def __call__(self, x: int) -> float: ...

End = tuple[int, Union[str, bool]]  # (node, "head" | "tail")

class Problem:
    def __init__(
        self,
        num_nodes: int = 0,
        ends: ArrayLike | None = None,  # (m, 2) node ids; -1 second: outer edge
        kinds: ArrayLike | None = None,  # (m, 2) +1 head, -1 tail, 0 missing end
        lower: ArrayLike | None = None,  # (m,) default 0
        upper: ArrayLike | None = None,  # (m,) default inf
        cost: Sequence[Cost] | dict[str, Any] | None = None,
        demand: ArrayLike | None = None,  # (num_nodes,) default 0
    ) -> None: ...
    def add_node(self, demand: int = 0) -> int: ...
    def add_edge(
        self, a: End, b: End | None = None, lower: float = 0, upper: float = ..., cost: Cost = ...
    ) -> int: ...
    @property
    def num_nodes(self) -> int: ...
    @property
    def num_edges(self) -> int: ...
    @property
    def demand(self) -> npt.NDArray[np.int64]: ...
    @property
    def lower(self) -> npt.NDArray[np.int64]: ...
    @property
    def upper(self) -> npt.NDArray[np.int64]: ...
    @property
    def ends(self) -> npt.NDArray[np.int32]: ...
    @property
    def kinds(self) -> npt.NDArray[np.int8]: ...
    @property
    def costs(self) -> list[Cost]: ...
    def validate(self) -> None: ...
    def write(self, path: str, format: str = "", libsatsuma_compatible: bool = False) -> None: ...

def read(path: str) -> Problem: ...
def parse(text: str) -> Problem: ...

class Solution:
    @property
    def flow(self) -> npt.NDArray[np.int64]: ...
    @property
    def objective(self) -> float: ...
    @property
    def status(self) -> str: ...  # "optimal" | "feasible"
    @property
    def lower_bound(self) -> float: ...
    @property
    def gap(self) -> float: ...
    @property
    def rounds(self) -> int: ...
    @property
    def stats(self) -> dict[str, Any]: ...
    @property
    def times(self) -> dict[str, float]: ...

class FlowCheck:
    @property
    def feasible(self) -> bool: ...
    @property
    def size_ok(self) -> bool: ...
    @property
    def objective(self) -> float: ...
    @property
    def bound_violations(self) -> list[tuple[int, int]]: ...  # (edge, flow)
    @property
    def conservation_violations(self) -> list[tuple[int, int, int]]: ...  # (node, net, demand)

def solve(
    problem: Problem,
    *,
    exact: bool = True,
    time_limit: float | None = None,
    threads: int = 1,
    progress: Callable[[dict[str, Any]], None] | None = None,
    max_rounds: int | None = None,
    max_deviation: int = 5,
) -> Solution: ...
def check(problem: Problem, flow: ArrayLike) -> FlowCheck: ...

Layout = Union[PathLike, tuple[ArrayLike, ArrayLike, ArrayLike, Sequence[ArrayLike]]]
Mesh = tuple[npt.NDArray[np.float64], npt.NDArray[np.int64], dict[str, Any]]

def quantize(
    layout: Layout,
    *,
    scale: float = 1.0,
    edge_length: float | None = None,
    target_faces: int | None = None,
    align: bool = True,
    threads: int = 1,
    time_limit: float | None = None,
) -> dict[str, Any]: ...
def remesh(
    layout: Layout,
    *,
    scale: float = 1.0,
    edge_length: float | None = None,
    target_faces: int | None = None,
    align: bool = True,
    smooth_iterations: int = 30,
    smooth_damping: float = 0.5,
    quality_rounds: int = 30,
    threads: int = 1,
    time_limit: float | None = None,
    sharp_angle: float = 35.0,
) -> Mesh: ...
def requantize(
    V: ArrayLike,
    F: ArrayLike,
    *,
    scale: float = 1.0,
    edge_length: float | None = None,
    target_faces: int | None = None,
    coarse: bool = False,
    max_angle: float | None = None,
    relaxed: bool = False,
    relaxed_weight: float = 1.0,
    sharp_angle: float = 35.0,
    cost: str = "quadratic",
    coarse_lengths: str = "uniform",
    calibrate: bool = True,
    smooth_iterations: int = 30,
    smooth_damping: float = 0.5,
    quality_rounds: int = 30,
    threads: int = 1,
    half_arc: str = "auto",
    reorder_weight: float = 1.0,
    keep_crossings: bool = False,
) -> Mesh: ...
def metrics(
    V: ArrayLike,
    F: ArrayLike,
    reference: PathLike | tuple[ArrayLike, ArrayLike] | None = None,
) -> dict[str, Any]: ...
def read_obj(path: PathLike) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]: ...
def write_obj(path: PathLike, V: ArrayLike, F: ArrayLike) -> None: ...
