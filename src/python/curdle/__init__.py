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

import dataclasses
import decimal
import fractions
import json
import os
import re
import typing
import warnings

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


@dataclasses.dataclass(frozen=True)
class Recipe:
    """A recipe's TOML text and the path that names it in messages (mask files are read
    beside it)."""
    text: str
    path: str = "recipe.toml"

    @classmethod
    def from_file(cls, path: str | os.PathLike) -> Recipe:
        """The recipe in a TOML file.

        Parameters:
            path: a regular file of at most 4 MiB.
        Returns:
            the Recipe, its path naming it in messages.
        Raises:
            InputError: the file cannot be read, or is not TOML (naming the line).
        Example:
            >>> curdle.Recipe.from_file("patterns/courtyard-l-shaped.toml")
            Recipe('patterns/courtyard-l-shaped.toml', name='courtyard-l-shaped', 41 lines)
        """
        path = os.fspath(path)
        return cls.from_text(_curdle.read_recipe(path), path)

    @classmethod
    def from_text(cls, text: str, path: str = "recipe.toml") -> Recipe:
        """A recipe from its TOML text.

        Parameters:
            text: the recipe's TOML.
            path: the name messages give it (and where mask files are read beside).
        Returns:
            the Recipe; its keys are checked when it runs, after any overrides.
        Raises:
            InputError: the text is not TOML (naming the line).
        Example:
            >>> curdle.Recipe.from_text('name = "t"\\n[lattice]\\nbase = 2\\n...')
        """
        _curdle.check_toml(text, path)
        return cls(text, path)

    def __repr__(self) -> str:
        name = re.search(r'^name\s*=\s*"([^"]*)"', self.text, re.M)
        return (f"Recipe({self.path!r}, name={name.group(1) if name else None!r}, "
                f"{self.text.count(chr(10)) + 1} lines)")

    def generate(self, seed: int | str | None = None,
                 window: typing.Sequence[int] | str | None = None,
                 overrides: typing.Mapping[str, object] | None = None, layout: bool = True,
                 threads: int = 0, max_memory: int = 0) -> Run:
        """Curdles this recipe (curdle.generate with this recipe).

        Parameters:
            seed: 0 to 2^64 - 1; None: the recipe's `seed`.
            window: (x, y, w, h) in cells, or "x,y,w,h"; None: the recipe's or the field.
            overrides: dotted recipe keys and their values, e.g. {"lattice.base": 3,
                "curds.0.probabilities": [Fraction(1, 5), 0.5, "2/3"]} (probabilities as
                Fraction, float, int, Decimal or text such as "1/5").
            layout: build the [layout] when the recipe has one.
            threads: worker threads (0: all cores).
            max_memory: bytes (0: half the machine's).
        Returns:
            the Run: its values, report, layout and every output's bytes.
        Raises:
            InputError: a key or value is wrong (naming it and what is allowed).
            ResourceLimitError: the run needs more than max_memory.
            KeyboardInterrupt: Ctrl-C.
        Example:
            >>> run = recipe.generate(seed=7, overrides={"lattice.base": 3})
        """
        return generate(self, seed, window, overrides, layout, threads, max_memory)


@dataclasses.dataclass(frozen=True)
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
    facade: str | None = None       # a building's: its façade ("S", "E2")
    strip_x_mm: float | None = None  # and where it lies on the unrolled strip
    strip_y_mm: float | None = None
    polygon: list | None = dataclasses.field(default=None, repr=False)


