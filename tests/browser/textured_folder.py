"""A folder holding an OBJ of two materials, its MTL and their images, loaded as `make demo MODELS=DIR`
loads a folder: the texture colours the ARG and the thumbnail, and the 3D view maps both images.

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
    # A search by upload with an image the server cannot read searches by the mesh alone, saying so.
    import app

    notes: list = []
    _, rows = app.rank_upload(bytes(row["mesh"]), b"not an image", {}, notes)
    found["upload without its texture"] = (len(rows) == 1 and len(notes) == 1
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
