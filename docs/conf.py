# SPDX-License-Identifier: BSD-3-Clause
"""Sphinx configuration of the pw85 documentation.

Run by docs/meson.build (``meson compile`` with ``-Ddocs=enabled``), which
sets these environment variables:

PW85_VERSION          the project version (meson.build)
PW85_DOXYGEN_XML      the directory of Doxygen's XML for the public headers
PW85_DOCS_HEADERS     the headers that Doxygen read, separated by os.pathsep
PW85_FIGURE_DIR       the build directory where docs/meson.build draws the
                      figures (contact_figure.py); unset or without them
                      when pypw85 is not built
PW85_LIBRARY          libpw85 of this build, loaded by pypw85 (autodoc)
PW85_LEGACY_LIBRARY   libpw85_legacy of this build (empty if not built)
PYTHONPATH            bindings/python, where pypw85 lives

Formulas are rendered at build time by LaTeX and dvisvgm (imgmath): the
site uses no network, neither to build nor to read.
"""

import os
import re
import sys
from pathlib import Path

from docutils import nodes
from docutils.parsers.rst import directives
from docutils.statemachine import StringList
from sphinx import addnodes
from sphinx.directives.patches import Figure, MathDirective
from sphinx.util import logging
from sphinx.util.docutils import SphinxDirective

logger = logging.getLogger("pw85.docs")

DOCS = Path(__file__).resolve().parent
ROOT = DOCS.parent

project = "pw85"
author = "The pw85 developers"
copyright = "2026, " + author
release = os.environ.get("PW85_VERSION", "")
version = ".".join(release.split(".")[:2])

extensions = [
    "sphinx.ext.autodoc",
    "sphinx.ext.napoleon",
    "sphinx.ext.imgmath",
    "breathe",
]

root_doc = "index"
templates_path = ["_templates"]
exclude_patterns = ["accuracy", "_build"]
default_role = "py:obj"
primary_domain = "c"
highlight_language = "c"
pygments_style = "sphinx"
nitpicky = False

# -- HTML ------------------------------------------------------------------
html_theme = "alabaster"
html_title = "pw85 " + release
html_static_path = ["_static"]
html_css_files = ["pw85.css"]
html_theme_options = {
    "description": "The contact function of two ellipsoids",
    "fixed_sidebar": False,
    "page_width": "1040px",
    "sidebar_width": "230px",
    "show_relbars": True,
}
html_sidebars = {"**": ["about.html", "navigation.html", "searchbox.html"]}
html_show_sourcelink = False
html_copy_source = False

# -- Formulas: LaTeX + dvisvgm, no JavaScript, no network -------------------
imgmath_image_format = "svg"
imgmath_use_preview = True  # baseline alignment of inline formulas
imgmath_font_size = 13
# Sphinx 5.3 writes the paths of the images relative to the root of the
# site, whatever the page: every page stays at the root. (imgmath_embed
# would avoid that, but renders every formula again at every build.)
# docs/_templates/preview.tex_t: Sphinx's template without anyfontsize, so
# that texlive-latex-base and preview-latex-style are enough.

# -- C, C++: Doxygen XML through Breathe -----------------------------------
breathe_projects = {"pw85": os.environ.get("PW85_DOXYGEN_XML",
                                           str(DOCS / "_doxygen" / "xml"))}
breathe_default_project = "pw85"
breathe_domain_by_extension = {"h": "c", "hpp": "cpp"}
breathe_show_define_initializer = True
breathe_show_enumvalue_initializer = True
breathe_separate_member_pages = False

# -- Python: autodoc imports pypw85 from bindings/python -------------------------
autodoc_member_order = "bysource"
autodoc_typehints = "none"
napoleon_google_docstring = False
napoleon_numpy_docstring = True
napoleon_use_rtype = False
napoleon_use_ivar = True

sys.path.insert(0, str(ROOT / "bindings" / "python"))


