"""psycopg 3 adapters of `arg` and `arg_weights`, text and binary, registered per connection."""

from __future__ import annotations

from typing import Any, Optional, Type

import psycopg
from psycopg import sql
from psycopg.adapt import Buffer, Dumper, Loader
from psycopg.pq import Format
from psycopg.types import TypeInfo

from .value import Arg
from .weights import ArgWeights
from .weights_binary import pack_weights, unpack_weights


class _ArgTextDumper(Dumper):
    format = Format.TEXT

    def dump(self, obj: Arg) -> bytes:
        return obj.to_text().encode("ascii")


class _ArgBinaryDumper(Dumper):
    format = Format.BINARY

    def dump(self, obj: Arg) -> bytes:
        return obj.data


class _ArgTextLoader(Loader):
    format = Format.TEXT

    def load(self, data: Buffer) -> Arg:
        return Arg.from_text(bytes(data))


class _ArgBinaryLoader(Loader):
    format = Format.BINARY

    def load(self, data: Buffer) -> Arg:
        return Arg(data)


class _WeightsTextDumper(Dumper):
    format = Format.TEXT

    def dump(self, obj: ArgWeights) -> bytes:
        return str(obj).encode("ascii")


class _WeightsBinaryDumper(Dumper):
    format = Format.BINARY

    def dump(self, obj: ArgWeights) -> bytes:
        return pack_weights(obj)


class _WeightsTextLoader(Loader):
    format = Format.TEXT

    def load(self, data: Buffer) -> ArgWeights:
        return ArgWeights.parse(bytes(data).decode("ascii"))


class _WeightsBinaryLoader(Loader):
    format = Format.BINARY

    def load(self, data: Buffer) -> ArgWeights:
        return unpack_weights(bytes(data))


def _register_type(conn: psycopg.Connection[Any], name: str, schema: Optional[str],
                   python_type: type, dumpers: "tuple[Type[Dumper], Type[Dumper]]",
                   loaders: "tuple[Type[Loader], Type[Loader]]") -> TypeInfo:
    info = TypeInfo.fetch(conn, sql.Identifier(schema, name) if schema else name)
    if info is None:
        raise psycopg.ProgrammingError(
            f"type {name} not found: run CREATE EXTENSION arg CASCADE in this database "
            "(or pass the schema it was created in)")
    # Registering the type info also teaches psycopg its array type (arg[], arg_weights[]).
    info.register(conn)
    adapters = conn.adapters
    # The dumpers need this database's OID, so each registration gets subclasses of its own.
    # The binary dumper goes last: psycopg uses the last one for %s placeholders, and binary
    # input costs the server less (no base64, no text parsing).
    for dumper in dumpers:
        adapters.register_dumper(python_type, type(dumper.__name__, (dumper,), {"oid": info.oid}))
    for loader in loaders:
        adapters.register_loader(info.oid, loader)
    return info


def register_arg(conn: psycopg.Connection[Any], schema: Optional[str] = None) -> None:
    """Teaches one connection the types `arg` and `arg_weights`.

    After it, query results of type ``arg`` load as :class:`Arg` and ``arg_weights`` as
    :class:`ArgWeights`, in text and binary results alike, and both classes can be passed as
    query parameters (sent in binary for ``%s`` and ``%b``, in text for ``%t``). The types'
    OIDs are looked up in the database, through the search path or in `schema`; raises
    psycopg.ProgrammingError when the extension is not there.
    """
    _register_type(conn, "arg", schema, Arg, (_ArgTextDumper, _ArgBinaryDumper),
                   (_ArgTextLoader, _ArgBinaryLoader))
    _register_type(conn, "arg_weights", schema, ArgWeights,
                   (_WeightsTextDumper, _WeightsBinaryDumper),
                   (_WeightsTextLoader, _WeightsBinaryLoader))
