"""What the paper uses (paper/inputs.yaml), read and checked once.

The file names the experiments the paper draws on (their files, the solvers
whose code they depend on, the modes that run them), and, per quoted number,
table and figure, which experiment and which file and key it comes from. The
generator reads nothing else, so pointing the paper at new data is an edit of
that file. Every rule broken raises InputsError naming the entry and the key.
"""
import re
from dataclasses import dataclass, field

import yaml

COMMANDS = ("experiment", "calibrate", "data")
MODES = ("quick", "full")
MACRO_NAME = re.compile(r"^[A-Za-z]+$")
ENTRY_ID = re.compile(r"^[a-z][a-z0-9_]*$")


class InputsError(ValueError):
    """A rule of inputs.yaml broken: names the entry, the key and the rule."""


@dataclass(frozen=True)
class ExperimentInput:
    id: str
    command: str               # experiment | calibrate | data (a committed run folder)
    path: str                  # experiment file, or the data folder (repository-relative)
    solvers: tuple             # solvers whose code the results depend on
    modes: tuple               # modes that run it; otherwise a fresh cached folder is used
    optional: bool = False     # absent file: its numbers print as "not yet run"
    estimate_s: float = 60.0   # first-run estimate, until a manifest gives the real time
    depends_on: tuple = ()     # files/folders it reads that its file does not name (a plot's reference data)


@dataclass(frozen=True)
class ValueSource:
    """One value: a key path in a JSON file, or a cell of a CSV file, of one experiment's folder."""
    experiment: str
    file: str
    key: str = ""              # JSON: dotted path, [3] indexes, [name=value] selects
    row: tuple = ()            # CSV: (column, value) that selects the row
    column: str = ""           # CSV: the column


@dataclass(frozen=True)
class MacroInput:
    name: str
    source: ValueSource
    format: str = "{:.3g}"     # Python format of the value after scaling
    scale: float = 1.0


TABLE_SIZES = ("small", "footnotesize", "scriptsize")


@dataclass(frozen=True)
class ColumnInput:
    heading: str
    key: str                   # JSON key path in each row, or CSV column
    format: str = "{}"
    scale: float = 1.0
    if_missing: str = ""       # printed when a row has no such key (empty: that is an error)
    until: str = ""            # text values: only what comes before its first occurrence (the caption says the rest)


@dataclass(frozen=True)
class TableInput:
    name: str
    experiment: str
    file: str
    rows: str                  # JSON: key path of the list of rows; CSV: empty
    columns: tuple
    caption: str
    filter: tuple = ()         # (key, value): keep only rows whose key equals value
    size: str = "small"        # the table's font size: small, footnotesize or scriptsize


@dataclass(frozen=True)
class FigureInput:
    name: str
    experiment: str
    script: str                # plot script (repository-relative), run with the folder
    output: str                # the PDF the script writes (its PNG name with .pdf)
    subfolder: str = ""        # run the script on this subfolder of the experiment's folder


@dataclass(frozen=True)
class PaperInputs:
    experiments: tuple
    macros: tuple
    tables: tuple
    figures: tuple
    cache_dir: str = "runs/paper"
    by_id: dict = field(default_factory=dict, compare=False)

    def experiment(self, experiment_id):
        return self.by_id[experiment_id]


def _require(entry, key, where):
    if key not in entry:
        raise InputsError(f"{where}: missing key '{key}'")
    return entry[key]


def _allowed(entry, keys, where):
    if not isinstance(entry, dict):
        raise InputsError(f"{where}: expected a mapping, got {type(entry).__name__}")
    unknown = sorted(set(entry) - set(keys))
    if unknown:
        raise InputsError(f"{where}: unknown key(s) {', '.join(unknown)} (allowed: {', '.join(keys)})")


def _experiment(entry, k):
    where = f"experiments[{k}]"
    _allowed(entry, ("id", "command", "file", "folder", "solvers", "modes", "optional", "estimate_s", "depends_on"),
             where)
    eid = str(_require(entry, "id", where))
    if not ENTRY_ID.match(eid):
        raise InputsError(f"{where}.id: expected lower-case letters, digits and _, got '{eid}'")
    command = _require(entry, "command", where)
    if command not in COMMANDS:
        raise InputsError(f"{where}.command: expected one of {', '.join(COMMANDS)}, got '{command}'")
    path = entry.get("folder") if command == "data" else entry.get("file")
    if not path:
        raise InputsError(f"{where}: '{'folder' if command == 'data' else 'file'}' is required for {command}")
    modes = tuple(entry.get("modes", ()))
    if command == "data" and modes:
        raise InputsError(f"{where}.modes: a data folder is never run (remake it with scripts/make-canonical-data.sh)")
    for mode in modes:
        if mode not in MODES:
            raise InputsError(f"{where}.modes: expected quick or full, got '{mode}'")
    estimate = float(entry.get("estimate_s", 60.0))
    if estimate <= 0:
        raise InputsError(f"{where}.estimate_s: expected > 0, got {estimate}")
    return ExperimentInput(eid, command, str(path), tuple(entry.get("solvers", ())), modes,
                           bool(entry.get("optional", False)), estimate,
                           tuple(str(d) for d in entry.get("depends_on", ())))


