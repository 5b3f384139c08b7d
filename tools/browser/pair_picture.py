"""The pair page's picture: `argtool render-match` of two stored meshes (matched nodes linked), kept for reuse."""

from __future__ import annotations

import tempfile
import threading
from collections import OrderedDict
from pathlib import Path
from typing import Tuple

from viewdata import TIMEOUT, run_argtool

KEEP = 8
_cache: "OrderedDict[Tuple[int, int, str, int, str], bytes]" = OrderedDict()
_lock = threading.Lock()


def render(a: Tuple[int, str, bytes], b: Tuple[int, str, bytes], weights: str, level: int,
           options: str = "", size: int = 320) -> bytes:
    """PNG of models a and b, each (id, file name, mesh bytes), side by side with the groups
    matched at `level` under the preset `weights` linked, as `argtool render-match` draws them
    from graphs built with the build `options` their stored values were built with."""
    key = (a[0], b[0], weights, level, options)
    with _lock:
        if key in _cache:
            _cache.move_to_end(key)
            return _cache[key]
    with tempfile.TemporaryDirectory(prefix="arg-pair-") as scratch:
        paths = []
        for tag, (model_id, file, mesh) in (("a", a), ("b", b)):
            # The file's own name: render-match captions each panel with it.
            path = Path(scratch) / tag / (Path(file or "").name or f"{model_id}.off")
            path.parent.mkdir()
            path.write_bytes(mesh)
            paths.append(str(path))
        png = Path(scratch) / "pair.png"
        extra = ["--build-options", options] if options else []
        run_argtool(["render-match", *paths, "-o", str(png), "--weights", weights, "--level", str(level),
                     "--size", str(size), *extra],
                    f"the picture of models {a[0]} and {b[0]} took more than {TIMEOUT} s",
                    f"models {a[0]} and {b[0]} cannot be drawn")
        data = png.read_bytes()
    with _lock:
        _cache[key] = data
        while len(_cache) > KEEP:
            _cache.popitem(last=False)
    return data
