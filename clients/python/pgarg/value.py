"""The Python side of the `arg` type: an ARG value as the bytes of its binary form."""

from __future__ import annotations

import base64
import binascii
import struct
from typing import Union

TEXT_TAG = "arg1:"
_MAGIC = b"ARGR"
# Magic, format version, header size, total size, builder version, digest: the first 24 bytes
# of every format (docs/DESIGN.md, "The binary format").
_HEADER = struct.Struct("<4sHHIIQ")


class Arg:
    """An Augmented Reeb Graph as the server stores it: the bytes of its binary form.

    The client neither builds nor compares ARGs; the server does (``arg_build``, ``<~>``).
    Only the magic is checked here: the server checks every byte when a value is sent to it.
    Two values are equal when their bytes are, as ``=`` in SQL.
    """

    __slots__ = ("_data",)

    def __init__(self, data: Union[bytes, bytearray, memoryview]) -> None:
        data = bytes(data)
        if len(data) < _HEADER.size or not data.startswith(_MAGIC):
            raise ValueError("not the binary form of an ARG (it starts with the magic ARGR)")
        self._data = data

    @classmethod
    def from_text(cls, text: Union[str, bytes]) -> "Arg":
        """Reads the text form, ``arg1:`` followed by standard padded base64."""
        if isinstance(text, str):
            text = text.encode("ascii")
        if not text.startswith(TEXT_TAG.encode()):
            raise ValueError(f"the text form of an ARG starts with {TEXT_TAG!r}")
        try:
            return cls(base64.b64decode(text[len(TEXT_TAG):], validate=True))
        except binascii.Error as error:
            raise ValueError(f"bad base64 in the text form of an ARG: {error}") from None

    def to_text(self) -> str:
        """The text form, byte for byte what the server's ``arg_out`` prints."""
        return TEXT_TAG + base64.b64encode(self._data).decode("ascii")

    @property
    def data(self) -> bytes:
        """The binary form (what ``arg_send`` sends and ``arg_recv`` reads)."""
        return self._data

    @property
    def format_version(self) -> int:
        """1 for values built by arg 0.1.0, 2 for values with the whole-shape terms."""
        return _HEADER.unpack_from(self._data)[1]

    @property
    def digest(self) -> int:
        """The FNV-1a digest the header stores (what the server's hash operator class uses)."""
        return _HEADER.unpack_from(self._data)[5]

    def __bytes__(self) -> bytes:
        return self._data

    def __len__(self) -> int:
        return len(self._data)

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Arg):
            return NotImplemented
        return self._data == other._data

    def __hash__(self) -> int:
        return hash(self._data)

    def __repr__(self) -> str:
        return f"<Arg format {self.format_version}, {len(self._data)} bytes, digest {self.digest:016x}>"