def _source(entry, where):
    row = entry.get("row", {})
    if not isinstance(row, dict) or len(row) > 1:
        raise InputsError(f"{where}.row: expected one 'column: value' pair, got {row!r}")
    source = ValueSource(str(_require(entry, "from", where)), str(_require(entry, "file", where)),
                         str(entry.get("key", "")), tuple((str(c), str(v)) for c, v in row.items()),
                         str(entry.get("column", "")))
    if source.file.endswith(".csv") != bool(source.column):
        raise InputsError(f"{where}: a CSV value needs 'column' (and 'row'), a JSON value 'key'")
    if not source.file.endswith(".csv") and not source.key:
        raise InputsError(f"{where}.key: required for a JSON value")
    return source


def _macro(name, entry):
    where = f"macros.{name}"
    _allowed(entry, ("from", "file", "key", "row", "column", "format", "scale"), where)
    if not MACRO_NAME.match(name):
        raise InputsError(f"{where}: a LaTeX macro name is letters only, got '{name}'")
    fmt = str(entry.get("format", "{:.3g}"))
    try:
        fmt.format(1.0)
    except (ValueError, IndexError) as e:
        raise InputsError(f"{where}.format: '{fmt}' does not format a number ({e})") from None
    return MacroInput(name, _source(entry, where), fmt, float(entry.get("scale", 1.0)))


def _table(name, entry):
    where = f"tables.{name}"
    _allowed(entry, ("from", "file", "rows", "columns", "caption", "filter", "size"), where)
    columns = []
    for c, col in enumerate(_require(entry, "columns", where)):
        _allowed(col, ("heading", "key", "format", "scale", "if_missing", "until"), f"{where}.columns[{c}]")
        columns.append(ColumnInput(str(_require(col, "heading", f"{where}.columns[{c}]")),
                                   str(_require(col, "key", f"{where}.columns[{c}]")),
                                   str(col.get("format", "{}")), float(col.get("scale", 1.0)),
                                   str(col.get("if_missing", "")), str(col.get("until", ""))))
    size = str(entry.get("size", "small"))
    if size not in TABLE_SIZES:
        raise InputsError(f"{where}.size: '{size}' is not one of {', '.join(TABLE_SIZES)}")
    flt = entry.get("filter", {})
    return TableInput(name, str(_require(entry, "from", where)), str(_require(entry, "file", where)),
                      str(entry.get("rows", "")), tuple(columns), str(_require(entry, "caption", where)),
                      tuple((str(k), str(v)) for k, v in flt.items()), size)


def _figure(name, entry):
    where = f"figures.{name}"
    _allowed(entry, ("from", "script", "output", "subfolder"), where)
    output = str(_require(entry, "output", where))
    if not output.endswith(".pdf"):
        raise InputsError(f"{where}.output: expected a .pdf file name, got '{output}'")
    return FigureInput(name, str(_require(entry, "from", where)), str(_require(entry, "script", where)), output,
                       str(entry.get("subfolder", "")))


def _check_references(inputs):
    for group, items in (("macros", inputs.macros), ("tables", inputs.tables), ("figures", inputs.figures)):
        for item in items:
            eid = item.source.experiment if group == "macros" else item.experiment
            if eid not in inputs.by_id:
                raise InputsError(f"{group}.{item.name}.from: no experiment '{eid}' (experiments: "
                                  f"{', '.join(inputs.by_id)})")


def parse_inputs(text, origin="inputs.yaml"):
    """PaperInputs from the YAML text of inputs.yaml; InputsError names what is wrong."""
    try:
        doc = yaml.safe_load(text) or {}
    except yaml.YAMLError as e:
        raise InputsError(f"{origin}: not YAML: {e}") from None
    _allowed(doc, ("cache_dir", "experiments", "macros", "tables", "figures"), origin)
    experiments = tuple(_experiment(e, k) for k, e in enumerate(doc.get("experiments", [])))
    by_id = {}
    for e in experiments:
        if e.id in by_id:
            raise InputsError(f"{origin}: experiments: id '{e.id}' twice")
        by_id[e.id] = e
    inputs = PaperInputs(experiments,
                         tuple(_macro(n, m) for n, m in (doc.get("macros") or {}).items()),
                         tuple(_table(n, t) for n, t in (doc.get("tables") or {}).items()),
                         tuple(_figure(n, f) for n, f in (doc.get("figures") or {}).items()),
                         str(doc.get("cache_dir", "runs/paper")), by_id)
    _check_references(inputs)
    return inputs


def load_inputs(path):
    with open(path, encoding="utf-8") as f:
        return parse_inputs(f.read(), path)
