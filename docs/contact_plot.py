# SPDX-License-Identifier: BSD-3-Clause
"""The drawing shared by contact_figure.py (two ellipsoids, their section
by z = 0) and ellipse_figure.py (two ellipses): each shape filled, its
outline, the same scaled by μ and its centre; the line of centres, the
contact point x0 and the common normal n; the title, legend and axes.
A module of the docs' build, imported by those two scripts from their
folder."""

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

COLOURS = ("#3a6ea5", "#c0504d")


def figure(height):
    """A figure 7 inches wide, fonts and SVG ids fixed (reproducible)."""
    plt.rcParams.update({"svg.hashsalt": "pw85", "font.size": 11})
    return plt.subplots(figsize=(7.0, height))


def shapes(ax, pairs, outline, mu):
    """Draw each (c, q) of `pairs` (two) through outline(c, q, scale), in
    the plane: c its centre (its first two coordinates drawn)."""
    for (c, q), colour, name in zip(pairs, COLOURS, ("1", "2")):
        xy = outline(c, q, 1.0)
        ax.fill(*xy, color=colour, alpha=0.25, lw=0)
        ax.plot(*xy, color=colour, lw=1.5, label=r"$E_%s$" % name)
        ax.plot(*outline(c, q, mu), color=colour, lw=1.2, ls="--",
                label=r"$E_%s$ scaled by $\mu$" % name)
        ax.plot(c[0], c[1], "+", color=colour, ms=9, mew=1.5)
        ax.annotate(r"$c_%s$" % name, c[:2], xytext=(5, -13),
                    textcoords="offset points", color=colour)


def contact(ax, c1, c2, x, n, x_offset):
    """The line of centres, the contact point x (labelled at x_offset
    points from it) and the normal n, all of two coordinates."""
    ax.plot([c1[0], c2[0]], [c1[1], c2[1]], color="0.5", lw=0.8, ls=":")
    ax.plot(x[0], x[1], "o", color="black", ms=5, zorder=3)
    ax.annotate(r"$x_0$", x, xytext=x_offset, textcoords="offset points")
    ax.annotate("", xy=x + 0.9 * n, xytext=x,
                arrowprops=dict(arrowstyle="-|>", color="black", lw=1.3))
    ax.annotate(r"$n$", x + 0.9 * n, xytext=(4, 0),
                textcoords="offset points")


def finish(fig, ax, title, output):
    """Title, equal axes, the legend beside the plot; saved to output
    (no date in the SVG: the same bytes on every build)."""
    ax.set_title(title)
    ax.set_aspect("equal")
    ax.legend(loc="center left", bbox_to_anchor=(1.02, 0.5), fontsize=9,
              frameon=False)
    ax.set_xlabel(r"$x$")
    ax.set_ylabel(r"$y$")
    fig.tight_layout()
    fig.savefig(output, metadata={"Date": None})
