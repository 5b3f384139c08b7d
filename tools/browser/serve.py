"""Runs the catalogue browser on 127.0.0.1 (uvicorn), on a port it binds itself and writes to a file."""

from __future__ import annotations

import argparse
import errno
import os
import socket
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
# The pages' modules beside this file, and the project's Python client (pgarg) without installing it.
sys.path[:0] = [str(HERE), str(HERE.parent.parent / "clients" / "python")]

import uvicorn  # noqa: E402  (after the path above)


def bind(port: int) -> socket.socket:
    """A listening socket on 127.0.0.1: the port asked for when it is free, else one the kernel picks.

    Binding here, before uvicorn starts, means the port written to the file is the one served,
    with no window in which another process could take it.
    """
    sock = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    try:
        sock.bind(("127.0.0.1", port))
    except OSError as error:
        if port == 0 or error.errno != errno.EADDRINUSE:
            raise
        sock.bind(("127.0.0.1", 0))
    sock.listen(128)
    return sock


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--port", type=int, default=0, help="port to try first (0: any free one)")
    parser.add_argument("--port-file", type=Path, required=True, help="where to write the port served")
    args = parser.parse_args()
    try:
        os.setsid()  # out of the starting shell's session and its signals (same process id)
    except OSError:
        pass  # already a process group leader: started by hand from an interactive shell
    os.environ.setdefault("PGDATABASE", "museum")
    from app import app  # the pages (PGDATABASE set first)

    sock = bind(args.port)
    port = sock.getsockname()[1]
    # Written whole under another name, then renamed: a reader never sees half a number.
    scratch = args.port_file.with_suffix(".tmp")
    scratch.write_text(f"{port}\n")
    scratch.replace(args.port_file)
    config = uvicorn.Config(app, log_level="info", access_log=True)
    uvicorn.Server(config).run(sockets=[sock])
    return 0


if __name__ == "__main__":
    sys.exit(main())
