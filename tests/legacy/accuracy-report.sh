#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# Regenerates the accuracy comparison of docs/implementation.rst, "Accuracy": the CSV histograms
# (accuracy-report) and their figures (plot_accuracy.py).
# Usage: accuracy-report.sh REPORT-EXE DATA.h5 OUTDIR PYTHON PLOT-SCRIPT
set -eu
exe=$1 data=$2 outdir=$3 python=$4 plot=$5
"$exe" "$data" "$outdir"
"$python" "$plot" "$outdir"
