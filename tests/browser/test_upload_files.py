"""Tests of what a search by upload accepts (tools/browser/upload_files.py): a mesh, an OBJ with its MTL and images, a zip."""

from __future__ import annotations

import io
import sys
import zipfile
from pathlib import Path
from typing import Dict, List

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "tools" / "browser"))
import upload_files  # noqa: E402
from upload_files import BadFiles, collect  # noqa: E402

PNG = b"\x89PNG\r\n\x1a\n" + b"png body"
JPEG = b"\xff\xd8\xff\xe0" + b"jpeg body"
OBJ = b"mtllib model.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl skin\nf 1/1 2/2 3/3\n"
MTL = b"newmtl unused\nmap_Kd other.png\nnewmtl skin\nKd 1 1 1\nmap_Kd -s 1 1 1 -o 0.5 textures\\skin.png\n"
LIMIT = 1 << 20


def zipped(files: Dict[str, bytes]) -> bytes:
    out = io.BytesIO()
    with zipfile.ZipFile(out, "w", zipfile.ZIP_DEFLATED) as z:
        for name, data in files.items():
            z.writestr(name, data)
    return out.getvalue()


def test_a_mesh_alone_has_no_texture() -> None:
    sent = collect([("C:\\models\\cube.off", b"OFF\n")], LIMIT)
    assert (sent.name, sent.mesh, sent.texture, sent.notes) == ("cube.off", b"OFF\n", None, [])


def test_an_obj_takes_the_map_kd_of_the_material_it_uses() -> None:
    sent = collect([("model.obj", OBJ), ("model.mtl", MTL), ("skin.png", PNG), ("other.png", PNG + b"x")],
                   LIMIT)
    assert sent.name == "model.obj" and sent.texture == PNG and sent.texture_name == "skin.png"
    assert sent.notes == [] and sent.materials == {"skin": PNG}


def test_an_obj_keeps_the_image_of_each_material_it_uses() -> None:
    obj = OBJ + b"usemtl two words\nf 1/1 3/3 2/2\nusemtl plain\nf 1 2 3\nusemtl skin\nf 3 2 1\n"
    mtl = MTL + b"newmtl two words\nmap_Kd wood.jpg\nnewmtl plain\nKd 1 0 0\n"
    files = [("model.obj", obj), ("model.mtl", mtl), ("skin.png", PNG), ("wood.jpg", JPEG),
             ("other.png", PNG + b"x")]
    sent = collect(files, LIMIT)
    # The first material's image colours the view; each material's maps its faces.
    assert sent.texture == PNG and sent.texture_name == "skin.png"
    assert sent.materials == {"skin": PNG, "two words": JPEG}
    assert sent.notes == ["the 3D view maps each material's texture (2 images: skin.png, wood.jpg); its "
                          "colours, and faces of a material without one, come from skin.png"]
    notes: List[str] = []
    mtls = {"model.mtl": ("model.mtl", mtl)}
    images = {"skin.png": ("skin.png", PNG)}
    assert upload_files.obj_texture("model.obj", obj, mtls, images, notes) == (
        "skin.png", PNG, {"skin": PNG})
    assert notes == ["the MTL of model.obj names wood.jpg, not sent"]


def test_a_zip_with_folders_and_a_readme_is_unpacked() -> None:
    data = zipped({"model/model.obj": OBJ, "model/model.mtl": MTL, "model/textures/skin.png": PNG,
                   "model/README.txt": b"hello", "__MACOSX/._model.obj": b"junk"})
    sent = collect([("model.zip", data)], LIMIT)
    assert sent.name == "model.obj" and sent.texture == PNG
    assert sent.notes == ["model.zip: left out README.txt (not a mesh, an MTL or an image)"]


def test_an_obj_with_one_image_and_no_mtl_uses_it() -> None:
    sent = collect([("model.obj", OBJ), ("anything.jpg", JPEG)], LIMIT)
    assert sent.texture == JPEG and sent.texture_name == "anything.jpg" and sent.materials == {}


def test_an_image_the_mtl_does_not_name_is_not_guessed() -> None:
    sent = collect([("model.obj", OBJ), ("model.mtl", MTL), ("wrong.png", PNG)], LIMIT)
    assert sent.texture is None and sent.materials == {}
    assert sent.notes == ["the MTL of model.obj names skin.png, not sent: shown without a texture"]


def test_map_kd_options_and_spaces() -> None:
    assert upload_files.map_kd("map_Kd -blendu on -s 2 2 -clamp on my skin.png") == "my skin.png"
    assert upload_files.map_kd("map_Kd -o 0.1 skin.png") == "skin.png"
    assert upload_files.map_kd("map_Kd skin.png") == "skin.png"


def test_a_path_in_the_mtl_reaches_no_file_but_the_sent_ones() -> None:
    mtl = b"newmtl skin\nmap_Kd ../../../../etc/passwd\n"
    sent = collect([("model.obj", OBJ), ("model.mtl", mtl), ("skin.png", PNG)], LIMIT)
    assert sent.texture is None and "names passwd, not sent" in sent.notes[0]


@pytest.mark.parametrize("files, message", [
    ([], "choose a mesh file"),
    ([("a.png", PNG)], "no mesh among the files"),
    ([("a.obj", OBJ), ("b.stl", b"solid")], "several meshes (a.obj, b.stl)"),
    ([("a.obj", OBJ), ("notes.txt", b"x")], "notes.txt: not a mesh"),
    ([("a.glb", b"glTF"), ("a.png", PNG)], "an MTL and texture images go with an OBJ"),
    ([("a.obj", OBJ), ("a.png", b"GIF89a")], "a.png is not a PNG image"),
    ([("a.obj", OBJ), ("a.png", PNG), ("b.png", PNG)], "2 images and no MTL"),
    ([("a.obj", OBJ), ("A.OBJ", OBJ)], "two files named A.OBJ"),
    ([("a.obj", OBJ), ("a.mtl", b"\0" * 10)], "a.mtl is not an MTL"),
    ([("m.zip", b"PK not really")], "m.zip is not a zip that can be read"),
    ([("m.zip", zipped({"a.obj": OBJ})), ("a.png", PNG)], "send m.zip alone"),
    ([("..", OBJ)], "is not a usable file name"),
    ([("a\x01.obj", OBJ)], "is not a usable file name"),
])
def test_bad_files_are_refused_saying_why(files, message) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(BadFiles) as refused:
        collect(files, LIMIT)
    assert message in refused.value.message


def test_a_zip_that_inflates_past_the_limit_is_refused_before_inflating() -> None:
    bomb = zipped({"a.obj": OBJ, "big.png": PNG + b"\0" * (2 * LIMIT)})
    assert len(bomb) < LIMIT // 10
    with pytest.raises(BadFiles) as refused:
        collect([("bomb.zip", bomb)], LIMIT)
    assert refused.value.status_code == 413 and "holds more than 1 MB" in refused.value.message


def test_too_many_files_in_a_zip() -> None:
    many = zipped({f"t{i}.png": PNG for i in range(upload_files.MAX_FILES + 1)})
    with pytest.raises(BadFiles) as refused:
        collect([("many.zip", many)], LIMIT)
    assert refused.value.status_code == 413
