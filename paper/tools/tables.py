"""The paper's tables as .tex files (generated/tables/NAME.tex), written from
the run folders' JSON lists or CSV rows as inputs.yaml describes them."""
import os

from latex import GENERATED_HEADER, not_yet_run
from macros import latex_number
from values import ValueMissing, format_value, lookup, read_csv, read_json


def table_rows(folder, table):
    """The rows (dicts) of a table: a JSON list at `rows`, or every CSV row; filtered."""
    path = os.path.join(folder, table.file)
    try:
        rows = read_csv(path) if table.file.endswith(".csv") else lookup(read_json(path), table.rows)
    except FileNotFoundError:
        raise ValueMissing(f"{path}: no such file") from None
    except (KeyError, IndexError) as e:
        raise ValueMissing(f"{path}: no list at '{table.rows}' ({e})") from None
    if not isinstance(rows, list):
        raise ValueMissing(f"{path}: '{table.rows}' is not a list")
    for key, value in table.filter:
        rows = [r for r in rows if str(lookup(r, key)) == value]
    return rows


def cell(row, column, where):
    try:
        value = lookup(row, column.key)
    except (KeyError, IndexError):
        if column.if_missing:
            return column.if_missing
        raise ValueMissing(f"{where}: a row has no '{column.key}'") from None
    if value is None or value == "":
        return "--"
    if column.until and isinstance(value, str):
        value = value.split(column.until, 1)[0]
    return latex_number(format_value(value, column.format, column.scale))


def tabular(table, rows, where):
    spec = "l" + "r" * (len(table.columns) - 1)
    lines = [f"\\begin{{tabular}}{{{spec}}}\n", "\\toprule\n",
             " & ".join(c.heading for c in table.columns) + " \\\\\n", "\\midrule\n"]
    for row in rows:
        lines.append(" & ".join(cell(row, c, where) for c in table.columns) + " \\\\\n")
    lines += ["\\bottomrule\n", "\\end{tabular}\n"]
    return lines


def write_table(folder_out, table, status):
    """Writes NAME.tex: a table float with the caption (prose) and the generated rows."""
    where = f"tables.{table.name}"
    lines = [GENERATED_HEADER, f"\\begin{{table}}[htbp]\n\\centering\\{table.size}\n",
             f"\\caption{{{table.caption}}}\\label{{tab:{table.name}}}\n"]
    if status is None or not status.usable:
        lines.append("\\fbox{" + not_yet_run(table.experiment) + "}\n")
    else:
        lines += tabular(table, table_rows(status.folder, table), where)
    lines.append("\\end{table}\n")
    with open(os.path.join(folder_out, f"{table.name}.tex"), "w", encoding="utf-8") as f:
        f.writelines(lines)


def write_tables(folder_out, inputs, statuses):
    os.makedirs(folder_out, exist_ok=True)
    for table in inputs.tables:
        write_table(folder_out, table, statuses.get(table.experiment))
