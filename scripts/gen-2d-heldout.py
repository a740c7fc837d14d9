#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Write a held-out set of 2D reference pairs (issue 29, "Done when": mu^2
correctly rounded on a held-out set of the same classes that the project does
not see).

The same generator as data/pw85_2d_pairs.h5 (data/gen_2d_data.py: the same
classes, recipes, counts, certified references and checks) with a seed of
your choosing, written to the path you give.  Never commit the output, and
keep the seed out of the repository: a held-out set is only held out while
nobody tunes the library on it.

Usage (from the repository root):
    /usr/bin/python3 scripts/gen-2d-heldout.py OUTPUT.h5 --seed N
        [--jobs 2] [--count K] [--geometry OUTPUT_GEOMETRY.h5]

Check it (and replay it with the library's tests by pointing them at the
file, e.g. PW85_2D_PAIRS=OUTPUT.h5):
    /usr/bin/python3 data/check_2d_data.py --pairs OUTPUT.h5 --seed N \\
        --geometry none
"""

import argparse
import os
import sys

sys.dont_write_bytecode = True
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "data"))
import gen_2d_data as gen  # noqa: E402


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("output", help="the pairs file to write (HDF5)")
    ap.add_argument("--seed", type=int, required=True,
                    help="any integer but the committed data's (%d)"
                    % gen.SEED)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--count", type=int, default=None,
                    help="records per class (default: as the committed file)")
    ap.add_argument("--geometry", default=None,
                    help="also write the geometry file here")
    args = ap.parse_args(argv)
    if args.seed == gen.SEED:
        ap.error("--seed %d is the committed data's seed" % gen.SEED)
    out = os.path.abspath(args.output)
    if os.path.commonpath([out, ROOT]) == ROOT:
        print("warning: %s is inside the repository; do not commit it" % out)
    outdir = os.path.dirname(out)
    os.makedirs(outdir, exist_ok=True)
    gen.generate(outdir, args.jobs, args.seed, args.count,
                 only=None if args.geometry else "pairs", pairs_path=out,
                 geom_path=os.path.abspath(args.geometry)
                 if args.geometry else None)
    return 0


if __name__ == "__main__":
    sys.exit(main())
