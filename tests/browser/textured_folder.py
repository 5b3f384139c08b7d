"""A folder holding an OBJ of two materials, its MTL and their images, and a soup of two boxes, loaded as
`make demo MODELS=DIR` loads a folder: the texture colours the ARG and the thumbnail, the 3D view maps
both images, and the soup (built on its proxy) is shown as its own triangles.

    textured_folder.py write DIR     the folder (the globe of textured_glb, its halves two materials)
    textured_folder.py check ARGTOOL the database in PGDATABASE, loaded from DIR by tools/demo/load.sql

check prints what it found and exits 1 on the first thing that is not as it should be.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
sys.path.insert(0, str(HERE.parents[1] / "tools" / "browser"))
sys.path.insert(0, str(HERE.parents[1] / "clients" / "python"))
import textured_glb  # noqa: E402


def write(folder: Path) -> None:
    obj, _ = textured_glb.globe_obj()
    lines = obj.splitlines()
    faces = [i for i, line in enumerate(lines) if line.startswith("f ")]
    # The southern half of the faces takes a second material and its own image.
    lines.insert(faces[len(faces) // 2], "usemtl south")
    (folder / "textures").mkdir(parents=True, exist_ok=True)
    (folder / "globe.obj").write_text("\n".join(lines) + "\n")
    (folder / "model.mtl").write_text("newmtl globe\nKd 1 1 1\nmap_Kd textures/checker.png\n"
                                      "newmtl south\nKd 1 1 1\nmap_Kd C:\\exports\\south.png\n")
    (folder / "textures" / "checker.png").write_bytes(textured_glb.checker_png())
    (folder / "south.png").write_bytes(textured_glb.south_png())
    # A soup of two crossing boxes, built on its proxy: its view shows its own 24 triangles.
    (folder / "soup").mkdir(exist_ok=True)
    (folder / "soup" / "boxes.obj").write_text(two_boxes())


def two_boxes() -> str:
    lines = []
    for k, (a, b) in enumerate((((0, 0, 0), (4, 1, 1)), ((1.5, -1, -1), (2.5, 2, 2)))):
        (x0, y0, z0), (x1, y1, z1) = a, b
        lines += [f"v {x} {y} {z}" for z in (z0, z1) for x, y in ((x0, y0), (x1, y0), (x1, y1), (x0, y1))]
        o = 8 * k
        for f in ("1 3 2", "1 4 3", "5 6 7", "5 7 8", "1 2 6", "1 6 5", "2 3 7", "2 7 6", "3 4 8", "3 8 7",
                  "4 1 5", "4 5 8"):
            lines.append("f " + " ".join(str(int(i) + o) for i in f.split()))
    return "\n".join(lines) + "\n"


def check(argtool: str) -> int:
    import catalogue  # the browser's modules, as its pages use them
    import viewdata

    viewdata.ARGTOOL = argtool
    with catalogue.connect() as conn:
        (model_id,) = conn.execute("SELECT id FROM objects WHERE model_id = 'globe'").fetchone()
        texture, colour, thumbnail = conn.execute(
            "SELECT texture, (arg_info(descr)->>'has_colour')::boolean, thumbnail FROM objects WHERE id = %s",
            (model_id,)).fetchone()
        row = catalogue.stored_mesh(conn, model_id)
    found = {"texture": texture is not None and bytes(texture) == textured_glb.checker_png(),
             "colour": bool(colour), "thumbnail": thumbnail is not None,
             "materials": sorted(row["materials"]) == ["globe", "south"]}
    view = json.loads(viewdata.convert(model_id, row["file"], row["mesh"], row["triangles"], row["texture"],
                                       row["options"], row["up"], row["materials"]).data)
    found["view's images"] = len(view.get("images") or []) == 2
    # The soup, built on its proxy, is shown as its own triangles, each with a node.
    with catalogue.connect() as conn:
        (soup_id,) = conn.execute("SELECT id FROM objects WHERE model_id = 'soup/boxes'").fetchone()
        proxy = conn.execute("SELECT (arg_info(descr)->>'proxy')::boolean FROM objects WHERE id = %s",
                             (soup_id,)).fetchone()[0]
        soup = catalogue.stored_mesh(conn, soup_id)
    soup_view = json.loads(viewdata.convert(soup_id, soup["file"], soup["mesh"], soup["triangles"], soup["texture"],
                                            soup["options"], soup["up"], soup["materials"]).data)
    found["soup as itself"] = (bool(proxy) and len(soup_view["faces"]) == 3 * 24
                               and all(min(level["face_nodes"]) >= 0 for level in soup_view["levels"]))
    # A search by upload with an image the server cannot read searches by the mesh alone, saying so.
    import app

    notes: list = []
    _, rows = app.rank_upload(bytes(row["mesh"]), b"not an image", {}, notes)
    found["upload without its texture"] = (len(rows) == 2 and len(notes) == 1
                                           and "cannot build ARG: image: not a PNG" in notes[0])
    print(found)
    return 0 if all(found.values()) else 1


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "write":
        write(Path(sys.argv[2]))
        sys.exit(0)
    if len(sys.argv) == 3 and sys.argv[1] == "check":
        sys.exit(check(sys.argv[2]))
    print(__doc__.strip().splitlines()[2].strip(), file=sys.stderr)
    sys.exit(2)
