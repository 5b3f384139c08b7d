"""The Python side of the `arg_weights` type: the weights of matching and SIM, and their canonical text."""

from __future__ import annotations

import dataclasses
import math
import struct
from typing import Dict, Tuple

# The eleven weights of the graph's matching and sim, in the order of the canonical text and of
# the binary form.
MATCH_FIELDS: Tuple[str, ...] = (
    "alpha_l", "beta_l", "gamma_l", "delta_l", "eps_l",
    "alpha_s", "beta_s", "lambda_1", "lambda_2", "lambda_3", "lambda_4",
)
# The weights of the three terms of SIM, the graph's share on proxies and the ratio of a level's
# share of the graph's SIM to the level above's: multiples of MIXING_STEP, because the server
# keeps each in (part of) a byte.
MIXING_FIELDS: Tuple[str, ...] = ("graph", "panorama", "spectrum", "graph_on_proxy", "level_ratio")
MIXING_STEP = 0.05
MAX_MIXING_STEPS = 255
MAX_GRAPH_ON_PROXY_STEPS = 20
MAX_LEVEL_RATIO_STEPS = 20
# Keys a server before 0.3.0 does not print, with the value its SIM had.
_OPTIONAL_KEYS: Dict[str, str] = {"level_ratio": "1"}


def float32(x: float) -> float:
    """x rounded to the nearest float4, which is what the server keeps."""
    return struct.unpack("<f", struct.pack("<f", x))[0]


def mixing_weight(steps: int) -> float:
    """The float4 the server keeps for `steps` steps of MIXING_STEP."""
    return float32(steps * MIXING_STEP)


def mixing_steps(name: str, value: float) -> int:
    """The number of MIXING_STEP steps of a mixing weight; ValueError when it has none."""
    steps = round(value / MIXING_STEP)
    limit = {"graph_on_proxy": MAX_GRAPH_ON_PROXY_STEPS,
             "level_ratio": MAX_LEVEL_RATIO_STEPS}.get(name, MAX_MIXING_STEPS)
    if not (0 <= steps <= limit) or abs(value / MIXING_STEP - steps) > 1e-6:
        raise ValueError(f"{name}={value!r} must be a multiple of {MIXING_STEP} in "
                         f"[0, {limit * MIXING_STEP:g}]")
    return steps


def _format_number(x: float) -> str:
    # The server's rule: the shortest of 6 to 9 significant digits that reads back as the same
    # float4 ("0.3", not "0.300000012").
    for digits in range(6, 10):
        text = "%.*g" % (digits, x)
        if float32(float(text)) == x:
            return text
    return text


@dataclasses.dataclass(frozen=True, repr=False)
class ArgWeights:
    """Weights of matching and SIM, as the server's ``arg_weights`` holds them.

    The defaults are the server's ``arg`` preset. Every weight is kept rounded to a float4, as the
    server keeps it, so that values equal here are equal there. Other presets are the server's to
    expand: ``SELECT 'mrg'::arg_weights`` returns one as an ArgWeights. The server checks the rest
    (at least one sim and one mixing weight positive, ranges) when a value is sent to it.
    """

    alpha_l: float = 0.3
    beta_l: float = 0.15
    gamma_l: float = 0.15
    delta_l: float = 0.2
    eps_l: float = 0.2
    alpha_s: float = 0.65
    beta_s: float = 0.35
    lambda_1: float = 0.3
    lambda_2: float = 0.5
    lambda_3: float = 12.0
    lambda_4: float = 1.0
    graph: float = 1.0
    panorama: float = 2.5
    spectrum: float = 0.75
    graph_on_proxy: float = 0.75
    level_ratio: float = 1.0
    norm: str = "l1"
    tung: bool = True
    groups: bool = False

    def __post_init__(self) -> None:
        for name in MATCH_FIELDS:
            value = float(getattr(self, name))
            if not math.isfinite(value) or value < 0:
                raise ValueError(f"{name}={value!r} must be finite and >= 0")
            object.__setattr__(self, name, float32(value))
        for name in MIXING_FIELDS:
            object.__setattr__(self, name, mixing_weight(mixing_steps(name, float(getattr(self, name)))))
        if self.norm not in ("l1", "l2"):
            raise ValueError(f"norm={self.norm!r} must be 'l1' or 'l2'")
        object.__setattr__(self, "tung", bool(self.tung))
        object.__setattr__(self, "groups", bool(self.groups))

    @classmethod
    def parse(cls, text: str) -> "ArgWeights":
        """Reads the canonical text the server prints: every key once, as key=value."""
        pairs: Dict[str, str] = {}
        for item in text.split():
            key, sep, value = item.partition("=")
            if not sep or key in pairs:
                raise ValueError(f"arg_weights: {item!r} is not a new key=value pair "
                                 "(presets are the server's: SELECT 'mrg'::arg_weights)")
            pairs[key] = value
        names = MATCH_FIELDS + MIXING_FIELDS + ("norm", "tung", "groups")
        for key, value in _OPTIONAL_KEYS.items():
            pairs.setdefault(key, value)
        if set(pairs) != set(names):
            missing = sorted(set(names) - set(pairs))
            unknown = sorted(set(pairs) - set(names))
            raise ValueError(f"arg_weights: not the canonical text (missing {missing}, unknown {unknown})")
        switches = {}
        for key in ("tung", "groups"):
            if pairs[key] not in ("on", "off"):
                raise ValueError(f"arg_weights: {key}={pairs[key]} (expected on or off)")
            switches[key] = pairs[key] == "on"
        numbers = {name: float(pairs[name]) for name in MATCH_FIELDS + MIXING_FIELDS}
        return cls(**numbers, norm=pairs["norm"], **switches)

    def __str__(self) -> str:
        """The canonical text, as the server's ``arg_weights_out`` prints it."""
        numbers = [f"{name}={_format_number(getattr(self, name))}"
                   for name in MATCH_FIELDS + MIXING_FIELDS]
        switches = [f"norm={self.norm}", "tung=" + ("on" if self.tung else "off"),
                    "groups=" + ("on" if self.groups else "off")]
        return " ".join(numbers + switches)

    def __repr__(self) -> str:
        fields = [f"{name}={_format_number(getattr(self, name))}"
                  for name in MATCH_FIELDS + MIXING_FIELDS]
        fields += [f"norm={self.norm!r}", f"tung={self.tung}", f"groups={self.groups}"]
        return f"ArgWeights({', '.join(fields)})"

    def replace(self, **changes: object) -> "ArgWeights":
        """A copy with some weights changed, checked as a new value is."""
        return dataclasses.replace(self, **changes)
