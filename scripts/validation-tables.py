#!/usr/bin/env python3
"""The tables of docs/validation.md, read from the reports that `pressridge tabulate --report`
wrote, so that each number is the report's (one source) and the page can be made again.

    scripts/validation-tables.py [--key HEADER=SCENE.KEY]... [--mj] [--cols LIST] \
        REPORT[#POINT-SUBSTRING#LABEL]...

Each REPORT contributes every grid point of its "Energy budget", "Ridge metrics" and
"Rafting" tables as one row; REPORT#SUBSTRING#LABEL takes only the point whose name contains
SUBSTRING and labels it LABEL (a first column "set"). --key adds a leading column with the
point's value of a scene key (e.g. --key "h (m)=sheet.thickness"); rows are sorted by the
--key columns, in the reports' order where none is given. --mj gives W and ΔPE in MJ/m.
--cols picks and orders the columns (default: every one below).

    scripts/validation-tables.py --check docs/validation.md

re-runs every command of this script in the page's ```sh blocks and checks that the table
after each is its output (scripts/test.sh runs it).

    scripts/validation-tables.py --write docs/validation.md

replaces each such table by its command's output, so that a page whose commands now name
new records (say paper5 for paper3) is made again in one step.
"""
import argparse
import math
import os
import re
import shlex
import sys

COLUMNS = {
    # name: (header, section, report column, format)
    "W": ("W (kJ/m)", "energy", "W (kJ/m)", "energy0"),
    "dPE": ("ΔPE (kJ/m)", "energy", "ΔPE (kJ/m)", "energy1"),
    "phif": ("Φ_f/W", "energy", "Φ_f/W", "mean"),
    "phii": ("Φ_i/W", "energy", "Φ_i/W", "mean"),
    "drag": ("drag/W", "energy", "drag/W", "mean"),
    "cf": ("W/ΔPE", "energy", "W/ΔPE", "as-is"),
    "sail": ("sail (m)", "metrics", "sail height (m)", "mean"),
    "keel": ("keel (m)", "metrics", "keel depth (m)", "mean"),
    "keelarea": ("keel area (m²/m)", "metrics", "keel area (m²/m)", "mean"),
    "Lh": ("L/h", "metrics", "L/h", "mean"),
    "rafted": ("rafted", "rafting", "rafted / known", "as-is"),
}
SECTIONS = {"energy": "## Energy budget", "metrics": "## Ridge metrics", "rafting": "## Rafting"}


def tables(path):
    """Section -> {point: {column: cell}} for the report at `path`."""
    try:
        text = open(path, encoding="utf-8").read().split("\n")
    except OSError as e:
        sys.exit(f"validation-tables: cannot read the report {path}: {e.strerror}")
    out = {}
    for name, heading in SECTIONS.items():
        start = next((i for i, l in enumerate(text) if l.startswith(heading)), None)
        if start is None:
            sys.exit(f"validation-tables: {path} has no section '{heading}'")
        rows = {}
        header = None
        for line in text[start + 1:]:
            if line.startswith("## "):
                break
            if not line.startswith("|"):
                continue
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            if header is None:
                header = cells
            elif not set(cells[0]) <= set("-"):
                rows[cells[0]] = dict(zip(header, cells))
        out[name] = rows
    return out


def split_cell(cell):
    """'665.1 ± 200.3' -> ('665.1', '200.3'); '0.77' -> ('0.77', None)."""
    m = re.match(r"^\s*([-+0-9.eE]+)(?:\s*±\s*([-+0-9.eE]+))?", cell)
    if not m:
        return None, None
    return m.group(1), m.group(2)


def sig3(x):
    """x with three significant figures, as a string, and its number of decimals."""
    if x == 0:
        return "0", 0
    decimals = max(0, 2 - math.floor(math.log10(abs(x))))
    return f"{x:.{decimals}f}", decimals


def fmt(cell, kind, mj):
    mean, sd = split_cell(cell)
    if mean is None:
        return cell
    if kind == "as-is":
        return cell.split(" (")[0]
    if kind == "mean":
        return mean
    m, s = float(mean), float(sd) if sd is not None else None
    if mj:
        m, s = m / 1000.0, (s / 1000.0 if s is not None else None)
        text, d = sig3(m)
    else:
        d = 0 if kind == "energy0" else 1
        text = f"{m:.{d}f}"
    return text if s is None else f"{text} ± {s:.{d}f}"


def point_value(point, key):
    for part in point.split(", "):
        k, _, v = part.partition("=")
        if k.strip() == key:
            v = v.strip()
            try:
                return f"{float(v):g}"
            except ValueError:
                return v
    return "–"


def sort_key(v):
    try:
        return (0, float(v), "")
    except ValueError:
        return (1, 0.0, v)


