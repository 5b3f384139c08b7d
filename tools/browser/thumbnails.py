"""Renders each model of objects without a thumbnail with `argtool render` and stores the PNGs in the table:
the object upright in its own colours (thumbnail), and coloured by mu with its Reeb graph (thumbnail_mu)."""

from __future__ import annotations

import argparse
import concurrent.futures
import os
import subprocess
import sys
import tempfile
from pathlib import Path
from typing import Optional, Tuple

import psycopg

TABLE = "objects"


def has_up(conn: psycopg.Connection) -> bool:
    """Whether the table keeps each file's up axis (the column `up` that tools/demo/load.sql makes
    from a catalogue's `up`); without it, the pictures find up from the shape."""
    return conn.execute("SELECT EXISTS (SELECT FROM information_schema.columns WHERE table_name = %s "
                        "AND column_name = 'up' AND table_schema = ANY (current_schemas(false)))",
                        (TABLE,)).fetchone()[0]


def render_one(argtool: str, size: int, model_id: int, scratch: Path, timeout: float) -> Tuple[int, Optional[str]]:
    """Renders one model from the mesh stored in the table (so from what the server built, not a
    file that may have moved since) and stores both PNGs. Returns (id, None) or (id, why not)."""
    with psycopg.connect(autocommit=True) as conn:
        # The catalogue's up axis of the file, where the table keeps one (tools/demo/load.sql).
        up = "coalesce(up, '')" if has_up(conn) else "''"
        row = conn.execute(f"SELECT file, mesh, texture, {up} FROM {TABLE} WHERE id = %s",
                           (model_id,)).fetchone()
        if row is None:
            return model_id, "gone from the table"
        file, mesh, texture, up = row
        # argtool reads the format from the file name's suffix.
        mesh_path = scratch / f"{model_id}{Path(file).suffix.lower() or '.off'}"
        mesh_path.write_bytes(bytes(mesh))
        # An OBJ's texture, stored beside it: the picture in its own colours samples it, as its ARG does.
        texture_path = scratch / f"{model_id}-texture"
        if texture is not None:
            texture_path.write_bytes(bytes(texture))
        colours_path = scratch / f"{model_id}-colours.png"
        mu_path = scratch / f"{model_id}-mu.png"
        try:
            # Both in the canonical view (the catalogue's up when it gives one, else the side it
            # stands on, seen from its front: argtool upright), from one computation of mu. A
            # blank caption: the page prints
            # the title; the colour legend would be unreadable at this size.
            done = subprocess.run(
                [argtool, "render", str(mesh_path), "-o", str(mu_path), "--colours-output", str(colours_path),
                 "--size", str(size), "--view", "upright", "--no-legend", "--title", " "]
                + ([f"--up={up}"] if up else []) + (["--texture", str(texture_path)] if texture is not None else []),
                capture_output=True, text=True, timeout=timeout)
        except subprocess.TimeoutExpired:
            return model_id, f"argtool render took more than {timeout:.0f} s"
        finally:
            mesh_path.unlink(missing_ok=True)
            texture_path.unlink(missing_ok=True)
        if done.returncode != 0:
            lines = (done.stderr.strip() or done.stdout.strip() or f"exit status {done.returncode}").splitlines()
            # An option argtool refuses (a stored up that is not an axis) is followed by a hint line.
            kept = [line for line in lines if not line.startswith("Run with --help")] or lines
            return model_id, kept[-1]
        pictures = [colours_path.read_bytes(), mu_path.read_bytes()]
        colours_path.unlink()
        mu_path.unlink()
        conn.execute(f"UPDATE {TABLE} SET thumbnail = %b, thumbnail_mu = %b WHERE id = %s",
                     (pictures[0], pictures[1], model_id))
        return model_id, None


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--argtool", default="build/argtool", help="the argtool binary")
    parser.add_argument("--size", type=int, default=256, help="width and height in pixels")
    parser.add_argument("--jobs", type=int, default=2, help="renders at once")
    parser.add_argument("--timeout", type=float, default=300, help="seconds one render may take")
    parser.add_argument("--keep-going", action="store_true",
                        help="a model that does not render keeps no thumbnail (exit 0) instead of failing")
    args = parser.parse_args()
    if not os.access(args.argtool, os.X_OK):
        print(f"thumbnails: no argtool at {args.argtool} (build first)", file=sys.stderr)
        return 1
    with psycopg.connect(autocommit=True) as conn:
        ids = [r[0] for r in conn.execute(f"SELECT id FROM {TABLE} WHERE thumbnail IS NULL ORDER BY id")]
    failed = 0
    with tempfile.TemporaryDirectory(prefix="arg-thumbnails-") as scratch, \
            concurrent.futures.ThreadPoolExecutor(max(1, args.jobs)) as pool:
        jobs = [pool.submit(render_one, args.argtool, args.size, i, Path(scratch), args.timeout) for i in ids]
        for done, job in enumerate(concurrent.futures.as_completed(jobs), 1):
            model_id, why = job.result()
            if why is not None:
                failed += 1
                print(f"thumbnails: model {model_id} has no thumbnail: {why}", file=sys.stderr)
            if done % 10 == 0 or done == len(jobs):
                print(f"  {done}/{len(jobs)} thumbnails rendered", flush=True)
    if failed and not args.keep_going:
        print(f"thumbnails: {failed} of {len(ids)} models could not be rendered", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
