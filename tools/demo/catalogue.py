#!/usr/bin/env python3
"""The demo's catalogue of a folder of meshes, as CSV on stdout.

    tools/demo/catalogue.py DIR

Every .off .obj .ply .stl .glb file under DIR is a row. When DIR/catalogue.csv exists, its rows
give the files' metadata: a `file` (or `path`) column names each file relative to DIR, and the
columns whose names the demo's table knows fill them (title; class, category or type;
inventory_no or inventory; artist or maker; period or date; material; licence or license;
up or up_axis, the file axis that points up: +x, -x, +y, -y, +z or -z; case ignored). Files
the catalogue does not list are loaded with their name as title; rows whose file is missing,
and up values that are not an axis, are reported on stderr and left out. Output header:
model_id,path,class,inventory_no,title,artist,period,material,licence,up.
"""

import csv
import pathlib
import sys

EXTENSIONS = {".off", ".obj", ".ply", ".stl", ".glb"}
OUT_COLUMNS = ["model_id", "path", "class", "inventory_no", "title", "artist", "period",
               "material", "licence", "up"]
# The demo table's column for each name a catalogue may use.
ALIASES = {
    "title": "title", "name": "title",
    "class": "class", "category": "class", "type": "class",
    "inventory_no": "inventory_no", "inventory": "inventory_no", "accession": "inventory_no",
    "artist": "artist", "maker": "artist",
    "period": "period", "date": "period",
    "material": "material",
    "licence": "licence", "license": "licence",
    "up": "up", "up_axis": "up",
}
# The up values argtool's --up accepts, as this catalogue writes them.
UP_AXES = {f"{sign}{axis}" for sign in "+-" for axis in "xyz"}


def up_axis(value: str) -> "str | None":
    """A catalogue's up value as +x ... -z (case and spaces ignored, no sign meaning +), or None."""
    text = "".join(value.split()).lower()
    text = text if text[:1] in ("+", "-") else "+" + text
    return text if text in UP_AXES else None


def main() -> int:
    if len(sys.argv) != 2:
        print(__doc__.strip().splitlines()[2].strip(), file=sys.stderr)
        return 2
    base = pathlib.Path(sys.argv[1]).resolve()
    files = sorted(p for p in base.rglob("*") if p.is_file() and p.suffix.lower() in EXTENSIONS
                   and "\n" not in str(p))
    known = {}
    listed = base / "catalogue.csv"
    if listed.is_file():
        with listed.open(newline="", encoding="utf-8-sig") as f:
            reader = csv.DictReader(f)
            names = {n.strip().lower(): n for n in (reader.fieldnames or [])}
            file_column = names.get("file") or names.get("path")
            if not file_column:
                print(f"demo: {listed} has no 'file' column: its metadata is not used",
                      file=sys.stderr)
            else:
                for row in reader:
                    rel = (row.get(file_column) or "").strip()
                    path = (base / rel).resolve()
                    if not rel or not path.is_file():
                        print(f"demo: {listed.name} lists {rel!r}, which is not under {base}",
                              file=sys.stderr)
                        continue
                    meta = {}
                    for name, column in names.items():
                        if name in ALIASES and (row.get(column) or "").strip():
                            meta.setdefault(ALIASES[name], row[column].strip())
                    if "up" in meta:
                        axis = up_axis(meta["up"])
                        if axis is None:
                            print(f"demo: {listed.name} gives {rel!r} the up {meta['up']!r}, not one "
                                  f"of +x, -x, +y, -y, +z, -z: it is left out", file=sys.stderr)
                            del meta["up"]
                        else:
                            meta["up"] = axis
                    known[path] = meta
        print(f"demo: {len(known)} files described by {listed.name}", file=sys.stderr)
    out = csv.writer(sys.stdout, lineterminator="\n")
    out.writerow(OUT_COLUMNS)
    for path in files:
        meta = known.get(path, {})
        rel = path.relative_to(base)
        row = {"model_id": str(rel.with_suffix("")), "path": str(path),
               "title": meta.get("title", path.stem)}
        row.update({k: v for k, v in meta.items() if k != "title"})
        out.writerow([row.get(c, "") for c in OUT_COLUMNS])
    return 0 if files else 1


if __name__ == "__main__":
    sys.exit(main())
