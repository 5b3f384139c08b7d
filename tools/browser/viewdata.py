"""The 3D view's data of a catalogue object or an upload: `argtool view-data` run on its mesh, kept for reuse."""

from __future__ import annotations

import hashlib
import json
import os
import subprocess
import tempfile
import threading
from collections import OrderedDict
from pathlib import Path
from typing import Dict, List, NamedTuple, Optional, Tuple

HERE = Path(__file__).resolve().parent
# server.sh sets it from BUILD_DIR; the default is the repository's build folder.
ARGTOOL = os.environ.get("ARG_ARGTOOL") or str(HERE.parent.parent / "build" / "argtool")
# Above this many triangles the view would be slow to send and to turn: the page says so instead.
# ARG_VIEW_MAX_TRIANGLES lowers it (the browser's tests make their largest sample model too large).
MAX_TRIANGLES = int(os.environ.get("ARG_VIEW_MAX_TRIANGLES") or 500_000)
# Seconds one conversion may take (it reruns the ARG's geometry: mu on the whole surface).
TIMEOUT = 120
# The last few objects' JSON, by (id, sha of the mesh): an object page reloads its view often.
KEEP = 8
# The last few uploads' bytes, for their 3D view: few, as each may be up to the upload's limit.
KEEP_UPLOADS = 4
# The largest texture image the page is sent (argtool view-data writes none above 32 MB).
MAX_TEXTURE_BYTES = 32 * 1024 * 1024
# What a texture the page is sent starts with, by its type: PNG and JPEG only.
TEXTURE_MAGIC = {"image/png": b"\x89PNG\r\n\x1a\n", "image/jpeg": b"\xff\xd8\xff"}


class View(NamedTuple):
    """A mesh's 3D view: the JSON of argtool view-data, and the images its textures map (each
    with its MIME type, in the order of the JSON's "images"; none when it maps no texture)."""
    data: bytes
    images: Tuple[Tuple[bytes, str], ...]


class ViewUnavailable(Exception):
    """Why an object cannot be shown in 3D, in words for the reader, with an HTTP status."""

    def __init__(self, message: str, status_code: int) -> None:
        super().__init__(message)
        self.message = message
        self.status_code = status_code


def run_argtool(args: List[str], slow: str, failed: str) -> None:
    """Runs argtool with ARGS; a run over TIMEOUT raises ViewUnavailable(SLOW, 503), a failure
    ViewUnavailable(FAILED + ": " + argtool's last line), 413 when the model is too large to
    display and 422 otherwise."""
    try:
        done = subprocess.run([ARGTOOL, *args], capture_output=True, text=True, timeout=TIMEOUT)
    except subprocess.TimeoutExpired:
        raise ViewUnavailable(slow, 503) from None
    if done.returncode != 0:
        lines = (done.stderr.strip() or done.stdout.strip() or f"exit status {done.returncode}").splitlines()
        # An option argtool refuses (a stored up that is not an axis) is followed by a hint line.
        why = ([line for line in lines if not line.startswith("Run with --help")] or lines)[-1]
        raise ViewUnavailable(f"{failed}: {why}", 413 if "too large to display" in why else 422)


_cache: "OrderedDict[Tuple[str, str, str, str, str, str], View]" = OrderedDict()
_uploads: "OrderedDict[str, Tuple[str, bytes, Optional[bytes], Dict[str, bytes]]]" = OrderedDict()
_lock = threading.Lock()


def convert(model_id: int, file: str, mesh: Optional[bytes], triangles: Optional[int],
            texture: Optional[bytes] = None, options: str = "", up: str = "",
            materials: Optional[Dict[str, bytes]] = None) -> View:
    """The view of one stored mesh (with the texture stored beside it, and each material's
    texture, for OBJ), its graph built with the stored ARG's build OPTIONS, starting with the
    file axis UP up when the catalogue gives one; raises ViewUnavailable with the reason."""
    if mesh is None:
        raise ViewUnavailable(f"model {model_id} has no mesh stored: there is nothing to show in 3D", 404)
    if triangles is not None and triangles > MAX_TRIANGLES:
        raise ViewUnavailable(f"model {model_id} is too large to display in 3D: {triangles:,} triangles, "
                              f"more than {MAX_TRIANGLES:,}", 413)
    return convert_bytes(f"model {model_id}", file, mesh, texture, options, up, materials)


def materials_digest(materials: Optional[Dict[str, bytes]]) -> str:
    """One hash of an OBJ's material textures (names and bytes, in any order): part of a key."""
    digest = hashlib.sha256()
    for name, image in sorted((materials or {}).items()):
        digest.update(hashlib.sha256(name.encode()).digest() + hashlib.sha256(image).digest())
    return digest.hexdigest()


