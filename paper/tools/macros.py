"""Every number the paper's text quotes, as a LaTeX macro written from the run
folders (generated/macros.tex). A macro of an experiment that has no folder
prints \notyetrun{ID}; a value that the folder should hold and does not is an
error naming the file and key (inputs.yaml then points at the wrong place).
"""
import re

from latex import GENERATED_HEADER, escape, macro_definition, not_yet_run
from values import ValueMissing, csv_value, format_value, json_value

EXPONENT = re.compile(r"^(-?[0-9.]+)e([+-])0*([0-9]+)$")


def latex_number(text):
    """'1.2e+04' -> '\\ensuremath{1.2\\times10^{4}}'; other text escaped as it is."""
    m = EXPONENT.match(text)
    if not m:
        return escape(text)
    sign = "-" if m.group(2) == "-" else ""
    return rf"\ensuremath{{{m.group(1)}\times10^{{{sign}{m.group(3)}}}}}"


def source_value(folder, source):
    if source.file.endswith(".csv"):
        return csv_value(folder, source.file, source.row, source.column)
    return json_value(folder, source.file, source.key)


def macro_body(macro, status):
    if status is None or not status.usable:
        return not_yet_run(macro.source.experiment)
    value = source_value(status.folder, macro.source)
    return latex_number(format_value(value, macro.format, macro.scale))


def write_macros(path, inputs, statuses, extra=()):
    """Writes macros.tex; raises ValueMissing listing every value that could not be found."""
    lines, missing = [GENERATED_HEADER], []
    for macro in inputs.macros:
        try:
            lines.append(macro_definition(macro.name, macro_body(macro, statuses.get(macro.source.experiment))))
        except ValueMissing as e:
            missing.append(f"\\{macro.name}: {e}")
    for name, body in extra:
        lines.append(macro_definition(name, body))
    if missing:
        raise ValueMissing("values named in inputs.yaml are not in the run folders:\n  " + "\n  ".join(missing))
    with open(path, "w", encoding="utf-8") as f:
        f.writelines(lines)
