"""Arg without a server: the text form, equality and the checks the client makes."""

from __future__ import annotations

import base64
import struct

import pytest

from pgarg import Arg

# A header as the binary form starts: magic, format 2, header size, total size, builder, digest.
HEADER = struct.pack("<4sHHIIQ", b"ARGR", 2, 0, 40, 0, 0x0123456789ABCDEF)
VALUE = HEADER + bytes(range(16))


def test_text_form_is_tag_and_padded_base64() -> None:
    a = Arg(VALUE)
    assert a.to_text() == "arg1:" + base64.b64encode(VALUE).decode()
    assert Arg.from_text(a.to_text()) == a
    assert Arg.from_text(a.to_text().encode()) == a


def test_header_fields_and_bytes() -> None:
    a = Arg(bytearray(VALUE))
    assert a.data == VALUE and bytes(a) == VALUE and len(a) == len(VALUE)
    assert a.format_version == 2
    assert a.digest == 0x0123456789ABCDEF
    assert repr(a) == f"<Arg format 2, {len(VALUE)} bytes, digest 0123456789abcdef>"


def test_equality_and_hash_follow_the_bytes() -> None:
    other = HEADER + bytes(16)
    assert Arg(VALUE) == Arg(VALUE) and hash(Arg(VALUE)) == hash(Arg(VALUE))
    assert Arg(VALUE) != Arg(other)
    assert len({Arg(VALUE), Arg(VALUE), Arg(other)}) == 2
    assert Arg(VALUE) != VALUE


@pytest.mark.parametrize("data", [b"", b"ARGR", b"OFF\n" + bytes(40), b"argr" + bytes(40)])
def test_not_an_arg_is_refused(data: bytes) -> None:
    with pytest.raises(ValueError, match="magic"):
        Arg(data)


@pytest.mark.parametrize("text", ["arg2:" + base64.b64encode(VALUE).decode(),
                                  "arg1:" + base64.b64encode(VALUE).decode()[:-1],
                                  "arg1:" + base64.b64encode(VALUE).decode().replace("A", "*", 1),
                                  base64.b64encode(VALUE).decode()])
def test_bad_text_is_refused(text: str) -> None:
    with pytest.raises(ValueError):
        Arg.from_text(text)
