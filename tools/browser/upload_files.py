"""What a search by upload sends, checked: one mesh and, for an OBJ, its MTL and texture images (as files or in a zip)."""

from __future__ import annotations

import io
import re
import zipfile
from typing import Any, Dict, List, NamedTuple, Optional, Tuple

MESH_SUFFIXES = (".off", ".obj", ".ply", ".stl", ".glb")
IMAGE_SUFFIXES = (".png", ".jpg", ".jpeg", ".tga", ".bmp")
# Files in one upload, or in one zip (a model with its MTL and a few images needs far fewer).
MAX_FILES = 32
# An MTL is a short text; one larger than this is not one.
MAX_MTL_BYTES = 1024 * 1024
# What each image type starts with (TGA has no magic number: its decoder checks it).
IMAGE_MAGIC = {".png": b"\x89PNG\r\n\x1a\n", ".jpg": b"\xff\xd8\xff", ".jpeg": b"\xff\xd8\xff", ".bmp": b"BM"}
# The options map_Kd may have before its file name, with how many values each takes (at most).
MAP_OPTIONS = {"-blendu": 1, "-blendv": 1, "-bm": 1, "-boost": 1, "-cc": 1, "-clamp": 1, "-imfchan": 1,
               "-mm": 2, "-o": 3, "-s": 3, "-t": 3, "-texres": 1, "-type": 1}
NUMBER = re.compile(r"^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$")


class BadFiles(Exception):
    """Why the files cannot be searched with, in words for the reader, with an HTTP status."""

    def __init__(self, message: str, status_code: int = 400) -> None:
        super().__init__(message)
        self.message = message
        self.status_code = status_code


class Upload(NamedTuple):
    """The mesh to search with, the texture image that colours its 3D view (an OBJ's; None if
    none), what was left out and why, and the image sent for each material the OBJ uses (by
    usemtl name; empty without an MTL): the 3D view maps each face's."""
    name: str
    mesh: bytes
    texture: Optional[bytes]
    texture_name: Optional[str]
    notes: List[str]
    materials: Dict[str, bytes]


def file_name(given: str) -> str:
    """The last part of a name as a client or a zip gives it (never a path: nothing is written
    by it, it only matches an MTL's names); BadFiles when it is empty or has control characters."""
    name = re.split(r"[\\/]", given or "")[-1].strip()
    if not name or name in (".", "..") or len(name) > 255 or any(ord(c) < 32 or ord(c) == 127 for c in name):
        raise BadFiles(f"{given[:80]!r} is not a usable file name")
    return name


def last_part(name: str) -> str:
    """What an OBJ or MTL names a file by, as the uploaded files are named: its last part."""
    return re.split(r"[\\/]", name.strip())[-1].strip()


def suffix(name: str) -> str:
    dot = name.rfind(".")
    return name[dot:].lower() if dot > 0 else ""


def unzip(name: str, data: bytes, max_bytes: int) -> Tuple[List[Tuple[str, bytes]], List[str]]:
    """The files of a zip as (name, bytes), folders flattened, with at most MAX_FILES files and
    max_bytes in all (checked before and while inflating), and notes on what was skipped."""
    try:
        archive = zipfile.ZipFile(io.BytesIO(data))
        members = archive.infolist()
    except (zipfile.BadZipFile, zipfile.LargeZipFile, ValueError, OSError) as error:
        raise BadFiles(f"{name} is not a zip that can be read: {error}") from None
    files: List[Tuple[str, bytes]] = []
    skipped: List[str] = []
    total = 0
    for member in members:
        base = re.split(r"[\\/]", member.filename.rstrip("/\\"))[-1]
        # Folders, and what macOS and editors leave beside the files.
        if member.is_dir() or member.filename.startswith("__MACOSX/") or base.startswith("."):
            continue
        if suffix(base) not in MESH_SUFFIXES + IMAGE_SUFFIXES + (".mtl",):
            skipped.append(base)
            continue
        if len(files) == MAX_FILES:
            raise BadFiles(f"{name} has more than {MAX_FILES} meshes, MTLs and images", 413)
        if member.flag_bits & 0x1:
            raise BadFiles(f"{name}: {base} is encrypted")
        total += member.file_size
        if total > max_bytes:
            raise BadFiles(f"{name} holds more than {max_bytes // (1024 * 1024)} MB", 413)
        try:
            with archive.open(member) as stream:
                content = stream.read(member.file_size + 1)
        except (zipfile.BadZipFile, NotImplementedError, RuntimeError, ValueError, OSError, EOFError) as error:
            raise BadFiles(f"{name}: {base} cannot be read: {error}") from None
        if len(content) != member.file_size:
            raise BadFiles(f"{name}: {base} is not the size the zip says")
        files.append((file_name(base), content))
    notes = [f"{name}: left out {', '.join(sorted(skipped))} (not a mesh, an MTL or an image)"] if skipped else []
    return files, notes


