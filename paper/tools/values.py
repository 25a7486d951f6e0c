"""Values out of a run folder's JSON and CSV files, by the paths inputs.yaml gives.

A JSON key path is dotted, with [3] to index a list and [name=value] to pick
the element of a list whose `name` is `value`:
    parameters[name=ground.sand.alpha].standard_error
    runs[name=no_sweep].measures.streaks.ball.rms_m
Keys that themselves hold dots (measure names) are matched longest first.
A final `#count` gives the length of the list reached (`starts.#count`).
A missing value raises ValueMissing with the path and the file, never a default.
"""
import csv
import json
import math
import os


class ValueMissing(LookupError):
    """A path that does not lead to a value in the file named."""


def _tokens(path):
    """'a.b[2].c[name=x.y]' -> ['a', 'b', ('index', 2), 'c', ('select', 'name', 'x.y')]."""
    tokens, word, k = [], "", 0
    while k < len(path):
        ch = path[k]
        if ch == "[":
            end = path.index("]", k)
            if word:
                tokens.append(word)
                word = ""
            inner = path[k + 1:end]
            if "=" in inner:
                key, value = inner.split("=", 1)
                tokens.append(("select", key, value))
            else:
                tokens.append(("index", int(inner)))
            k = end + 1
            continue
        if ch == ".":
            if word:
                tokens.append(word)
            word = ""
        else:
            word += ch
        k += 1
    if word:
        tokens.append(word)
    return tokens


def _step_dict(node, tokens, k):
    """The value under the longest run of plain tokens from k that is a key of node."""
    end = k
    while end < len(tokens) and isinstance(tokens[end], str):
        end += 1
    for stop in range(end, k, -1):
        key = ".".join(tokens[k:stop])
        if key in node:
            return node[key], stop
    raise KeyError(tokens[k])


def lookup(document, path):
    """The value at `path` in a parsed JSON document; KeyError/IndexError when absent."""
    tokens = _tokens(path)
    node, k = document, 0
    while k < len(tokens):
        token = tokens[k]
        if token == "#count" and k == len(tokens) - 1 and isinstance(node, list):
            return len(node)
        if isinstance(token, str):
            if not isinstance(node, dict):
                raise KeyError(token)
            node, k = _step_dict(node, tokens, k)
            continue
        if not isinstance(node, list):
            raise KeyError(str(token))
        if token[0] == "index":
            node = node[token[1]]
        else:
            matches = [e for e in node if isinstance(e, dict) and str(e.get(token[1])) == token[2]]
            if len(matches) != 1:
                raise KeyError(f"[{token[1]}={token[2]}] matches {len(matches)} elements")
            node = matches[0]
        k += 1
    return node


def read_json(path):
    with open(path, encoding="utf-8") as f:
        return json.load(f)


def read_csv(path):
    with open(path, newline="", encoding="utf-8") as f:
        return list(csv.DictReader(f))


def json_value(folder, file, key):
    path = os.path.join(folder, file)
    try:
        return lookup(read_json(path), key)
    except FileNotFoundError:
        raise ValueMissing(f"{path}: no such file") from None
    except (KeyError, IndexError, ValueError) as e:
        raise ValueMissing(f"{path}: no value at '{key}' ({e})") from None


def csv_value(folder, file, row, column):
    path = os.path.join(folder, file)
    try:
        rows = read_csv(path)
    except FileNotFoundError:
        raise ValueMissing(f"{path}: no such file") from None
    if row:
        rows = [r for r in rows if r.get(row[0][0]) == row[0][1]]
    if len(rows) != 1 or column not in rows[0] or rows[0][column] == "":
        raise ValueMissing(f"{path}: no single row {dict(row)} with a value in column '{column}'")
    return rows[0][column]


def number(value, where):
    """A finite float from a JSON/CSV value; ValueMissing otherwise (never NaN in the paper)."""
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise ValueMissing(f"{where}: expected a number, got {value!r}") from None
    if not math.isfinite(x):
        raise ValueMissing(f"{where}: not a finite number ({value!r})")
    return x


def format_value(value, fmt, scale):
    """A number formatted by `fmt` after scaling; text (e.g. a version) as it is."""
    if isinstance(value, str):
        try:
            value = float(value)
        except ValueError:
            return value
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return str(value)
    return fmt.format(number(value, fmt) * scale)
