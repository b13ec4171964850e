"""curdle: random curds for façade, paving, perforation and park layouts, from Python.

The same library as the `curdle` program: a run from Python writes the same bytes as
`curdle generate`, and its errors carry the same messages.

    import curdle
    recipe = curdle.Recipe.from_file("patterns/courtyard-l-shaped.toml")
    run = recipe.generate(seed=7, overrides={"lattice.base": 3})
    run.values                    # NumPy array of each cell's value, [y, x] from run.origin
    run.curd("dark")              # that curd's cells, a bool array of the same shape
    run.report                    # report.json as dicts and lists
    run.layout.elements           # schedule.csv's rows as Element objects
    run.layout.table()            # the same as a NumPy structured array
    run.output_bytes("layout.svg")
    run.write(["layout.pdf", "schedule.csv"], out="out/courtyard")

The GIL is released while the engine runs; Ctrl-C stops a long run with KeyboardInterrupt.
"""

from __future__ import annotations

import decimal
import fractions
import json
import os
import re
import warnings
from dataclasses import dataclass, field
from typing import Iterable, Mapping, Sequence

import numpy as np

from . import _curdle
from ._curdle import InputError, ResourceLimitError, WorkStopped

__version__ = _curdle.version()
__all__ = ["Recipe", "Run", "Layout", "Element", "generate", "search", "measure", "fit",
           "outputs", "InputError", "ResourceLimitError", "WorkStopped"]


