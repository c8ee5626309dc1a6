# Types of the public interface of `impact` (docs/python.md); python/tests/test_typing.py checks
# that every public name is here with the runtime's parameters, and that every annotation resolves.
import os
from typing import Any, Iterable, Mapping, Union

import numpy as np
import numpy.typing as npt

StrPath = Union[str, os.PathLike[str]]
#: A JSON document as Python values.
Document = dict[str, Any]
#: One merge patch or several, applied in order.
Patches = Union[Document, Iterable[Document], None]
ArrayLike = npt.ArrayLike
StateDict = dict[str, np.ndarray]

__version__: str
failure_causes: list[str]
update_statuses: list[str]
__all__: list[str]

class InputError(ValueError): ...

class RunError(RuntimeError):
    reason: str
    exit_code: int
    directory: str | None
    result: Any
    def __init__(self, reason: str, exit_code: int, directory: str | None = None,
                 result: Any = None) -> None: ...

class InputWarning(UserWarning): ...

class Table(dict[str, np.ndarray]):
    units: dict[str, str]
    def __init__(self, columns: Mapping[str, np.ndarray], units: dict[str, str],
                 **info: Any) -> None: ...
    def __getattr__(self, name: str) -> Any: ...

class Snapshot:
    time: float
    step: int
    file: str
    def __init__(self, time: float, file: str) -> None: ...
    @property
    def positions(self) -> np.ndarray: ...
    @property
    def fields(self) -> Table: ...
    @property
    def pieces(self) -> int: ...

class Run:
    directory: str
    history: Table
    summary: Document | None
    status: Document | None
    scene: Document | None
    snapshots: list[Snapshot]
    paths: dict[str, Table]
    def __init__(self, directory: str, history: Table, summary: Document | None,
                 status: Document | None, scene: Document | None, snapshots: list[Snapshot],
                 paths: dict[str, Table]) -> None: ...

class Material:
    def __init__(self, source: Union[StrPath, Document, "Material"], patches: Patches = None,
                 base_dir: StrPath | None = None) -> None: ...
    @property
    def name(self) -> str: ...
    @property
    def file(self) -> str: ...
    @property
    def warnings(self) -> list[str]: ...
    @property
    def density(self) -> float: ...
    @property
    def room_temperature(self) -> float: ...
    def to_dict(self) -> Document: ...
    def initial_state(self, temperature: float | None = None, n: int = 1) -> StateDict: ...

def data_path(*relative: str) -> str: ...
def load_material(source: Union[StrPath, Document, Material], patches: Patches = None,
                  base_dir: StrPath | None = None) -> Material: ...
def update(material: Union[Material, StrPath, Document], state: Mapping[str, ArrayLike],
           L: ArrayLike, dt: float,
           F1: ArrayLike | None = None) -> tuple[StateDict, dict[str, np.ndarray]]: ...
def run_path(path: Union[StrPath, Document], patches: Patches = None,
             base_dir: StrPath | None = None) -> Table: ...
def fit(config: Union[StrPath, Document], base_dir: StrPath | None = None) -> Document: ...
def check(config: Union[StrPath, Document], base_dir: StrPath | None = None) -> Document: ...
def check_scene(scene: Union[StrPath, Document], patches: Patches = None, threads: int = 0,
                base_dir: StrPath | None = None) -> Document: ...
def run_scene(scene: Union[StrPath, Document], out: StrPath, patches: Patches = None,
              threads: int = 0, progress: bool = False,
              base_dir: StrPath | None = None) -> Document: ...
def resume_scene(directory: StrPath, threads: int = 0, progress: bool = False) -> Document: ...
def read_history(directory: StrPath) -> Table: ...
def read_run(directory: StrPath) -> Run: ...