_WORDS = ("element_id", "lot", "element_type", "colour", "material", "shape_wkt", "facade")


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

    def __repr__(self) -> str:
        f = self._facts
        return (f"Layout({f['kind']!r}, {f['width_mm']:g} x {f['height_mm']:g} mm, "
                f"{f['elements']} {f['element_type']}s)")

    def columns(self) -> dict[str, typing.Any]:
        """schedule.csv as columns.

        Returns:
            {column: values}: NumPy arrays of numbers (NaN where the CSV is empty) and lists
            of words (element_id, lot, element_type, colour, material, shape_wkt, facade:
            a building's façade, empty elsewhere).
        Raises:
            InputError: never for a layout made by generate.
        Example:
            >>> run.layout.columns()["area_m2"].sum()
        """
        if self._columns is None:
            self._columns = self._run._native.schedule_columns()
        return self._columns

    def table(self) -> np.recarray:
        """schedule.csv as a NumPy structured array.

        Returns:
            one record per element, one field per column (curds as 0/1 fields named after
            them; a Markov curd's field its state).
        Raises:
            InputError: never for a layout made by generate.
        Example:
            >>> t = run.layout.table(); t[t.material == "Basalt"].area_m2.sum()
        """
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
        arrays = [np.asarray(a) for a in arrays]
        return np.rec.fromarrays(arrays, dtype=[(n, a.dtype) for n, a in zip(names, arrays)])

    @property
    def elements(self) -> list[Element]:
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
                facade=c["facade"][i] or None,
                strip_x_mm=_optional(c["strip_x_mm"][i]),
                strip_y_mm=_optional(c["strip_y_mm"][i]),
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

    @property
    def seed(self) -> int:
        """The seed the curds were drawn with, 0 to 2^64 - 1."""
        return self._native.seed

    @property
    def name(self) -> str:
        """The recipe's `name`, as its files and drawings give it."""
        return self._native.name

    def __repr__(self) -> str:
        shape = " x ".join(str(n) for n in reversed(self.values.shape))
        layout = f", layout={self._native.layout_facts()['kind']!r}" if self._native.has_layout \
            else ""
        return (f"Run({self.name!r}, seed={self.seed}, curds={self.curd_names}, "
                f"cells {shape}{layout})")

    @property
    def curd_names(self) -> list[str]:
        """The recipe's curds by name, one per [[curds]] table."""
        return [c[0] for c in self._native.curd_bits]

    @property
    def curd_states(self) -> dict[str, list[str]]:
        """Each Markov curd's states by name, "dead" first: index i is state i."""
        return {c[0]: list(c[3]) for c in self._native.curd_bits if c[3]}

    @property
    def origin(self) -> tuple[int, ...]:
        """The view's first cell (x[, y[, z]]) in cells from the lattice origin."""
        return tuple(self._native.origin)

    @property
    def values(self) -> np.ndarray:
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

    def curd(self, which: str | int) -> np.ndarray:
        """One plain curd's cells.

        Parameters:
            which: the curd's name or index.
        Returns:
            a bool array shaped like `values`: True where the curd survived.
        Raises:
            InputError: no such curd (the message lists the curds), or a Markov curd (use
                states).
        Example:
            >>> run.curd("dark").mean()
        """
        name, bit, _, states = self._curd_bits(which)
        if states:
            raise InputError(f"curd: {name!r} is a Markov curd; its cells' states are "
                             f"states({name!r})")
        return (self.values >> bit & 1).astype(bool)

    def states(self, which: str | int) -> np.ndarray:
        """A Markov curd's state in each cell: cells.csv's column of the curd.

        Parameters:
            which: the curd's name or index.
        Returns:
            uint8 shaped like `values`: 0 dead, i its i-th state (curd_states names them).
        Raises:
            InputError: no such curd (the message lists the curds), or a plain curd (use curd).
        Example:
            >>> run.states("wheys")
        """
        name, bit, planes, states = self._curd_bits(which)
        if not states:
            raise InputError(f"states: {name!r} is a plain curd; its cells are curd({name!r})")
        return (self.values >> bit & ((1 << planes) - 1)).astype("uint8")

    @property
    def report(self) -> dict[str, typing.Any]:
        """report.json as plain dicts and lists."""
        if self._report is None:
            self._report = json.loads(self.output_bytes("report.json"))
        return self._report

    @property
    def layout(self) -> Layout | None:
        """The layout, or None when the recipe has no [layout] or it was not asked for."""
        if self._layout is None and self._native.has_layout:
            self._layout = Layout(self)
        return self._layout

    def output_bytes(self, name: str) -> bytes:
        """One output as `curdle generate` writes it.

        Parameters:
            name: "layout.svg", "schedule.csv", "layout.gpkg", "layout.bin",
                "sheets/S-R1-C1.dxf", ... (curdle.outputs() lists them).
        Returns:
            the file's bytes.
        Raises:
            InputError: no such output, or one this run cannot write (naming why).
        Example:
            >>> open("layout.svg", "wb").write(run.output_bytes("layout.svg"))
        """
        return self._native.output_bytes(name)

    def write(self, outputs: typing.Iterable[str] | None = None,
              out: str | os.PathLike = ".") -> list[str]:
        """Writes outputs into a directory, replaced whole or not at all.

        Parameters:
            outputs: names as curdle.outputs() lists them; None: the defaults.
            out: the directory.
        Returns:
            the paths written. Defaults left out (for their size, or not installed here) are
            named in a warning.
        Raises:
            InputError: an unknown output, or a directory that cannot be written.
        Example:
            >>> run.write(["layout.pdf", "schedule.csv"], out="out/courtyard")
        """
        files, skipped = _curdle.write(self._native, list(outputs or []), os.fspath(out))
        for note in skipped:
            warnings.warn(note, stacklevel=2)
        return files


