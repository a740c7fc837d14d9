# SPDX-License-Identifier: BSD-3-Clause
"""The two steps of the documentation build, run by docs/meson.build.

    build_step.py doxygen DOXYGEN DOXYFILE XML_DIR STAMP
        Run Doxygen on DOXYFILE (warnings fail it), after removing XML_DIR
        so that nothing stale survives; then touch STAMP.
    build_step.py sphinx SOURCE_DIR HTML_DIR DOCTREE_DIR
        Check the versions named in prose (check_versions.py), then run
        sphinx-build (HTML, fresh environment, warnings as errors, every
        warning listed) with the interpreter running this script; then touch
        HTML_DIR, the output that ninja tracks.
"""

import os
import pathlib
import shutil
import subprocess
import sys
import time


def touch(path):
    if os.path.isdir(path):
        os.utime(path)
    else:
        with open(path, "a"):
            os.utime(path)


def doxygen(doxygen_exe, doxyfile, xml_dir, stamp):
    shutil.rmtree(xml_dir, ignore_errors=True)
    # Doxygen writes relative to its working directory: the Doxyfile's.
    result = subprocess.run([doxygen_exe, os.path.basename(doxyfile)],
                            cwd=os.path.dirname(os.path.abspath(doxyfile)))
    if result.returncode != 0:
        sys.exit("doxygen failed (status %d): see its messages above"
                 % result.returncode)
    if not os.path.isfile(os.path.join(xml_dir, "index.xml")):
        sys.exit("doxygen wrote no %s" % os.path.join(xml_dir, "index.xml"))
    touch(stamp)


def sphinx(source_dir, html_dir, doctree_dir):
    start = time.monotonic()
    # The version named in prose is the project's (check_versions.py).
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    import check_versions
    stale = check_versions.check(os.environ["PW85_VERSION"],
                                 pathlib.Path(source_dir).resolve().parent)
    if stale:
        sys.exit("\n".join(stale + ["stale versions in the prose (above)"]))
    # -E: a fresh environment every time. Sphinx would otherwise reread
    # only the pages it knows to have changed, and miss changes of conf.py's
    # code, of the environment (PW85_LIBRARY, ...) or of what pypw85 can
    # import. Formulas are still rendered only once: their images are kept
    # in HTML_DIR/_images/math.
    command = [sys.executable, "-m", "sphinx", "-b", "html", "-E", "-W",
               "--keep-going", "-q", "-d", doctree_dir, source_dir, html_dir]
    result = subprocess.run(command)
    if result.returncode != 0:
        sys.exit("sphinx-build failed (status %d): see its messages above"
                 % result.returncode)
    touch(html_dir)
    print("pw85 docs: %s/index.html (%.1f s)"
          % (html_dir, time.monotonic() - start))


def main(argv):
    if len(argv) == 6 and argv[1] == "doxygen":
        doxygen(*argv[2:])
    elif len(argv) == 5 and argv[1] == "sphinx":
        sphinx(*argv[2:])
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main(sys.argv)