def _importable(name):
    """True if the module imports (pypw85 loads libpw85 on import)."""
    try:
        __import__(name)
    except Exception as exc:  # ImportError, OSError from ctypes, ...
        logger.info("pw85 docs: %s is not importable (%s)", name,
                    str(exc).splitlines()[0] if str(exc) else type(exc))
        return False
    return True


def _documented_headers():
    value = os.environ.get("PW85_DOCS_HEADERS", "")
    return {Path(p).name for p in value.split(os.pathsep) if p}


# What the optional parts of the site need (see the pw85-optional
# directive below). Each is true on a full build of the project.
AVAILABLE = {
    "pypw85": _importable("pypw85"),
    "pypw85.legacy": _importable("pypw85.legacy"),
    "tutorial.py": (ROOT / "tutorial" / "tutorial.py").is_file(),
    "accuracy-f": (DOCS / "accuracy" / "accuracy-f.png").is_file(),
    "accuracy-mu2": (DOCS / "accuracy" / "accuracy-mu2.png").is_file(),
    "legacy-header": "pw85_legacy.h" in _documented_headers(),
    "matplotlib": _importable("matplotlib") and _importable("pypw85"),
}

# The figure of assemblies.rst is drawn at build time (plot_section.py).
if AVAILABLE["matplotlib"]:
    extensions.append("matplotlib.sphinxext.plot_directive")
    plot_formats = [("png", 110)]
    plot_html_show_source_link = False
    plot_html_show_formats = False
    plot_include_source = False
    plot_working_directory = str(DOCS)  # plot_section.py finds ../tutorial


class OptionalContent(SphinxDirective):
    """The content if a part of the project is available, else a note.

    Used only where the documentation would otherwise fail to build: a
    Python module that cannot be imported in this configuration (NumPy or
    the library missing), a file that another part of the project has not
    produced yet.

    .. pw85-optional:: pypw85
       :otherwise: text of the note (reStructuredText)

       content
    """

    required_arguments = 1
    has_content = True
    option_spec = {"otherwise": directives.unchanged_required}

    def run(self):
        key = self.arguments[0]
        if key not in AVAILABLE:
            raise self.error("pw85-optional: unknown key %r" % key)
        if AVAILABLE[key]:
            text = self.content
            offset = self.content_offset
        else:
            logger.info("pw85 docs: %s unavailable in %s: a note replaces "
                        "it", key, self.env.docname)
            note = nodes.note()
            text = " ".join(line.strip() for line in
                            self.options["otherwise"].splitlines())
            self.state.nested_parse(StringList([text], self.env.docname),
                                    self.content_offset, note)
            return [note]
        container = nodes.container()
        self.state.nested_parse(text, offset, container)
        return container.children


class BuiltFigure(Figure):
    """A figure drawn at build time into PW85_FIGURE_DIR (docs/meson.build),
    outside the source tree: the argument is its file name there. When the
    build did not draw it (pypw85 unavailable), a note replaces it.

    .. pw85-figure:: name.svg
       :otherwise: text of the note (reStructuredText)
       :alt: ... (the options of figure)

       Caption.
    """

    option_spec = dict(Figure.option_spec,
                       otherwise=directives.unchanged_required)

    def run(self):
        otherwise = self.options.pop("otherwise", None)
        if otherwise is None:
            raise self.error("pw85-figure: the option :otherwise: is required")
        env = self.state.document.settings.env  # a docutils directive
        name = self.arguments[0]
        folder = os.environ.get("PW85_FIGURE_DIR", "")
        path = Path(folder) / name if folder else None
        if path is None or not path.is_file():
            logger.info("pw85 docs: figure %s not drawn: a note replaces it "
                        "in %s", name, env.docname)
            note = nodes.note()
            text = " ".join(line.strip() for line in otherwise.splitlines())
            self.state.nested_parse(StringList([text], env.docname),
                                    self.content_offset, note)
            return [note]
        # Image paths are relative to the page's directory; Sphinx copies
        # the file into _images.
        page_dir = Path(env.srcdir) / Path(env.docname).parent
        self.arguments[0] = os.path.relpath(path.resolve(), page_dir)
        return super().run()