def parser():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--key", action="append", default=[], help="HEADER=SCENE.KEY")
    ap.add_argument("--mj", action="store_true", help="W and ΔPE in MJ/m")
    ap.add_argument("--cols", default=",".join(COLUMNS))
    ap.add_argument("--check", metavar="PAGE",
                    help="check that every table of PAGE after a command of this script is its output")
    ap.add_argument("--write", metavar="PAGE",
                    help="replace every table of PAGE after a command of this script by its output")
    ap.add_argument("reports", nargs="*")
    return ap


def made_tables(lines, page):
    """Each table of `lines` that follows a ```sh block calling this script, as
    (first line, end line, command, that command's output); exits when there is none."""
    made = []
    i = 0
    while i < len(lines):
        if lines[i].strip() != "```sh":
            i += 1
            continue
        j = i + 1
        while j < len(lines) and lines[j].strip() != "```":
            j += 1
        if j == len(lines):
            sys.exit(f"validation-tables: {page}, line {i + 1}: a ```sh block is not closed")
        command = " ".join(l.rstrip("\\").strip() for l in lines[i + 1:j])
        i = j + 1
        if not command.startswith("scripts/validation-tables.py"):
            continue
        k = i
        while k < len(lines) and not lines[k].startswith("|"):
            k += 1
        end = k
        while end < len(lines) and lines[end].startswith("|"):
            end += 1
        made.append((k, end, command, table(parser().parse_args(shlex.split(command)[1:]))))
        i = end
    if not made:
        sys.exit(f"validation-tables: {page} has no table made by this script")
    return made


def check(page):
    """Re-runs each ```sh block of `page` that calls this script and compares its output
    with the table that follows the block; exits non-zero naming the first table that differs."""
    lines = open(page, encoding="utf-8").read().split("\n")
    made = made_tables(lines, page)
    for k, end, command, want in made:
        if "\n".join(lines[k:end]) != want:
            sys.exit(f"validation-tables: {page}, line {k + 1}: the table is not the output of\n"
                     f"  {command}\nexpected:\n{want}")
    print(f"validation-tables: {len(made)} tables of {page} are the reports' numbers")


def write(page):
    """Replaces each table of `page` that follows a command of this script by that command's
    output (the text around the tables is the author's to keep true). Every table is made
    before the page is touched, and the page is replaced whole (a temporary file renamed over
    it), so a failed command or a kill leaves it as it was."""
    lines = open(page, encoding="utf-8").read().split("\n")
    made = made_tables(lines, page)
    for k, end, _, want in reversed(made):
        lines[k:end] = want.split("\n")
    tmp = f"{page}.tmp-{os.getpid()}"
    try:
        with open(tmp, "w", encoding="utf-8") as f:
            f.write("\n".join(lines))
        os.replace(tmp, page)
    finally:
        if os.path.exists(tmp):
            os.remove(tmp)
    print(f"validation-tables: {len(made)} tables of {page} written from the reports")


def main():
    a = parser().parse_args()
    if a.check:
        check(a.check)
        return
    if a.write:
        write(a.write)
        return
    if not a.reports:
        sys.exit("validation-tables: no REPORT given")
    print(table(a))


def table(a):
    """The markdown table for the parsed arguments `a`."""
    cols = [c.strip() for c in a.cols.split(",")]
    for c in cols:
        if c not in COLUMNS:
            sys.exit(f"validation-tables: --cols: unknown column '{c}' (known: {', '.join(COLUMNS)})")
    in_mj = {c for c in cols if a.mj and c in ("W", "dPE")}
    keys = [k.partition("=")[::2] for k in a.key]
    labelled = any("#" in r for r in a.reports)
    rows = []
    for spec in a.reports:
        path, _, pick = spec.partition("#")
        t = tables(path)
        points = list(t["energy"])
        label = None
        if pick:
            sub, _, label = pick.partition("#")
            points = [p for p in points if sub in p]
            if len(points) != 1:
                sys.exit(f"validation-tables: '{sub}' matches {len(points)} points of {path}")
        for p in points:
            row = [label or p] if labelled else []
            row += [point_value(p, key) for _, key in keys]
            for c in cols:
                _, sec, col, kind = COLUMNS[c]
                cell = t[sec].get(p, {}).get(col)
                if cell is None:
                    sys.exit(f"validation-tables: {path}: no '{col}' for point '{p}'")
                row.append(fmt(cell, kind, c in in_mj))
            rows.append((tuple(sort_key(point_value(p, key)) for _, key in keys), row))
    rows.sort(key=lambda r: r[0])  # stable: reports' own order where there is no key
    heads = (["set"] if labelled else []) + [h for h, _ in keys]
    heads += [COLUMNS[c][0].replace("kJ", "MJ") if c in in_mj else COLUMNS[c][0] for c in cols]
    out = ["| " + " | ".join(heads) + " |", "|" + "---|" * len(heads)]
    out += ["| " + " | ".join(r) + " |" for _, r in rows]
    return "\n".join(out)


if __name__ == "__main__":
    main()
