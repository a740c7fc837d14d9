#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Draw the accuracy comparison of seed ch. 4.3 from the CSV histograms that
tests/legacy/accuracy-report.c writes (run `ninja -C BUILD accuracy-report`).

Writes accuracy-f.png/.svg (f: implementation #1, Cholesky, against
implementation #2, rational fraction) and accuracy-mu2.png/.svg (μ²: the
contact function of libpw85 and the two legacy ones).

Usage: /usr/bin/python3 docs/accuracy/plot_accuracy.py [DIR]
DIR (default: the folder of this script) holds the CSV files and receives
the figures. Needs Debian's python3-matplotlib.
"""

import csv
import os
import sys

try:
    import matplotlib
except ImportError:  # pragma: no cover
    sys.exit("plot_accuracy.py: matplotlib is missing (Debian: apt-get install "
             "python3-matplotlib; run with /usr/bin/python3)")

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# Fixed metadata so that regenerated SVG files are reproducible.
SVG_METADATA = {"Date": None, "Creator": None}
PNG_METADATA = {"Software": None}


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    digits = [int(r["digits"]) for r in rows]
    columns = {k: [float(r[k]) for r in rows] for k in rows[0] if k != "digits"}
    return digits, columns


def bars(ax, digits, series, title):
    """Grouped bars, one group per number of correct digits; series are
    (label, values, color, hatch)."""
    n = len(series)
    width = 0.8 / n
    for k, (label, values, color, hatch) in enumerate(series):
        x = [d + (k - (n - 1) / 2) * width for d in digits]
        ax.bar(x, values, width=width, label=label, color=color, hatch=hatch,
               edgecolor="black", linewidth=0.4)
    ax.set_xlabel("number of correct digits")
    ax.set_ylabel("fraction of cases (%)")
    ax.set_xticks(digits)
    # The top bin also holds the exact results; bin 0, the results with a
    # relative error of 10% or more (and NaN).
    labels = [str(d) for d in digits]
    labels[-1] = "\u2265%d" % digits[-1]
    ax.set_xticklabels(labels)
    ax.set_xlim(min(digits) - 0.6, max(digits) + 0.6)
    ax.set_title(title)
    ax.grid(axis="y", linewidth=0.3)
    ax.set_axisbelow(True)
    ax.legend(loc="upper left")


def save(fig, outdir, stem):
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, stem + ".png"), dpi=120,
                metadata=PNG_METADATA)
    fig.savefig(os.path.join(outdir, stem + ".svg"), metadata=SVG_METADATA)
    plt.close(fig)


def main():
    outdir = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(
        os.path.abspath(__file__))
    plt.rcParams["svg.hashsalt"] = "pw85"

    digits, cols = read_csv(os.path.join(outdir, "accuracy-f.csv"))
    fig, ax = plt.subplots(figsize=(8, 4.5))
    bars(ax, digits, [
        ("implementation #1 (Cholesky)", cols["percent_impl1"], "tab:blue",
         None),
        ("implementation #2 (rational fraction)", cols["percent_impl2"],
         "tab:orange", None),
        ("implementation #1 in plain double (pw85_legacy_f1)",
         cols["percent_impl1_plain"], "white", "////"),
    ], "Accuracy of f over the reference dataset F (1,539,648 values)")
    save(fig, outdir, "accuracy-f")

    digits, cols = read_csv(os.path.join(outdir, "accuracy-mu2.csv"))
    fig, ax = plt.subplots(figsize=(8, 4.5))
    bars(ax, digits, [
        ("pw85_contact_function (Brent + Newton, implementation #1)",
         cols["percent_contact_function"], "tab:blue", None),
        ("pw85_legacy_contact_function1 (Newton on f\u2032)",
         cols["percent_legacy_contact_function1"], "tab:green", None),
        ("pw85_legacy_contact_function2 (bisection, implementation #2)",
         cols["percent_legacy_contact_function2"], "tab:orange", None),
    ], "Accuracy of \u03bc\u00b2 over the reference dataset MU2 "
       "(419,904 values)")
    save(fig, outdir, "accuracy-mu2")


if __name__ == "__main__":
    main()
