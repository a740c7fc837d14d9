/* SPDX-License-Identifier: BSD-3-Clause */
/* The yardstick of bench_batch.py: the plain C loop of single-pair calls
 * over contiguous arrays, loaded by ctypes into the benchmark's process so
 * that both are timed in the same run. */
#include <pw85.h>
#include <stddef.h>

void bench_loop_contact_function(size_t n, double const *r12,
                                 double const *q1, double const *q2,
                                 double *out) {
  for (size_t i = 0; i < n; i++)
    pw85_contact_function(r12 + 3 * i, q1 + 6 * i, q2 + 6 * i, out + 2 * i);
}

void bench_loop_overlap(size_t n, double const *r12, double const *q1,
                        double const *q2, int *result) {
  for (size_t i = 0; i < n; i++)
    pw85_overlap(r12 + 3 * i, q1 + 6 * i, q2 + 6 * i, result + i);
}
