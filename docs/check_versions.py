# SPDX-License-Identifier: BSD-3-Clause
"""The version named in prose is the project's.

    check_versions.py VERSION SOURCE_ROOT

Every "pw85 X.Y" (or X.Y.Z) in the pages of docs/, in README.md and in
the docstrings of pypw85 names either this project's MAJOR.MINOR
(VERSION, from meson.build) or a version this one is defined against:
1.0, the original C API and the legacy library, and 2.0, the C++ API
(docs: "Installation" and the seeds). ``find_package(pw85 X.Y`` in the
README and in the CMake package asks for this MAJOR.MINOR. Prints each
offending line and exits with status 1; the docs build runs it before
Sphinx (build_step.py), and the test docs-version runs it alone.
"""

import pathlib
import re
import sys

#: Versions that prose may name besides the project's: what it re-implements.
REFERENCES = {"1.0": "the original C API (pw85 1.0) and its legacy library",
              "2.0": "the C++ API of pw85 2.0"}

MENTION = re.compile(r"\bpw85 (\d+)\.(\d+)(?:\.\d+)?\b")
FIND_PACKAGE = re.compile(r"find_package\(pw85 (\d+)\.(\d+)")


def files(root):
    yield from sorted((root / "docs").glob("*.rst"))
    yield root / "README.md"
    yield from sorted((root / "bindings" / "python" / "pypw85").glob("*.py"))
    yield root / "cmake" / "pw85Config.cmake.in"


def check(version, root):
    current = ".".join(version.split(".")[:2])
    errors = []
    for path in files(root):
        if not path.is_file():
            continue
        for number, line in enumerate(path.read_text().splitlines(), 1):
            for m in MENTION.finditer(line):
                named = "%s.%s" % m.groups()
                if named != current and named not in REFERENCES:
                    errors.append("%s:%d: names pw85 %s, but this is pw85 %s: "
                                  "%s" % (path.relative_to(root), number,
                                          named, current, line.strip()))
            for m in FIND_PACKAGE.finditer(line):
                named = "%s.%s" % m.groups()
                if named != current:
                    errors.append("%s:%d: find_package asks for pw85 %s, "
                                  "this is %s" % (path.relative_to(root),
                                                  number, named, current))
    return errors


def main(argv):
    if len(argv) != 3:
        sys.exit(__doc__)
    errors = check(argv[1], pathlib.Path(argv[2]))
    for e in errors:
        print(e)
    if errors:
        print("docs-version: %d stale version(s); the project is %s (meson.build)"
              % (len(errors), argv[1]))
        return 1
    print("docs-version: every version named in prose is %s or one of %s"
          % (argv[1], ", ".join(sorted(REFERENCES))))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
