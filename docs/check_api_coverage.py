# SPDX-License-Identifier: BSD-3-Clause
"""Check that the generated API reference documents the whole API.

    check_api_coverage.py --nm NM --html HTML_DIR --xml DOXYGEN_XML_DIR
        --lib LIB [--lib LIB ...] --header H [--header H ...]
        [--python MODULE ...]

Reads the Sphinx inventory HTML_DIR/objects.inv and requires:

- every symbol exported by each LIB (``nm -D --defined-only``) as a C
  function of the reference, whose Doxygen entry has a description, and
  whose anchor is in the page the inventory names;
- every macro defined by the C headers (include guards aside) as a C macro;
- every function and constant of the C++ header (namespace pw85) as a C++
  function or variable;
- every public class that a C++ header declares, and each of its public
  members (functions, fields, nested classes), as a C++ entry of the
  reference with a description in the header;
- every name in ``MODULE.__all__`` as a Python object of the reference.

Prints what it checked; exit status 1 and the list of what is missing
otherwise. Run by meson as the test docs-api-coverage (suite docs).
"""

import argparse
import importlib
import re
import subprocess
import sys
import xml.etree.ElementTree as ET
import zlib
from pathlib import Path

_INVENTORY_LINE = re.compile(r"(.+?)\s+(\S+?):(\S+)\s+(-?\d+)\s+(\S*)\s+(.*)")


def read_inventory(path):
    """{(domain:role, name): uri} from a Sphinx objects.inv (version 2)."""
    with open(path, "rb") as f:
        header = [f.readline() for _ in range(4)]
        if not header[0].startswith(b"# Sphinx inventory version 2"):
            sys.exit("%s: not a Sphinx inventory of version 2" % path)
        body = zlib.decompress(f.read()).decode("utf-8")
    entries = {}
    for line in body.splitlines():
        m = _INVENTORY_LINE.fullmatch(line.rstrip())
        if not m:
            continue
        name, domain, role, _, uri, _ = m.groups()
        if uri.endswith("$"):
            uri = uri[:-1] + name
        entries[(domain + ":" + role, name)] = uri
    return entries


def exported_symbols(nm, lib):
    out = subprocess.run([nm, "-D", "--defined-only", lib], check=True,
                         capture_output=True, text=True).stdout
    symbols = set()
    for line in out.splitlines():
        fields = line.split()
        # Type A: a version node (PW85_2.0, ...), not a function.
        if len(fields) == 3 and fields[1] != "A":
            symbols.add(fields[2].split("@")[0])
    if not symbols:
        sys.exit("%s exports no symbol: is it the library?" % lib)
    return symbols


def documented_members(xml_dir):
    """{name: has a description} for the members of Doxygen's XML."""
    index = ET.parse(Path(xml_dir) / "index.xml").getroot()
    members = {}
    for compound in index.findall("compound"):
        tree = ET.parse(Path(xml_dir) / (compound.get("refid") + ".xml"))
        for member in tree.iter("memberdef"):
            name = member.findtext("qualifiedname") or member.findtext("name")
            text = "".join(member.find("briefdescription").itertext()) + \
                "".join(member.find("detaileddescription").itertext())
            members[name] = members.get(name, False) or bool(text.strip())
    return members


def _described(element):
    return bool(("".join(element.find("briefdescription").itertext()) +
                 "".join(element.find("detaileddescription").itertext())).strip())


def cpp_classes(xml_dir, header):
    """[(role, qualified name, has a description)] for the public classes
    that a C++ header declares and their public members (Doxygen's XML)."""
    found = []
    index = ET.parse(Path(xml_dir) / "index.xml").getroot()
    for compound in index.findall("compound"):
        if compound.get("kind") not in ("class", "struct"):
            continue
        cdef = ET.parse(Path(xml_dir) / (compound.get("refid") + ".xml")) \
            .getroot().find("compounddef")
        location = cdef.find("location")
        if location is None or cdef.get("prot") != "public" or \
                Path(location.get("file")).name != Path(header).name:
            continue
        name = cdef.findtext("compoundname")
        found.append(("cpp:class", name, _described(cdef)))
        for member in cdef.iter("memberdef"):
            if member.get("prot") != "public":
                continue
            role = "cpp:function" if member.get("kind") == "function" \
                else "cpp:member"
            found.append((role, name + "::" + member.findtext("name"),
                          _described(member)))
    return found


def header_macros(path):
    text = Path(path).read_text(encoding="utf-8")
    names = re.findall(r"^\s*#\s*define\s+(\w+)", text, re.M)
    return {n for n in names if not n.endswith("_H")}