def map_kd(line: str) -> str:
    """The file name of an MTL's map_Kd line (its options skipped), or ""."""
    words = line.split()[1:]
    i = 0
    while i < len(words) - 1 and words[i].lower() in MAP_OPTIONS:
        most = MAP_OPTIONS[words[i].lower()]
        i += 1
        taken = 0
        while taken < most and i < len(words) - 1 and (taken == 0 or NUMBER.match(words[i])):
            i += 1
            taken += 1
    return " ".join(words[i:])


def materials(mtl: bytes) -> Dict[str, str]:
    """Each material of an MTL with the file name of its diffuse texture (map_Kd), if it has one."""
    found: Dict[str, str] = {}
    current = None
    for raw in mtl.decode("utf-8", errors="replace").splitlines():
        line = raw.strip()
        key = line.split(maxsplit=1)[0].lower() if line else ""
        if key == "newmtl":
            current = line.split(maxsplit=1)[1].strip() if len(line.split(maxsplit=1)) > 1 else ""
        elif key == "map_kd" and current is not None and current not in found:
            name = map_kd(line)
            if name:
                found[current] = name
    return found


def obj_material_names(obj: bytes) -> Tuple[List[str], List[str]]:
    """The MTL files an OBJ names (mtllib) and the materials it uses (usemtl), in file order."""
    libraries: List[str] = []
    used: List[str] = []
    for key, value in re.findall(rb"^[ \t]*(mtllib|usemtl)[ \t]+([^\r\n#]*)", obj, re.M):
        text = value.decode("utf-8", errors="replace").strip()
        if key == b"mtllib":
            libraries += text.split()
        elif text and text not in used:
            used.append(text)
    return libraries, used


def material_choice(used: List[str], textured: "Dict[str, Any]") -> Tuple[List[str], List[str]]:
    """Of the materials with a texture (TEXTURED's keys), those in the order their images are
    wanted (the ones the OBJ uses, in use order, else all: the first colours the model), and
    those the 3D view maps (the ones it uses); the same rule for an upload and a catalogue."""
    mapped = [m for m in used if m in textured]
    return mapped or list(textured), mapped


def obj_texture(name: str, obj: bytes, mtls: Dict[str, Tuple[str, bytes]], images: Dict[str, Tuple[str, bytes]],
                notes: List[str]) -> Tuple[Optional[str], Optional[bytes], Dict[str, bytes]]:
    """The texture image that colours an OBJ's view (name, bytes): the map_Kd of the first material
    it uses that names a sent image (through the MTLs it names, or the one sent), or the one image
    sent with no MTL; and each material it uses whose map_Kd was sent, with that image's bytes."""
    if not mtls:
        if len(images) > 1:
            raise BadFiles(f"{name} came with {len(images)} images and no MTL to say which it uses: "
                           "send its MTL too, or the one image")
        image_name, image = next(iter(images.values()), (None, None))
        return image_name, image, {}
    libraries, used = obj_material_names(obj)
    named = [mtls[last_part(n).lower()] for n in libraries if last_part(n).lower() in mtls]
    if not named:
        named = list(mtls.values())
        if libraries:
            notes.append(f"{name} names {', '.join(libraries)}, not sent: read {', '.join(n for n, _ in named)} instead")
    textures: Dict[str, str] = {}
    for _, mtl in named:
        for material, image in materials(mtl).items():
            textures.setdefault(material, image)
    order, _ = material_choice(used, textures)
    wanted = []
    for material in order:
        image = last_part(textures[material])
        if image and image not in wanted:
            wanted.append(image)
    if not wanted:
        notes.append(f"the MTL of {name} gives no texture image (map_Kd): shown in its colours")
        return None, None, {}
    missing = [w for w in wanted if w.lower() not in images]
    present = [w for w in wanted if w.lower() in images]
    if missing:
        notes.append(f"the MTL of {name} names {', '.join(missing)}, not sent"
                     + ("" if present else ": shown without a texture"))
    if not present:
        return None, None, {}
    mapped = {m: images[last_part(textures[m]).lower()][1] for m in used
              if m in textures and last_part(textures[m]).lower() in images}
    if len(present) > 1:
        notes.append(f"the 3D view maps each material's texture ({len(present)} images: "
                     f"{', '.join(present)}); its colours, and faces of a material without one, "
                     f"come from {present[0]}")
    image_name, image = images[present[0].lower()]
    return image_name, image, mapped