def _toml_value(value, key):
    """A Python value as the TOML text an override takes (`--set key=VALUE`)."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, np.integer)):
        return str(int(value))
    if isinstance(value, (float, np.floating)):
        return repr(float(value))
    if isinstance(value, fractions.Fraction):
        # Kept exact, as a recipe writes it: "1/5".
        return json.dumps(f"{value.numerator}/{value.denominator}")
    if isinstance(value, decimal.Decimal):
        if not value.is_finite():
            raise InputError(f"overrides {key}: {value} is not a finite number")
        return json.dumps(format(value, "f"))
    if isinstance(value, str):
        return json.dumps(value, ensure_ascii=False)
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_toml_value(v, key) for v in value) + "]"
    raise InputError(f"overrides {key}: {type(value).__name__} is not a recipe value; allowed: "
                     "bool, int, float, fractions.Fraction, decimal.Decimal, str and lists "
                     "of them")


def _overrides(overrides):
    if overrides is None:
        return []
    if not isinstance(overrides, dict):
        raise InputError("overrides: must be a dict of dotted recipe keys, "
                         "e.g. {\"lattice.base\": 3}")
    return [f"{key}={_toml_value(value, key)}" for key, value in overrides.items()]


def _cells_text(value, name):
    """A window or segment as a tuple of cells, or its text ("10,13,100,77")."""
    if value is None:
        return ""
    if isinstance(value, str):
        return value
    try:
        return ",".join(str(int(v)) for v in value)
    except (TypeError, ValueError):
        raise InputError(f"{name}: must be a tuple of whole numbers of cells, "
                         "e.g. (10, 13, 100, 77)") from None


def _seed_text(seed):
    if seed is None:
        return ""
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer, str)):
        raise InputError("seed: must be a whole number from 0 to 2^64 - 1")
    return str(seed)


@dataclass(frozen=True)
class Recipe:
    """A recipe's TOML text and the path that names it in messages (mask files are read
    beside it)."""
    text: str
    path: str = "recipe.toml"

    @classmethod
    def from_file(cls, path: str | os.PathLike) -> Recipe:
        """The recipe in the TOML file at `path` (a regular file of at most 4 MiB). Raises
        InputError for a file that cannot be read or is not TOML, as from_text."""
        path = os.fspath(path)
        return cls.from_text(_curdle.read_recipe(path), path)

    @classmethod
    def from_text(cls, text: str, path: str = "recipe.toml") -> Recipe:
        """A recipe from its TOML text; `path` names it in messages. Raises InputError, naming
        the line, for text that is not TOML; its keys are checked when it runs (overrides may
        still change them)."""
        _curdle.check_toml(text, path)
        return cls(text, path)

    def __repr__(self):
        name = re.search(r'^name\s*=\s*"([^"]*)"', self.text, re.M)
        return (f"Recipe({self.path!r}, name={name.group(1) if name else None!r}, "
                f"{self.text.count(chr(10)) + 1} lines)")

    def generate(self, seed: int | str | None = None,
                 window: Sequence[int] | str | None = None,
                 overrides: Mapping[str, object] | None = None, layout: bool = True,
                 threads: int = 0, max_memory: int = 0) -> Run:
        """Curdles this recipe; see curdle.generate, which this calls.

        seed:       0 to 2^64 - 1; None: the recipe's `seed`.
        window:     (x, y, w, h) in cells, or "x,y,w,h"; None: the recipe's or the field.
        overrides:  dotted recipe keys and their values, e.g.
                    {"lattice.base": 3, "curds.0.probabilities": [Fraction(1, 5), 0.5, "2/3"]}
                    (probabilities as Fraction, float, int or text such as "1/5").
        layout:     build the [layout] when the recipe has one.
        threads:    worker threads (0: all cores).
        max_memory: bytes (0: half the machine's).
        Raises InputError naming the key and what is allowed, ResourceLimitError above
        max_memory, KeyboardInterrupt on Ctrl-C."""
        return generate(self, seed, window, overrides, layout, threads, max_memory)


@dataclass(frozen=True)
class Element:
    """One row of schedule.csv: a piece as laid, lengths in mm from the layout's bottom-left
    corner. `polygon` holds the piece's outline as `shape_wkt` gives it (rings of (x, y), outer
    first, per part; a rectangle's four corners, a circle's chords), `opening` the centre and
    diameter of a round opening."""
    element_id: str
    lot: str
    level: int | None
    row: int
    column: int
    x_mm: float
    y_mm: float
    z_mm: float
    width_mm: float
    height_mm: float
    depth_mm: float | None
    area_m2: float
    stock_width_mm: float | None
    stock_height_mm: float | None
    value: int
    curds: dict
    element_type: str
    colour: str
    material: str
    cut: bool
    shape_wkt: str
    opening: tuple | None
    polygon: list = field(default=None, repr=False)


_WORDS = ("element_id", "lot", "element_type", "colour", "material", "shape_wkt")


def _optional(x):
    return None if np.isnan(x) else float(x)


class Layout:
    """A run's layout: facts (kind, size, legend, notes) and its elements."""

    def __init__(self, run):
        self._run = run
        self._facts = run._native.layout_facts()
        self._columns = None

    def __getattr__(self, name):
        try:
            return self.__dict__["_facts"][name]
        except KeyError:
            raise AttributeError(name) from None

    def __repr__(self):
        f = self._facts
        return (f"Layout({f['kind']!r}, {f['width_mm']:g} x {f['height_mm']:g} mm, "
                f"{f['elements']} {f['element_type']}s)")

    def columns(self):
        """schedule.csv as columns: NumPy arrays of numbers (NaN where the CSV is empty) and
        lists of words."""
        if self._columns is None:
            self._columns = self._run._native.schedule_columns()
        return self._columns

    def table(self):
        """schedule.csv as a NumPy structured array, one record per element, one field per
        column (curds as 0/1 fields named after them)."""
        c = self.columns()
        names, arrays = [], []
        for name, values in c.items():
            if name in _WORDS:
                values = np.array(values, dtype=str)
            names.append(name)
            arrays.append(values)
            if name == "value":
                # A plain curd's field is 0/1; a Markov curd's its state (0 dead, i state i).
                for curd, bit, planes, _ in self._run._native.curd_bits:
                    names.append(curd)
                    arrays.append(((values >> bit) & ((1 << planes) - 1)).astype(np.uint8))
        return np.rec.fromarrays(arrays, names=names)

    @property
    def elements(self):
        """Every row of schedule.csv as an Element, in the same order."""
        c = self.columns()
        curds = self._run._native.curd_bits
        out = []
        for i in range(len(c["element_id"])):
            value = int(c["value"][i])
            level = c["level"][i]
            diameter = _optional(c["opening_diameter_mm"][i])
            centre = (_optional(c["opening_x_mm"][i]), _optional(c["opening_y_mm"][i]))
            out.append(Element(
                element_id=c["element_id"][i], lot=c["lot"][i],
                level=None if np.isnan(level) else int(level),
                row=int(c["row"][i]), column=int(c["column"][i]),
                x_mm=float(c["x_mm"][i]), y_mm=float(c["y_mm"][i]), z_mm=float(c["z_mm"][i]),
                width_mm=float(c["width_mm"][i]), height_mm=float(c["height_mm"][i]),
                depth_mm=_optional(c["depth_mm"][i]), area_m2=float(c["area_m2"][i]),
                stock_width_mm=_optional(c["stock_width_mm"][i]),
                stock_height_mm=_optional(c["stock_height_mm"][i]),
                value=value,
                curds={n: value >> b & ((1 << p) - 1) for n, b, p, _ in curds},
                element_type=c["element_type"][i], colour=c["colour"][i],
                material=c["material"][i], cut=bool(c["cut"][i]), shape_wkt=c["shape_wkt"][i],
                opening=None if centre[0] is None else centre + (diameter,),
                polygon=self._run._native.element_outlines(i)))
        return out


