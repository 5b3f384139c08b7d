#!/usr/bin/env python3
"""The demo's catalogue of a folder of meshes, as CSV on stdout.

    tools/demo/catalogue.py DIR [--textures FILE]

Every .off .obj .ply .stl .glb file under DIR is a row. When DIR/catalogue.csv exists, its rows
give the files' metadata: a `file` (or `path`) column names each file relative to DIR, and the
columns whose names the demo's table knows fill them (title; class, category or type;
inventory_no or inventory; artist or maker; period or date; material; licence or license;
up or up_axis, the file axis that points up: +x, -x, +y, -y, +z or -z; case ignored). Files
the catalogue does not list are loaded with their name as title; rows whose file is missing,
and up values that are not an axis, are reported on stderr and left out. Output header:
model_id,path,class,inventory_no,title,artist,period,material,licence,up.

With --textures FILE, the texture images of the OBJ files are written to FILE as CSV with header
model_id,material,path: a row with an empty material for the image that colours the model (its
ARG's colours and its pictures), and a row per material it uses (usemtl) whose diffuse texture
(map_Kd of an MTL it names, mtllib) is there, for the 3D view. An OBJ without an MTL takes the
one image beside it when its folder holds no other mesh and no other image. Images are looked
for where the MTL names them, then by file name beside the MTL and beside the OBJ; only files
under DIR are used.
"""

import argparse
import csv
import pathlib
import sys
from typing import Dict, List, Optional, Tuple

# The MTL parsing a search by upload uses (standard library only).
sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "browser"))
import upload_files  # noqa: E402

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


def under(base: pathlib.Path, path: pathlib.Path) -> bool:
    return path == base or base in path.parents


def usable(path: pathlib.Path) -> bool:
    """Whether a file's name can go into the CSV and a psql script: UTF-8, one line."""
    text = str(path)
    try:
        text.encode("utf-8")
    except UnicodeEncodeError:
        return False
    return "\n" not in text and "\r" not in text


def found_under(base: pathlib.Path, path: pathlib.Path) -> Optional[pathlib.Path]:
    """PATH resolved (links followed) if it is a usable file under BASE, else None."""
    try:
        real = path.resolve()
        return real if real.is_file() and under(base, real) and usable(real) else None
    except (OSError, ValueError):  # a name with a NUL, a loop of links
        return None


def named_file(base: pathlib.Path, folders: List[pathlib.Path], name: str) -> Optional[pathlib.Path]:
    """The file an OBJ or MTL names: as given, relative to the first folder (its backslashes as
    they are, then as folder separators), else the file of that last part (case ignored) in any
    of the folders; None when there is none under BASE. An MTL written elsewhere often names its
    images by an absolute path of the machine it came from."""
    given = name.strip()
    candidates = [folders[0] / g for g in dict.fromkeys([given, given.replace("\\", "/")])
                  if g and not g.startswith("/")]
    wanted = upload_files.last_part(name).lower()
    for folder in folders:
        if folder.is_dir():
            candidates += sorted(p for p in folder.iterdir() if p.name.lower() == wanted)
    for path in candidates:
        real = found_under(base, path)
        if real is not None:
            return real
    return None


def obj_textures(base: pathlib.Path, obj: pathlib.Path, meshes_here: int,
                 images_here: List[pathlib.Path]) -> Tuple[Optional[pathlib.Path], Dict[str, pathlib.Path]]:
    """The image that colours OBJ (the first material it uses with a texture found, else any
    material's) and each material it uses with its image, as a search by upload chooses them:
    without an MTL found, the one image beside it when no other mesh shares its folder."""
    libraries, used = upload_files.obj_material_names(obj.read_bytes())
    mtls = []
    for library in libraries:
        mtl = named_file(base, [obj.parent], library)
        if mtl is None:
            print(f"demo: {obj.relative_to(base)} names the MTL {library!r}, which is not there",
                  file=sys.stderr)
        else:
            mtls.append(mtl)
    if not mtls:
        lone = found_under(base, images_here[0]) if meshes_here == 1 and len(images_here) == 1 else None
        return lone, {}
    found: Dict[str, pathlib.Path] = {}
    for mtl in mtls:
        for material, image_name in upload_files.materials(mtl.read_bytes()).items():
            image = named_file(base, [mtl.parent, obj.parent], image_name)
            if image is None:
                print(f"demo: {mtl.relative_to(base)} gives material {material!r} the texture "
                      f"{image_name!r}, which is not there", file=sys.stderr)
            elif material not in found:
                found[material] = image
    order, mapped = upload_files.material_choice(used, found)
    return (found[order[0]] if order else None), {m: found[m] for m in mapped}


def write_textures(base: pathlib.Path, files: List[pathlib.Path], model_ids: Dict[pathlib.Path, str],
                   out_path: str) -> None:
    meshes: Dict[pathlib.Path, int] = {}
    images: Dict[pathlib.Path, List[pathlib.Path]] = {}
    for path in files:
        meshes[path.parent] = meshes.get(path.parent, 0) + 1
    for path in sorted(base.rglob("*")):
        if path.is_file() and upload_files.suffix(path.name) in upload_files.IMAGE_SUFFIXES:
            images.setdefault(path.parent, []).append(path)
    textured = 0
    with open(out_path, "w", newline="", encoding="utf-8") as f:
        out = csv.writer(f, lineterminator="\n")
        out.writerow(["model_id", "material", "path"])
        for path in files:
            if path.suffix.lower() != ".obj":
                continue
            texture, mapped = obj_textures(base, path, meshes[path.parent], images.get(path.parent, []))
            if texture is None:
                continue
            textured += 1
            out.writerow([model_ids[path], "", str(texture)])
            for material, image in mapped.items():
                out.writerow([model_ids[path], material, str(image)])
    print(f"demo: {textured} OBJ files with a texture", file=sys.stderr)


def main() -> int:
    parser = argparse.ArgumentParser(description="The demo's catalogue of a folder of meshes, as CSV on stdout.")
    parser.add_argument("dir", help="the folder of meshes")
    parser.add_argument("--textures", help="where to write the OBJ files' texture images, as CSV")
    args = parser.parse_args()
    base = pathlib.Path(args.dir).resolve()
    files = sorted(p for p in base.rglob("*") if p.is_file() and p.suffix.lower() in EXTENSIONS)
    for path in files:
        if not usable(path):
            print(f"demo: {ascii(str(path))}: a file name that is not one line of UTF-8 is left out",
                  file=sys.stderr)
    files = [p for p in files if usable(p)]
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
    model_ids = {}
    for path in files:
        meta = known.get(path, {})
        rel = path.relative_to(base)
        model_ids[path] = str(rel.with_suffix(""))
        row = {"model_id": model_ids[path], "path": str(path),
               "title": meta.get("title", path.stem)}
        row.update({k: v for k, v in meta.items() if k != "title"})
        out.writerow([row.get(c, "") for c in OUT_COLUMNS])
    if args.textures:
        write_textures(base, files, model_ids, args.textures)
    return 0 if files else 1


if __name__ == "__main__":
    sys.exit(main())