def keep_upload(file: str, mesh: bytes, texture: Optional[bytes] = None,
                materials: Optional[Dict[str, bytes]] = None) -> str:
    """Keeps an uploaded mesh, with the texture sent for it and each material's (an OBJ's), for its
    3D view (the last KEEP_UPLOADS) and returns its key."""
    digest = hashlib.sha256(mesh)
    digest.update(hashlib.sha256(texture or b"").digest())
    digest.update(materials_digest(materials).encode())
    key = digest.hexdigest()[:32]
    with _lock:
        _uploads[key] = (file, mesh, texture, dict(materials or {}))
        _uploads.move_to_end(key)
        while len(_uploads) > KEEP_UPLOADS:
            _uploads.popitem(last=False)
    return key


def convert_upload(key: str) -> View:
    """The view of an upload kept by keep_upload; ViewUnavailable (404) once it is no longer kept."""
    with _lock:
        kept = _uploads.get(key)
    if kept is None:
        raise ViewUnavailable("this upload is no longer kept for the 3D view: upload it again", 404)
    file, mesh, texture, materials = kept
    return convert_bytes(f"the upload {file}", file, mesh, texture, materials=materials)


def texture_of(view: View, what: str, index: int = 0) -> Tuple[bytes, str]:
    """Image INDEX of a view's textures and its MIME type, checked again before it is sent: a
    PNG or a JPEG by its first bytes, at most MAX_TEXTURE_BYTES; ViewUnavailable (404, 422)
    otherwise."""
    if not view.images:
        raise ViewUnavailable(f"{what} has no texture the 3D view maps", 404)
    if not 0 <= index < len(view.images):
        raise ViewUnavailable(f"{what} has no texture image {index}: its 3D view maps "
                              f"{len(view.images)} (0 to {len(view.images) - 1})", 404)
    image, kind = view.images[index]
    magic = TEXTURE_MAGIC.get(kind)
    if magic is None or not image.startswith(magic) or len(image) > MAX_TEXTURE_BYTES:
        raise ViewUnavailable(f"the texture of {what} is not a PNG or JPEG of at most "
                              f"{MAX_TEXTURE_BYTES // (1024 * 1024)} MB", 422)
    return image, kind


def convert_bytes(what: str, file: str, mesh: bytes, texture: Optional[bytes] = None,
                  options: str = "", up: str = "", materials: Optional[Dict[str, bytes]] = None) -> View:
    """The view of MESH (named WHAT in messages) by `argtool view-data`, its graph built with the
    build OPTIONS (empty: the defaults), kept for reuse by its bytes, texture, material textures
    (an OBJ's, by usemtl name: each face maps its material's), suffix and options text and UP (not
    by WHAT, which only a failure's message, never kept, names). An upload passes no options and a
    catalogue object its value's written out, so the two keep separate views."""
    key = (hashlib.sha256(mesh).hexdigest(), hashlib.sha256(texture or b"").hexdigest(),
           Path(file or "").suffix.lower(), options, up, materials_digest(materials))
    with _lock:
        if key in _cache:
            _cache.move_to_end(key)
            return _cache[key]
    if not os.access(ARGTOOL, os.X_OK):
        raise ViewUnavailable(f"the 3D view needs argtool, not found at {ARGTOOL} (build first)", 503)
    with tempfile.TemporaryDirectory(prefix="arg-view-") as scratch:
        # argtool reads the format from the content; the suffix keeps OBJ's texture lookup right.
        source = Path(scratch) / f"model{Path(file or '').suffix.lower() or '.off'}"
        target = Path(scratch) / "view.json"
        image = Path(scratch) / "texture"
        source.write_bytes(mesh)
        args = ["view-data", str(source), "-o", str(target), "--max-triangles", str(MAX_TRIANGLES),
                "--texture-output", str(image)]
        if options:
            args += ["--build-options", options]
        if up:
            args.append(f"--up={up}")  # one word: a value with a leading - is never an option
        if texture:
            (Path(scratch) / "given-texture").write_bytes(texture)
            args += ["--texture", str(Path(scratch) / "given-texture")]
        for i, (name, image_bytes) in enumerate(sorted((materials or {}).items())):
            given = Path(scratch) / f"material-{i}"
            given.write_bytes(image_bytes)
            # One word: a name with a leading - is never an option; argtool splits at the last =.
            args.append(f"--material={name}={given}")
        run_argtool(args, f"{what} took more than {TIMEOUT} s to prepare for the 3D view",
                    f"{what} cannot be shown in 3D")
        data = target.read_bytes()
        # argtool writes image i at texture-i for each image the JSON lists, of the type it says.
        listed = json.loads(data).get("images") or []
        view = View(data, tuple((Path(f"{image}-{i}").read_bytes(), str(entry["type"]))
                                for i, entry in enumerate(listed)))
    with _lock:
        _cache[key] = view
        while len(_cache) > KEEP:
            _cache.popitem(last=False)
    return view