class Run:
    """A generated run: its curds, report and layout, made once; any output's bytes from it."""

    def __init__(self, native, recipe):
        self._native = native
        self.recipe = recipe
        self._values = None
        self._report = None
        self._layout = None

    seed = property(lambda self: self._native.seed,
                    doc="The seed the curds were drawn with, 0 to 2^64 - 1")
    name = property(lambda self: self._native.name, doc="The recipe's `name`")

    def __repr__(self):
        shape = " x ".join(str(n) for n in reversed(self.values.shape))
        layout = f", layout={self._native.layout_facts()['kind']!r}" if self._native.has_layout \
            else ""
        return (f"Run({self.name!r}, seed={self.seed}, curds={self.curd_names}, "
                f"cells {shape}{layout})")
    curd_names = property(lambda self: [c[0] for c in self._native.curd_bits],
                          doc="The recipe's curds by name, one per [[curds]] table")
    curd_states = property(
        lambda self: {c[0]: list(c[3]) for c in self._native.curd_bits if c[3]},
        doc="Each Markov curd's states by name, \"dead\" first: index i is state i")
    origin = property(lambda self: tuple(self._native.origin),
                      doc="The view's first cell (x[, y[, z]]) in cells from the lattice origin")

    @property
    def values(self):
        """Each cell's value (bit i: curd i survived), uint16, indexed [x], [y, x] or [z, y, x]
        from `origin`: cells.csv's value column as an array."""
        if self._values is None:
            self._values = self._native.values()
            self._values.flags.writeable = False
        return self._values

    def _curd_bits(self, which):
        names = self.curd_names
        index = names.index(which) if isinstance(which, str) and which in names else which
        if isinstance(index, str) or not 0 <= int(index) < len(names):
            raise InputError(f"curd: {which!r} is not a curd; the curds are " + ", ".join(names))
        return self._native.curd_bits[int(index)]

    def curd(self, which):
        """One plain curd's cells (by name or index) as a bool array shaped like `values`."""
        name, bit, _, states = self._curd_bits(which)
        if states:
            raise InputError(f"curd: {name!r} is a Markov curd; its cells' states are "
                             f"states({name!r})")
        return (self.values >> bit & 1).astype(bool)

    def states(self, which):
        """A Markov curd's state in each cell (by name or index), uint8 shaped like `values`:
        0 dead, i its i-th state (curd_states names them); cells.csv's column of the curd."""
        name, bit, planes, states = self._curd_bits(which)
        if not states:
            raise InputError(f"states: {name!r} is a plain curd; its cells are curd({name!r})")
        return (self.values >> bit & ((1 << planes) - 1)).astype("uint8")

    @property
    def report(self):
        """report.json as plain dicts and lists."""
        if self._report is None:
            self._report = json.loads(self.output_bytes("report.json"))
        return self._report

    @property
    def layout(self):
        """The layout, or None when the recipe has no [layout] or it was not asked for."""
        if self._layout is None and self._native.has_layout:
            self._layout = Layout(self)
        return self._layout

    def output_bytes(self, name):
        """One output as `curdle generate` writes it: "layout.svg", "schedule.csv",
        "layout.bin", "sheets/S-R1-C1.dxf", ..."""
        return self._native.output_bytes(name)

    def write(self, outputs=None, out="."):
        """Writes the outputs named (None: the defaults) into the directory `out`, replaced
        whole or not at all; returns the paths written. Defaults left out for their size are
        named in a warning."""
        files, skipped = _curdle.write(self._native, list(outputs or []), os.fspath(out))
        for note in skipped:
            warnings.warn(note, stacklevel=2)
        return files