_CPP_TOKEN = re.compile(
    r"(?P<ns>\bnamespace\s+(?P<name>\w+)\s*\{)"
    r"|(?P<fn>\binline\s[^;{}]*?\b(?P<fname>\w+)\s*\()"
    r"|(?P<const>\bconstexpr\s[^;{}=]*?\b(?P<cname>\w+)\s*[{=])"
    r"|(?P<open>\{)|(?P<close>\})")


def _without_comments(text):
    """C++ text with its comments and string literals blanked."""
    return re.sub(r'//[^\n]*|/\*.*?\*/|"(?:\\.|[^"\\])*"',
                  lambda m: " " * len(m.group(0)), text, flags=re.S)


def cpp_names(path):
    """The functions and constants that a C++ header declares, each
    qualified by the namespaces it is in (pw85::d2::contact_function)."""
    text = _without_comments(Path(path).read_text(encoding="utf-8"))
    functions, constants = set(), set()
    scopes = []  # a namespace name, or None for any other brace
    for m in _CPP_TOKEN.finditer(text):
        names = [s for s in scopes if s is not None]
        if m.group("ns"):
            scopes.append(m.group("name"))
        elif m.group("fn"):
            functions.add("::".join(names + [m.group("fname")]))
            # the body or the initialiser list follows: a brace of its own
        elif m.group("const"):
            # In a class or a function (a brace that is not a namespace's)
            # it is a member or a local: cpp_classes checks the members.
            if None not in scopes:
                constants.add("::".join(names + [m.group("cname")]))
            if m.group(0).endswith("{"):
                scopes.append(None)
        elif m.group("open"):
            scopes.append(None)
        elif m.group("close") and scopes:
            scopes.pop()
    return functions, constants


def anchor_in_page(html_dir, uri, cache={}):
    page, _, anchor = uri.partition("#")
    if page not in cache:
        cache[page] = (Path(html_dir) / page).read_text(encoding="utf-8")
    return not anchor or ('id="%s"' % anchor) in cache[page]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--nm", required=True)
    parser.add_argument("--html", required=True)
    parser.add_argument("--xml", required=True)
    parser.add_argument("--lib", action="append", default=[])
    parser.add_argument("--header", action="append", default=[])
    parser.add_argument("--python", action="append", default=[])
    args = parser.parse_args()

    inventory = read_inventory(Path(args.html) / "objects.inv")
    members = documented_members(args.xml)
    missing = []
    checked = 0

    def require(kind, name, what, describe=None):
        nonlocal checked
        checked += 1
        uri = inventory.get((kind, name))
        if uri is None:
            missing.append("%s %s: no %s entry in the reference" % (what, name, kind))
        elif not anchor_in_page(args.html, uri):
            missing.append("%s %s: anchor of %s not in the page" % (what, name, uri))
        elif describe is not None and not members.get(describe):
            missing.append("%s %s: no description in the header" % (what, name))

    for lib in args.lib:
        symbols = sorted(exported_symbols(args.nm, lib))
        for symbol in symbols:
            require("c:function", symbol, Path(lib).name + " exports", symbol)
        print("%s: %d exported symbols" % (Path(lib).name, len(symbols)))

    for header in args.header:
        if header.endswith(".hpp"):
            functions, constants = cpp_names(header)
            for name in sorted(functions):
                require("cpp:function", name, "C++ function", name)
            for name in sorted(constants):
                require("cpp:member", name, "C++ constant")
            entries = cpp_classes(args.xml, header)
            for role, name, described in entries:
                require(role, name, "C++ class member")
                if not described:
                    missing.append("C++ class member %s: no description in "
                                   "the header" % name)
            print("%s: %d functions, %d constants, %d class entries"
                  % (Path(header).name, len(functions), len(constants),
                     len(entries)))
        else:
            macros = sorted(header_macros(header))
            for name in macros:
                require("c:macro", name, "macro", name)
            print("%s: %d macros" % (Path(header).name, len(macros)))

    for module_name in args.python:
        module = importlib.import_module(module_name)
        require("py:module", module_name, "Python module")
        for name in module.__all__:
            kinds = [k for (k, n) in inventory
                     if n == module_name + "." + name and k.startswith("py:")]
            require(kinds[0] if kinds else "py:object", module_name + "." + name,
                    "Python name")
        print("%s: %d public names" % (module_name, len(module.__all__)))

    if missing:
        print("\n%d of %d checks failed:" % (len(missing), checked))
        for line in missing:
            print("  " + line)
        return 1
    print("ok: %d API entries documented" % checked)
    return 0


if __name__ == "__main__":
    sys.exit(main())
