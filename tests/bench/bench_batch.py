# SPDX-License-Identifier: BSD-3-Clause
"""Benchmark (meson test --benchmark): pypw85 on arrays of pairs against
the C loop of single-pair calls (the yardstick, bench-loop.c, loaded into
this process), per pair, at N = 1e3, 1e5 and 1e6 pairs of the reference
workload (the 419,904 pairs of data/pw85_ref_data.h5, sampled or repeated),
and the speed-up of 2 threads over 1.

Ratios matter, not absolute times: the machines are shared. Each variant is
timed in turn, interleaved, R rounds, and the best time of each is kept.

    bench_batch.py REF_DATA LOOP_LIBRARY
"""

import ctypes
import sys
import time

import h5py
import numpy as np

import pypw85

ROUNDS = 7


def workload(path):
    """r12 (N, 3), q1 (N, 6), q2 (N, 6) of every record of MU2, in the
    order of bench-contact.cpp (spheroid i, spheroid j, direction,
    distance)."""
    with h5py.File(path, "r") as f:
        dirs, sph, dist = (np.asarray(f[k]) for k in
                           ("directions", "spheroids", "distances"))
    ns, nd, nm = len(sph), len(dirs), len(dist)
    i, j, k, m = (a.ravel() for a in np.meshgrid(
        np.arange(ns), np.arange(ns), np.arange(nd), np.arange(nm),
        indexing="ij"))
    r12 = dist[m, None] * dirs[k]
    return (np.ascontiguousarray(r12), np.ascontiguousarray(sph[i]),
            np.ascontiguousarray(sph[j]))


def take(pairs, n):
    """n pairs: evenly spaced through the workload, or the workload
    repeated."""
    total = len(pairs[0])
    index = (np.linspace(0, total - 1, n).astype(np.intp) if n <= total
             else np.arange(n) % total)
    return tuple(np.ascontiguousarray(a[index]) for a in pairs)


def best_times(variants, repeat):
    """{name: best seconds per call} over ROUNDS interleaved rounds; each
    timing runs the variant `repeat` times."""
    best = {name: float("inf") for name in variants}
    for _ in range(ROUNDS):
        for name, run in variants.items():
            t0 = time.perf_counter()
            for _ in range(repeat):
                run()
            best[name] = min(best[name], (time.perf_counter() - t0) / repeat)
    return best


def main(ref_data, loop_library):
    loop = ctypes.CDLL(loop_library)
    p = ctypes.c_void_p
    for name in ("bench_loop_contact_function", "bench_loop_overlap"):
        getattr(loop, name).argtypes = [ctypes.c_size_t, p, p, p, p]
        getattr(loop, name).restype = None
    pairs = workload(ref_data)
    print("pypw85 %s (%s), OpenMP threads: %d by default; %d rounds, best "
          "of each" % (pypw85.__version__, pypw85._library_path,
                       pypw85.batch_threads(0), ROUNDS))
    print("  %-18s %9s %10s %10s %10s %9s %9s"
          % ("function", "N", "C loop", "batch 1t", "batch 2t", "1t / C",
             "2t speed"))
    print("  %-18s %9s %10s %10s %10s %9s %9s"
          % ("", "", "ns/pair", "ns/pair", "ns/pair", "", "-up"))
    for n in (1000, 100000, 1000000):
        r12, q1, q2 = take(pairs, n)
        out = np.empty((n, 2))
        result = np.empty(n, dtype=np.intc)
        addresses = [a.ctypes.data for a in (r12, q1, q2)]
        repeat = max(1, 100000 // n)
        cases = {
            "contact_function": {
                "c": lambda: loop.bench_loop_contact_function(
                    n, *addresses, out.ctypes.data),
                "b1": lambda: pypw85.contact_function(r12, q1, q2, out,
                                                      threads=1),
                "b2": lambda: pypw85.contact_function(r12, q1, q2, out,
                                                      threads=2)},
            "overlap": {
                "c": lambda: loop.bench_loop_overlap(n, *addresses,
                                                     result.ctypes.data),
                "b1": lambda: pypw85.overlap(r12, q1, q2, threads=1),
                "b2": lambda: pypw85.overlap(r12, q1, q2, threads=2)},
        }
        for name, variants in cases.items():
            t = best_times(variants, repeat)
            print("  %-18s %9d %10.1f %10.1f %10.1f %9.3f %9.2f"
                  % (name, n, 1e9 * t["c"] / n, 1e9 * t["b1"] / n,
                     1e9 * t["b2"] / n, t["b1"] / t["c"], t["b1"] / t["b2"]))
        sys.stdout.flush()

    # One form against many (stride 0) against the same form copied to
    # every pair, the copy included (what broadcasting would cost without
    # strides), for the cheapest call.
    n = 1000000
    r12, q1, q2 = take(pairs, n)
    q = q1[0]
    t = best_times({
        "stride 0": lambda: pypw85.overlap(r12, q, q2),
        "copied": lambda: pypw85.overlap(
            r12, np.ascontiguousarray(np.broadcast_to(q, (n, 6))), q2)}, 1)
    print("  overlap, one q1 against 1e6 pairs: stride 0 %.1f ns/pair, "
          "copied %.1f ns/pair (copy / stride 0 = %.3f)"
          % (1e9 * t["stride 0"] / n, 1e9 * t["copied"] / n,
             t["copied"] / t["stride 0"]))


if __name__ == "__main__":
    main(*sys.argv[1:])