def generate(recipe: Recipe | str | os.PathLike, seed: int | str | None = None,
             window: Sequence[int] | str | None = None,
             overrides: Mapping[str, object] | None = None, layout: bool = True,
             threads: int = 0, max_memory: int = 0) -> Run:
    """Curdles `recipe` (a Recipe, or a path) with `seed` (None: the recipe's), over `window`
    ((x, y, w, h) in cells; None: the recipe's or the field), with `overrides` as a dict of
    dotted keys ({"lattice.base": 3}; probabilities as fractions.Fraction, float, int or text
    such as "1/5"). The layout is built when the recipe has one and `layout` is true.
    `max_memory` in bytes (0: half the machine's). Returns a Run: its values, report, layout
    and every output's bytes."""
    if not isinstance(recipe, Recipe):
        recipe = Recipe.from_file(recipe)
    native = _curdle.generate(text=recipe.text, path=recipe.path,
                              overrides=_overrides(overrides), seed=_seed_text(seed),
                              window=_cells_text(window, "window"), layout=bool(layout),
                              threads=int(threads), max_memory=int(max_memory))
    return Run(native, recipe)


def search(recipe: Recipe | str | os.PathLike, seeds: str | range = "1..1000",
           segment: Sequence[int] | str | None = None, targets: Iterable[str] | str = (),
           top: int = 10, stride: int = 0, overrides: Mapping[str, object] | None = None,
           threads: int = 0, max_memory: int = 0) -> dict:
    """The seeds (and segments of size `segment`, (w, h)) that best meet `targets`, as
    `curdle search` finds them: {"targets": [...], "hits": [{rank, seed, window, score,
    measured, command}, ...]}, best first."""
    if not isinstance(recipe, Recipe):
        recipe = Recipe.from_file(recipe)
    if isinstance(seeds, range):
        if seeds.step != 1 or len(seeds) == 0:
            raise InputError("seeds: a range of step 1 with at least one seed")
        seeds = f"{seeds.start}..{seeds.stop - 1}"
    if isinstance(targets, str):
        targets = [targets]
    hits = _curdle.search(recipe.text, recipe.path, _overrides(overrides), str(seeds),
                          _cells_text(segment, "segment"), list(targets), int(top), int(stride),
                          int(threads), int(max_memory))
    return json.loads(hits)


def measure(path: str | os.PathLike, values: int = 2, threshold: float | None = None,
            base: int = 2, max_memory: int = 0) -> dict:
    """A picture quantised to `values` values and box-counted: measure.json as dicts."""
    return json.loads(_curdle.measure(os.fspath(path), int(values), threshold, int(base),
                                      int(max_memory)))


def fit(source: str | os.PathLike, base: int = 2, stages: int = 0, curds: int = 1,
        cell_pixels: int = 0, max_memory: int = 0) -> dict:
    """A recipe fitted to a picture or a cells.csv, as `curdle fit` fits it: the lattice, each
    curd's per-stage probability with its 95 % interval, measured and expected counts and the
    test of its branching, the warnings, and the recipe's TOML (Recipe.from_text(result["toml"])
    runs it). `cell_pixels`: a picture's cells in pixels a side (0: found)."""
    return _curdle.fit(os.fspath(source), int(base), int(stages), int(curds), int(cell_pixels),
                       int(max_memory))


def outputs() -> list:
    """Every output a run can write: name, description, whether it needs a [layout] and
    whether it is written by default."""
    return _curdle.outputs()
