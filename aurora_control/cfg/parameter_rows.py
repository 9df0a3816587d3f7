"""The parameter table's rows (include/aurora_control/params/parameter_table.h,
kParameterTable), read from the header itself: Controller.cfg generates the
live settings' limits from them, so the table stays the one source (as PX4
generates its parameter metadata from one file). A row the reader cannot
parse stops the build with the row's text."""
import os
import re

HEADER = os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, "include", "aurora_control", "params",
                      "parameter_table.h")
TOKEN = re.compile(r'"(?:[^"\\]|\\.)*"|[{},]|[^\s{},"]+')


def _value(tokens):
    """One field: adjacent string literals joined, a number, kNoValue (None), nullptr (None), or a name."""
    if tokens[0].startswith('"'):
        return "".join(t[1:-1] for t in tokens)
    text = " ".join(tokens)
    if text in ("kNoValue", "nullptr"):
        return None
    try:
        return float(text)
    except ValueError:
        return text


def _rows(body):
    rows, fields, current, depth = [], [], [], 0
    for tok in TOKEN.findall(body):
        if tok == "{":
            depth += 1
            fields, current = [], []
        elif tok == "}":
            if current:
                fields.append(_value(current))
            rows.append(fields)
            depth -= 1
            current = []
        elif tok == ",":
            if depth == 1 and current:
                fields.append(_value(current))
            current = []
        elif depth == 1:
            current.append(tok)
    return rows


def rows(header=HEADER):
    """Every row as a dict: name, kind, default, min, max, unit, doc, choices, live."""
    text = open(header).read()
    start = text.index("kParameterTable[kParameterRows] = {") + len("kParameterTable[kParameterRows] = {")
    body = text[start:text.index("\n};", start)]
    keys = ("name", "kind", "default", "min", "max", "unit", "doc", "choices", "live")
    out = []
    for fields in _rows(body):
        if not 6 <= len(fields) <= len(keys) or not isinstance(fields[3], float):
            raise SystemExit("parameter_rows.py: cannot read the row %r of %s" % (fields, header))
        out.append(dict(zip(keys, fields + [None] * (len(keys) - len(fields)))))
    return out
