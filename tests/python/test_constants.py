# SPDX-License-Identifier: BSD-3-Clause
"""pypw85's constants against include/pw85/pw85.h, its messages against
the library.

The values of pypw85/_constants.py are written by hand; these tests parse
the header (found through PW85_SOURCE_ROOT, which meson sets) and fail when
a ``#define PW85_*`` number has no Python counterpart or a different value,
and when a status message is not the library's own pw85_strerror() text.
"""

import ast
import ctypes
import pathlib
import re

import pytest

import pypw85
from pypw85 import _constants

from conftest import SOURCE_ROOT

HEADER = SOURCE_ROOT / "include" / "pw85" / "pw85.h"

# An object-like macro: the name after PW85_, then its replacement text up
# to an optional comment. Function-like macros (a '(' right after the name)
# and macros with no value do not match.
DEFINE = re.compile(r"^[ \t]*#[ \t]*define[ \t]+PW85_(\w+)[ \t]+(.+?)[ \t]*"
                    r"(?:/[*/].*)?$", re.M)
# C integer and floating constants, with their suffixes.
C_INT = re.compile(r"[-+]?(0[xX][0-9a-fA-F]+|[0-9]+)[uUlL]*")
C_FLOAT = re.compile(r"[-+]?([0-9]+\.[0-9]*|\.[0-9]+|[0-9]+)"
                     r"([eE][-+]?[0-9]+)?[fFlL]?")

# Numeric macros with no counterpart in pypw85, and why.
NOT_MIRRORED = {
    # The headers' version describes the build; pypw85 reports the version
    # of the library it loaded (__version__, from pw85_version()), which
    # test_api.py compares with the project's.
    "VERSION_MAJOR", "VERSION_MINOR", "VERSION_PATCH", "VERSION_NUMBER",
}


def c_number(text):
    """The value of a C numeric literal (parentheses allowed), or None."""
    text = text.strip()
    while text.startswith("(") and text.endswith(")"):
        text = text[1:-1].strip()
    match = C_INT.fullmatch(text)
    if match:
        sign = -1 if text.startswith("-") else 1
        return sign * int(match.group(1), 0 if match.group(1)[:2] in
                          ("0x", "0X") else 10)
    match = C_FLOAT.fullmatch(text)
    if match:
        return float(text.rstrip("fFlL"))
    return None


def header_numbers(path):
    """{NAME: value} of every numeric #define PW85_NAME in the header."""
    numbers = {}
    for name, text in DEFINE.findall(path.read_text()):
        value = c_number(text)
        if value is not None:
            numbers[name] = value
    return numbers


NUMBERS = header_numbers(HEADER)
MIRRORED = sorted(set(NUMBERS) - NOT_MIRRORED)
STATUSES = {name: value for name, value in NUMBERS.items()
            if re.fullmatch(r"SUCCESS|E[A-Z]+", name)}


def test_parser():
    """The parser reads literals as C does, and finds the header's."""
    assert c_number("3") == 3 and type(c_number("3")) is int
    assert c_number("(25)") == 25
    assert c_number("0x10u") == 16
    assert c_number("1e-6") == 1e-6 and type(c_number("1e-6")) is float
    assert c_number("2.5f") == 2.5
    assert c_number("-4") == -4
    assert c_number('"2.1.0"') is None
    assert c_number("__attribute__((visibility(\"default\")))") is None
    assert c_number("noexcept") is None
    # Names that the header has always had: a parser that finds nothing
    # would otherwise pass every test below.
    assert {"DIM", "SYM", "LAMBDA_ATOL", "MAX_ITER", "NR_ITER", "SUCCESS",
            "EDOM", "ENOCONV"} <= set(NUMBERS), NUMBERS


@pytest.mark.parametrize("name", MIRRORED)
def test_header_number_in_pypw85(name):
    """Every numeric macro of pw85.h has the same value, and type, in
    pypw85 and in pypw85._constants."""
    expected = NUMBERS[name]
    for where in (pypw85, _constants):
        assert hasattr(where, name), "%s.%s missing (PW85_%s = %r)" % (
            where.__name__, name, name, expected)
        actual = getattr(where, name)
        assert actual == expected, (where.__name__, name, actual, expected)
        assert type(actual) is type(expected), (name, type(actual))


def test_pypw85_numbers_in_header():
    """No numeric constant of pypw85 or _constants is unknown to pw85.h."""
    for where in (pypw85, _constants):
        names = {name for name in dir(where)
                 if name.isupper() and not name.startswith("_")
                 and type(getattr(where, name)) in (int, float)}
        assert names, where.__name__
        assert names <= set(NUMBERS), (where.__name__, names - set(NUMBERS))
        assert names >= set(MIRRORED), (where.__name__,
                                         set(MIRRORED) - names)


def test_legacy_enoconv():
    try:
        import pypw85.legacy as legacy
    except ImportError:
        pytest.skip("libpw85_legacy is not built")
    assert legacy.ENOCONV == NUMBERS["ENOCONV"]


@pytest.mark.parametrize("name", sorted(STATUSES))
def test_status_named_in_messages(name):
    """Error names each status code of the header by its C name."""
    assert "(PW85_%s)" % name in str(pypw85.Error(STATUSES[name]))


def library_strerror():
    """pw85_strerror of the loaded library, through a ctypes function of
    our own (not the one pypw85 declared)."""
    lib = ctypes.CDLL(pypw85._library_path)
    strerror = lib.pw85_strerror
    strerror.argtypes = [ctypes.c_int]
    strerror.restype = ctypes.c_char_p
    return lambda status: strerror(status).decode("utf-8")


@pytest.mark.parametrize("status", sorted(STATUSES.values()) + [-1, 1000])
def test_messages_from_library(status):
    expected = library_strerror()(status)
    error = pypw85.Error(status, "where")
    assert error.strerror == expected
    assert str(error).startswith("where: %s (" % expected)
    if status in STATUSES.values():
        assert not expected.startswith("unknown"), status


def code_strings(source):
    """The string literals of a Python file, docstrings excepted."""
    tree = ast.parse(source.read_text(), str(source))
    docstrings = set()
    for node in ast.walk(tree):
        if isinstance(node, (ast.Module, ast.ClassDef, ast.FunctionDef,
                             ast.AsyncFunctionDef)) and node.body and \
                isinstance(node.body[0], ast.Expr):
            docstrings.add(id(node.body[0].value))
    return [node for node in ast.walk(tree)
            if isinstance(node, ast.Constant) and isinstance(node.value, str)
            and id(node) not in docstrings]


def test_messages_not_duplicated():
    """No string in pypw85's code (docstrings may describe the errors)
    repeats a message of pw85_strerror(): the library is the one place of
    those texts."""
    strerror = library_strerror()
    messages = {strerror(status) for status in STATUSES.values()}
    package = pathlib.Path(pypw85.__file__).parent
    sources = sorted(package.glob("*.py"))
    assert len(sources) > 2, sources
    for source in sources:
        for node in code_strings(source):
            for message in messages:
                assert message not in node.value, (source.name,
                                                   node.lineno, message)