def collect(files: List[Tuple[str, bytes]], max_bytes: int) -> Upload:
    """The one mesh among FILES (as (name given, bytes)), with its texture when it is an OBJ that
    came with one; a single zip is unpacked first. BadFiles says what is wrong with the rest."""
    notes: List[str] = []
    files = [(file_name(n), data) for n, data in files]
    if not files:
        raise BadFiles("choose a mesh file (OFF, OBJ, PLY, STL or GLB) to search with")
    if len(files) > MAX_FILES:
        raise BadFiles(f"{len(files)} files: at most {MAX_FILES} (a mesh, its MTL and images)", 413)
    in_zip = False
    zips = [n for n, _ in files if suffix(n) == ".zip"]
    if zips:
        if len(files) > 1:
            raise BadFiles(f"send {zips[0]} alone, or the files it holds without it")
        files, notes = unzip(files[0][0], files[0][1], max_bytes)
        in_zip = True
    seen: Dict[str, str] = {}
    for n, _ in files:
        if n.lower() in seen:
            raise BadFiles(f"two files named {n}: which one is meant?")
        seen[n.lower()] = n
    meshes = [(n, d) for n, d in files if suffix(n) in MESH_SUFFIXES]
    others = [(n, d) for n, d in files if suffix(n) not in MESH_SUFFIXES]
    unknown = [n for n, _ in others if suffix(n) not in IMAGE_SUFFIXES + (".mtl",)]
    if unknown:
        raise BadFiles(f"{', '.join(unknown)}: not a mesh (OFF, OBJ, PLY, STL, GLB), an MTL or a texture "
                       "image (PNG, JPEG, TGA, BMP)")
    if not meshes:
        raise BadFiles("no mesh among the files: send one OFF, OBJ, PLY, STL or GLB file "
                       "(with an OBJ, its MTL and images may come too)")
    if len(meshes) > 1:
        raise BadFiles(f"several meshes ({', '.join(n for n, _ in meshes)}): search with one at a time")
    name, mesh = meshes[0]
    if others and suffix(name) != ".obj":
        what = ", ".join(n for n, _ in others)
        if not in_zip:
            raise BadFiles(f"{what}: an MTL and texture images go with an OBJ; {name} is sent alone")
        notes.append(f"left out {what}: an MTL and texture images go with an OBJ, not {name}")
        others = []
    mtls: Dict[str, Tuple[str, bytes]] = {}
    images: Dict[str, Tuple[str, bytes]] = {}
    for n, data in others:
        kind = suffix(n)
        if kind == ".mtl":
            if len(data) > MAX_MTL_BYTES or b"\0" in data:
                raise BadFiles(f"{n} is not an MTL (a text file of at most {MAX_MTL_BYTES // 1024} KB)")
            mtls[n.lower()] = (n, data)
        else:
            magic = IMAGE_MAGIC.get(kind)
            if not data or (magic is not None and not data.startswith(magic)):
                raise BadFiles(f"{n} is not a {kind[1:].upper()} image")
            images[n.lower()] = (n, data)
    texture_name, texture, mapped = obj_texture(name, mesh, mtls, images, notes) if others else (None, None, {})
    return Upload(name, mesh, texture, texture_name, notes, mapped)