def generate(recipe: Recipe | str | os.PathLike, seed: int | str | None = None,
             window: typing.Sequence[int] | str | None = None,
             overrides: typing.Mapping[str, object] | None = None, layout: bool = True,
             threads: int = 0, max_memory: int = 0) -> Run:
    """Curdles a recipe, as `curdle generate` does.

    Parameters:
        recipe: a Recipe, or the path of its TOML file.
        seed: 0 to 2^64 - 1; None: the recipe's.
        window: (x, y, w, h) in cells, or "x,y,w,h"; None: the recipe's or the field.
        overrides: dotted keys and values ({"lattice.base": 3}; probabilities as
            fractions.Fraction, float, int, Decimal or text such as "1/5").
        layout: build the layout when the recipe has one.
        threads: worker threads (0: all cores).
        max_memory: bytes (0: half the machine's).
    Returns:
        a Run: its values, report, layout and every output's bytes.
    Raises:
        InputError: a key or value is wrong (naming it and what is allowed).
        ResourceLimitError: the run needs more than max_memory.
        KeyboardInterrupt: Ctrl-C.
    Example:
        >>> run = curdle.generate("patterns/courtyard-l-shaped.toml", seed=7)
    """
    if not isinstance(recipe, Recipe):
        recipe = Recipe.from_file(recipe)
    native = _curdle.generate(text=recipe.text, path=recipe.path,
                              overrides=_overrides(overrides), seed=_seed_text(seed),
                              window=_cells_text(window, "window"), layout=bool(layout),
                              threads=int(threads), max_memory=int(max_memory))
    return Run(native, recipe)


def search(recipe: Recipe | str | os.PathLike, seeds: str | range = "1..1000",
           segment: typing.Sequence[int] | str | None = None, targets: typing.Iterable[str] | str = (),
           top: int = 10, stride: int = 0, overrides: typing.Mapping[str, object] | None = None,
           threads: int = 0, max_memory: int = 0) -> dict:
    """The seeds (and segments) that best meet targets, as `curdle search` finds them.

    Parameters:
        recipe: a Recipe, or the path of its TOML file.
        seeds: "from..to", or a range of step 1.
        segment: (w, h) in cells to search segments of that size too; None: whole views.
        targets: such as "ratio:dark=0.3..0.4" or "cluster:dark<=12" (docs/page.md: Searching
            seeds and segments).
        top: how many hits to return.
        stride: cells between segments tried (0: a quarter of the segment).
        overrides, threads, max_memory: as generate.
    Returns:
        {"targets": [...], "hits": [{rank, seed, window, score, margin, measured, command,
        call}, ...]}, best first: seed an int, command the `curdle generate` line (None for a
        recipe with no file of its own: from_text), call the same as a Python call on it.
    Raises:
        InputError: a target, range or key is wrong (naming it and what is allowed).
    Example:
        >>> curdle.search("patterns/fig7-paving-20m.toml", range(1, 201), top=3)
    """
    if not isinstance(recipe, Recipe):
        recipe = Recipe.from_file(recipe)
    if isinstance(seeds, range):
        if seeds.step != 1 or len(seeds) == 0:
            raise InputError("seeds: a range of step 1 with at least one seed")
        seeds = f"{seeds.start}..{seeds.stop - 1}"
    if isinstance(targets, str):
        targets = [targets]
    hits = json.loads(_curdle.search(recipe.text, recipe.path, _overrides(overrides), str(seeds),
                                     _cells_text(segment, "segment"), list(targets), int(top),
                                     int(stride), int(threads), int(max_memory)))
    # A command runs only on a recipe file that holds this recipe's text.
    on_disk = os.path.isfile(recipe.path) and _same_text(recipe.path, recipe.text)
    for hit in hits["hits"]:
        hit["seed"] = int(hit["seed"])  # text in JSON, which a browser reads as doubles
        window = f", window={hit['window']!r}" if segment is not None else ""
        with_overrides = f", overrides={dict(overrides)!r}" if overrides else ""
        hit["call"] = f"recipe.generate(seed={hit['seed']}{window}{with_overrides})"
        if not on_disk:
            hit["command"] = None
    return hits


