"""Tests of the demo's catalogue of a folder (tools/demo/catalogue.py): the OBJ files' textures it lists."""

from __future__ import annotations

import csv
import subprocess
import sys
from pathlib import Path
from typing import List, Tuple

SCRIPT = Path(__file__).resolve().parents[2] / "tools" / "demo" / "catalogue.py"
PNG = b"\x89PNG\r\n\x1a\n" + b"png body"
TRIANGLE = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"


def catalogue(folder: Path, tmp_path: Path) -> Tuple[List[List[str]], List[Tuple[str, str, str]], str]:
    """catalogue.py's rows, its texture rows (paths relative to FOLDER) and what it said on stderr."""
    textures = tmp_path / "textures.csv"
    done = subprocess.run([sys.executable, str(SCRIPT), str(folder), "--textures", str(textures)],
                          capture_output=True, text=True, check=True)
    rows = list(csv.reader(done.stdout.splitlines()))
    with textures.open(newline="") as f:
        listed = list(csv.reader(f))
    assert listed[0] == ["model_id", "material", "path"]
    relative = [(m, mat, str(Path(p).relative_to(folder.resolve()))) for m, mat, p in listed[1:]]
    return rows, relative, done.stderr


def write(path: Path, data: "str | bytes") -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(data.encode() if isinstance(data, str) else data)


def test_each_material_an_obj_uses_and_the_first_one_for_its_colours(tmp_path: Path) -> None:
    models = tmp_path / "models"
    write(models / "jug" / "jug.obj",
          "mtllib jug.mtl\n" + TRIANGLE + "usemtl glaze\nf 1/1 2/2 3/3\nusemtl rim\nf 1/1 3/3 2/2\n")
    # An unused material first, an option before a file name, a Windows path from elsewhere.
    write(models / "jug" / "jug.mtl", "newmtl unused\nmap_Kd other.png\nnewmtl rim\nmap_Kd -s 2 2 1 maps/rim.png\n"
          "newmtl glaze\nmap_Kd C:\\Users\\someone\\glaze.png\n")
    write(models / "jug" / "maps" / "rim.png", PNG)
    write(models / "jug" / "glaze.png", PNG)
    write(models / "jug" / "other.png", PNG)
    rows, textures, _ = catalogue(models, tmp_path)
    assert [r[0] for r in rows[1:]] == ["jug/jug"]
    assert textures == [("jug/jug", "", "jug/glaze.png"), ("jug/jug", "glaze", "jug/glaze.png"),
                        ("jug/jug", "rim", "jug/maps/rim.png")]


def test_an_obj_without_an_mtl_takes_the_one_image_beside_it(tmp_path: Path) -> None:
    models = tmp_path / "models"
    write(models / "head" / "head.obj", TRIANGLE + "f 1/1 2/2 3/3\n")
    write(models / "head" / "head_diffuse.tga", b"tga")
    # Two meshes beside two images: which image is whose is not guessed.
    write(models / "pair" / "a.obj", TRIANGLE + "f 1 2 3\n")
    write(models / "pair" / "b.obj", TRIANGLE + "f 1 2 3\n")
    write(models / "pair" / "a.png", PNG)
    write(models / "pair" / "b.png", PNG)
    write(models / "cube.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
    rows, textures, _ = catalogue(models, tmp_path)
    assert sorted(r[0] for r in rows[1:]) == ["cube", "head/head", "pair/a", "pair/b"]
    assert textures == [("head/head", "", "head/head_diffuse.tga")]


def test_what_is_missing_or_outside_the_folder_is_reported_not_used(tmp_path: Path) -> None:
    models = tmp_path / "models"
    write(models / "vase.obj", "mtllib vase.mtl gone.mtl\n" + TRIANGLE + "usemtl a\nf 1 2 3\nusemtl b\nf 1 3 2\n")
    write(models / "vase.mtl", "newmtl a\nmap_Kd ../secret.png\nnewmtl b\nmap_Kd missing.png\n")
    write(tmp_path / "secret.png", PNG)
    rows, textures, said = catalogue(models, tmp_path)
    assert [r[0] for r in rows[1:]] == ["vase"] and textures == []
    assert "names the MTL 'gone.mtl', which is not there" in said
    assert "material 'a' the texture '../secret.png', which is not there" in said
    assert "material 'b' the texture 'missing.png', which is not there" in said


def test_a_link_out_of_the_folder_and_a_name_of_two_lines_are_not_used(tmp_path: Path) -> None:
    models = tmp_path / "models"
    write(tmp_path / "outside" / "secret.png", PNG)
    write(models / "lone" / "a.obj", TRIANGLE + "f 1/1 2/2 3/3\n")
    (models / "lone" / "a.png").symlink_to(tmp_path / "outside" / "secret.png")
    write(models / "two" / "b.obj", TRIANGLE + "f 1/1 2/2 3/3\n")
    write(models / "two" / "b\nc.png", PNG)
    write(models / "two\nlines.obj", TRIANGLE + "f 1 2 3\n")
    rows, textures, said = catalogue(models, tmp_path)
    assert sorted(r[0] for r in rows[1:]) == ["lone/a", "two/b"] and textures == []
    assert "'" + str(models / "two\nlines.obj").replace("\n", "\\n") + "'" in said


def test_an_mtl_that_is_not_there_leaves_the_one_image_beside_the_obj(tmp_path: Path) -> None:
    models = tmp_path / "models"
    write(models / "bowl.obj", "mtllib bowl.mtl\n" + TRIANGLE + "usemtl glaze\nf 1/1 2/2 3/3\n")
    write(models / "bowl texture.png", PNG)
    # A name with a backslash, as Linux allows, is found as it is written.
    write(models / "cup" / "cup.obj", "mtllib cup.mtl\n" + TRIANGLE + "usemtl a\nf 1/1 2/2 3/3\n")
    write(models / "cup" / "cup.mtl", "newmtl a\nmap_Kd odd\\name.png\n")
    write(models / "cup" / "odd\\name.png", PNG)
    _, textures, said = catalogue(models, tmp_path)
    assert textures == [("bowl", "", "bowl texture.png"), ("cup/cup", "", "cup/odd\\name.png"),
                        ("cup/cup", "a", "cup/odd\\name.png")]
    assert "names the MTL 'bowl.mtl', which is not there" in said