class NumberedMath(MathDirective):
    """A display formula numbered "(C.N)": equation N of chapter C.

    Chapters 3 to 6 of this site follow the chapters of the original pw85
    documentation, so "ch. 5, eq. (4)" in a comment of the source code is
    formula (5.4) here; "C.Na–c" numbers a display that gathers equations
    (C.Na) to (C.Nc). The label is ``eq-`` and the number, for :eq:.
    """

    option_spec = dict(MathDirective.option_spec, number=directives.unchanged_required)

    def run(self):
        number = self.options.get("number")
        if not number or not re.fullmatch(r"\d+\.\d+[a-z]?(–[a-z])?", number):
            raise self.error("numbered-math needs :number: C.N, C.Na or "
                             "C.Na–b, got %r" % number)
        self.options["label"] = "eq-" + number
        ret = super().run()
        node = next(n for n in ret if isinstance(n, nodes.math_block))
        domain = self.env.get_domain("math")
        domain.equations[node["label"]] = (self.env.docname, number)
        node["number"] = number
        return ret


_UNDERLINE = re.compile(r"^(-{3,}|={3,}|~{3,})$")
# Inline literals and roles, left alone by the escaping below.
_LITERAL = re.compile(r"(``.+?``|:\w+:`[^`]+`|`[^`]+`)")
# |x| (an absolute value in plain text) and name_ (a trailing underscore,
# as in lambda_) are markup in reStructuredText.
_PLAIN_MARKUP = re.compile(r"\||(?<=\w)_(?=$|[\s,.;:)\]])")


def _escape_plain(line):
    parts = _LITERAL.split(line)
    for k in range(0, len(parts), 2):  # outside literals and roles
        parts[k] = _PLAIN_MARKUP.sub(lambda m: "\\" + m.group(0), parts[k])
    return "".join(parts)


def _plain_docstrings(app, what, name, obj, options, lines):
    """The docstrings of pypw85 are written for help() as much as for this
    site: plain text with Unicode formulas such as |μ² − 1|, and argument
    names such as lambda_. Escape what reStructuredText would take for
    markup, and turn the section titles of module docstrings ("Title" over
    "-----"), which a directive cannot hold, into rubrics. Napoleon's own
    sections (Parameters, Returns, ...) are left to it."""
    if what == "module":
        i = 0
        while i + 1 < len(lines):
            title, rule = lines[i].strip(), lines[i + 1].strip()
            if title and _UNDERLINE.match(rule) and len(rule) >= len(title):
                lines[i:i + 2] = [".. rubric:: " + title, ""]
            i += 1
    in_literal_block = False
    for i, line in enumerate(lines):
        stripped = line.strip()
        if in_literal_block and stripped and not line[:1].isspace():
            in_literal_block = False
        if not in_literal_block and not stripped.startswith(".. "):
            lines[i] = _escape_plain(line)
        if stripped.endswith("::") and not stripped.startswith(".. "):
            in_literal_block = True


def _unlink_namespace_word(app, doctree):
    """Doxygen links every "pw85" of the header comments to the C++
    namespace pw85; in prose the word means the library: keep it as text."""
    for node in list(doctree.findall(addnodes.pending_xref)):
        if node.get("reftarget") == "namespacepw85" and node.astext() == "pw85":
            node.replace_self(nodes.Text("pw85"))


def setup(app):
    app.add_directive("pw85-optional", OptionalContent)
    app.add_directive("numbered-math", NumberedMath)
    app.add_directive("pw85-figure", BuiltFigure)
    app.connect("doctree-read", _unlink_namespace_word)
    app.connect("autodoc-process-docstring", _plain_docstrings,
                priority=400)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