def _same_text(path: str, text: str) -> bool:
    try:
        with open(path, encoding="utf-8") as f:
            return f.read() == text
    except (OSError, UnicodeDecodeError):
        return False


def measure(path: str | os.PathLike, values: int = 2, threshold: float | None = None,
            base: int = 2, max_memory: int = 0) -> dict:
    """A picture quantised and box-counted, as `curdle measure` does.

    Parameters:
        path: a PNG, JPEG, TIFF or BMP (at most 64 MiB and 8192 x 8192 pixels).
        values: 2 to 16 values by luminance (value 0 the lightest).
        threshold: instead of values, darker than this (0 to 1) is value 1.
        base: the box sides' base.
        max_memory: bytes (0: half the machine's).
    Returns:
        measure.json as dicts: size, per value its count, share, lacunarity and box dimension.
    Raises:
        InputError: not a readable picture, or a value out of range.
    Example:
        >>> curdle.measure("facade.png", values=3)["values"][1]["box_dimension"]
    """
    return json.loads(_curdle.measure(os.fspath(path), int(values), threshold, int(base),
                                      int(max_memory)))


def fit(source: str | os.PathLike, base: int = 2, stages: int = 0, curds: int = 1,
        cell_pixels: int = 0, max_memory: int = 0, states: int = 0, stage_wise: bool = False,
        wheys: bool = False) -> dict:
    """A recipe fitted to a picture or a cells.csv, as `curdle fit` fits it.

    Parameters:
        source: a picture or a cells.csv.
        base: the lattice's base.
        stages: how many stages (0: as many as the source holds).
        curds: how many curds (a picture's values are 2^curds).
        cell_pixels: a picture's cells in pixels a side (0: found).
        max_memory: bytes (0: half the machine's).
        states: read the source as one Markov curd of this many living states instead (a
            picture's states + 1 tones, the lightest the ground); a cells.csv of a Markov curd
            is read as its chain whatever this says.
        stage_wise: the chain's matrix per stage, not one for every stage.
        wheys: the chain's dead row fitted too (dead cells that come back).
    Returns:
        the lattice, each curd's per-stage probability with its 95 % interval, measured and
        expected counts and the test of its branching, the warnings, and the recipe's TOML; with
        "chain" the fitted chain (each entry's value and 95 % interval, its stages beside the
        picture's, and the readings compared by BIC with the supported one), None without one,
        and "recipe_is_chain" whether the recipe is the chain's.
    Raises:
        InputError: the source cannot be read or does not fit (saying why).
    Example:
        >>> curdle.Recipe.from_text(curdle.fit("preview.png", stages=6)["toml"]).generate()
        >>> curdle.fit("paving.png", base=4, stages=3, states=2)["chain"]["supported"]
    """
    return _curdle.fit(os.fspath(source), int(base), int(stages), int(curds), int(cell_pixels),
                       int(max_memory), int(states), bool(stage_wise), bool(wheys))


def outputs() -> list[dict[str, typing.Any]]:
    """Every output a run can write.

    Returns:
        per output its name, description, whether it needs a [layout], whether it is written
        by default and the layout kind it is for (None: any).
    Raises:
        InputError: never.
    Example:
        >>> [o["name"] for o in curdle.outputs() if o["by_default"]]
    """
    return _curdle.outputs()
