// SPDX-License-Identifier: BSD-3-Clause
// pw85_index.hpp: pw85::Index against the C functions of pw85_index.h
// called directly on the same configurations (the same results, bit for
// bit), the capacity protocol with many results, moves, and every status
// of pw85_index.h returned with the index and the outputs unchanged.
#include <glib.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <pw85/pw85.hpp>  // gives pw85::Index (pw85_index.hpp)
#include <utility>
#include <vector>

namespace {

using Neighbours = std::vector<pw85::Index::Neighbour>;
using Overlaps = std::vector<pw85::Index::OverlappingPair>;
using Pairs = std::vector<pw85::Index::Pair>;

double const nan = std::numeric_limits<double>::quiet_NaN();
double const inf = std::numeric_limits<double>::infinity();
double const side = 8.;
double const box[pw85::dim] = {side, side, side};

// A random ellipsoid: semi-axes from 0.2 to 1.2 (radius ratios to 6,
// aspect ratios to 6), a random orientation from a normalised Gaussian
// quaternion, the centre anywhere in [-side/2, 3·side/2)³ (so that
// ellipsoids straddle the faces and corners of the periodic box).
struct Ellipsoid {
  double c[pw85::dim];
  double q[pw85::sym];
};

Ellipsoid random_ellipsoid(GRand *rng) {
  Ellipsoid e;
  double a[pw85::dim], p[4], norm = 0.;
  for (double &x : a) x = g_rand_double_range(rng, 0.2, 1.2);
  for (double &x : p) {
    double const u = g_rand_double_range(rng, 1e-300, 1.);
    double const v = g_rand_double(rng);
    x = std::sqrt(-2. * std::log(u)) * std::cos(2. * G_PI * v);
    norm += x * x;
  }
  for (double &x : p) x /= std::sqrt(norm);
  g_assert_cmpint(pw85_ellipsoid_quaternion(a, p, e.q), ==, PW85_SUCCESS);
  for (double &x : e.c) x = g_rand_double_range(rng, -side / 2, 1.5 * side);
  return e;
}

// The C queries through their own protocol: ask for the count (capacity
// 0), then call again with exactly that room.
struct CResults {
  int status = PW85_SUCCESS;
  std::vector<std::size_t> ids;
  std::vector<int> shifts, results;
  std::vector<double> mu2_lambda;
};

template <typename Call>
CResults c_query(std::size_t ids_per, Call call) {
  CResults r;
  std::size_t n = 0;
  r.status = call(0, nullptr, nullptr, nullptr, nullptr, &n);
  if (r.status != PW85_SUCCESS) return r;
  r.ids.resize(ids_per * n);
  r.shifts.resize(3 * n);
  r.results.resize(n);
  r.mu2_lambda.resize(2 * n);
  std::size_t again = 0;
  r.status = call(n, r.ids.data(), r.shifts.data(), r.results.data(),
                  r.mu2_lambda.data(), &again);
  g_assert_cmpuint(again, ==, n);
  return r;
}

void same_shift(std::array<int, 3> const &s, int const *c_shift) {
  for (std::size_t d = 0; d < 3; ++d) g_assert_cmpint(s[d], ==, c_shift[d]);
}

// Bit for bit: μ² and λ compared as bytes.
void same_double(double x, double y) {
  g_assert_cmpmem(&x, sizeof x, &y, sizeof y);
}

void same_within(pw85::Index const &ix, pw85_index const *c, Ellipsoid const &e,
                 double t, std::size_t exclude) {
  Neighbours out;
  int const status = ix.within(e.c, e.q, t, exclude, out);
  CResults r = c_query(1, [&](std::size_t cap, std::size_t *ids, int *sh, int *,
                              double *ml, std::size_t *n) {
    return pw85_index_within(c, e.c, e.q, t, exclude, cap, ids, sh, ml, n);
  });
  g_assert_cmpint(status, ==, r.status);
  g_assert_cmpuint(out.size(), ==, r.ids.size());
  for (std::size_t k = 0; k < out.size(); ++k) {
    g_assert_cmpuint(out[k].id, ==, r.ids[k]);
    same_shift(out[k].shift, &r.shifts[3 * k]);
    same_double(out[k].mu2, r.mu2_lambda[2 * k]);
    same_double(out[k].lambda, r.mu2_lambda[2 * k + 1]);
  }
}

void same_overlapping_pairs(pw85::Index const &ix, pw85_index const *c,
                            int threads) {
  Overlaps out;
  int const status = ix.overlapping_pairs(threads, out);
  CResults r = c_query(2, [&](std::size_t cap, std::size_t *ids, int *sh,
                              int *res, double *, std::size_t *n) {
    return pw85_index_overlapping_pairs(c, threads, cap, ids, sh, res, n);
  });
  g_assert_cmpint(status, ==, r.status);
  g_assert_cmpuint(out.size(), ==, r.results.size());
  for (std::size_t k = 0; k < out.size(); ++k) {
    g_assert_cmpuint(out[k].i, ==, r.ids[2 * k]);
    g_assert_cmpuint(out[k].j, ==, r.ids[2 * k + 1]);
    same_shift(out[k].shift, &r.shifts[3 * k]);
    g_assert_cmpint(out[k].result, ==, r.results[k]);
  }
}

void same_pairs_within(pw85::Index const &ix, pw85_index const *c, double t,
                       int threads) {
  Pairs out;
  int const status = ix.pairs_within(t, threads, out);
  CResults r = c_query(2, [&](std::size_t cap, std::size_t *ids, int *sh, int *,
                              double *ml, std::size_t *n) {
    return pw85_index_pairs_within(c, t, threads, cap, ids, sh, ml, n);
  });
  g_assert_cmpint(status, ==, r.status);
  g_assert_cmpuint(out.size(), ==, r.ids.size() / 2);
  for (std::size_t k = 0; k < out.size(); ++k) {
    g_assert_cmpuint(out[k].i, ==, r.ids[2 * k]);
    g_assert_cmpuint(out[k].j, ==, r.ids[2 * k + 1]);
    same_shift(out[k].shift, &r.shifts[3 * k]);
    same_double(out[k].mu2, r.mu2_lambda[2 * k]);
    same_double(out[k].lambda, r.mu2_lambda[2 * k + 1]);
  }
}

// Every member's answer on ix equals the C function's on c: count, get of
// every id up to max_id (stored or not), the queries on candidates, the
// all-pairs queries on 1 and 2 threads.
void same_answers(pw85::Index const &ix, pw85_index const *c, GRand *rng,
                  std::size_t max_id) {
  std::size_t n = 0, n_c = 0;
  g_assert_cmpint(ix.count(n), ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_index_count(c, &n_c), ==, PW85_SUCCESS);
  g_assert_cmpuint(n, ==, n_c);
  for (std::size_t id = 0; id <= max_id; ++id) {
    Ellipsoid e{}, e_c{};
    g_assert_cmpint(ix.get(id, e.c, e.q), ==,
                    pw85_index_get(c, id, e_c.c, e_c.q));
    g_assert_cmpmem(&e, sizeof e, &e_c, sizeof e_c);
  }
  for (int k = 0; k < 40; ++k) {
    Ellipsoid const e = random_ellipsoid(rng);
    std::size_t const exclude =
        k % 2 ? pw85::index_no_id
              : (std::size_t)g_rand_int_range(rng, 0, (gint32)max_id + 1);
    int result = 7, result_c = 7;
    std::size_t id = 7, id_c = 7;
    g_assert_cmpint(
        ix.overlap_any(e.c, e.q, exclude, result, id), ==,
        pw85_index_overlap_any(c, e.c, e.q, exclude, &result_c, &id_c));
    g_assert_cmpint(result, ==, result_c);
    g_assert_cmpuint(id, ==, id_c);
    same_within(ix, c, e, 1., exclude);
    same_within(ix, c, e, 2.5, exclude);
  }
  // overlap_any_batch(): contiguous arrays, on 2 threads, against the C
  // function's one call per candidate.
  std::size_t const m = 600;
  std::vector<double> cs(3 * m), qs(6 * m);
  std::vector<std::size_t> excl(m), ids(m), ids_c(m);
  std::vector<int> results(m), results_c(m);
  for (std::size_t i = 0; i < m; ++i) {
    Ellipsoid const e = random_ellipsoid(rng);
    std::copy(e.c, e.c + 3, &cs[3 * i]);
    std::copy(e.q, e.q + 6, &qs[6 * i]);
    excl[i] = i % 2 ? pw85::index_no_id : i % (max_id + 1);
    g_assert_cmpint(pw85_index_overlap_any(c, e.c, e.q, excl[i], &results_c[i], &ids_c[i]),
                    ==, PW85_SUCCESS);
  }
  g_assert_cmpint(ix.overlap_any_batch(m, cs.data(), qs.data(), excl.data(), results.data(),
                                       ids.data(), nullptr, 2),
                  ==, PW85_SUCCESS);
  g_assert_true(results == results_c);
  g_assert_true(ids == ids_c);
  for (int threads : {1, 2}) {
    same_overlapping_pairs(ix, c, threads);
    same_pairs_within(ix, c, 1.7, threads);
  }
}

// The same random configuration in a pw85::Index and in a pw85_index
// called directly, then the same random updates, removals and insertions
// in both.
void twin_configuration(bool periodic) {
  GRand *rng = g_rand_new_with_seed(periodic ? 16 : 61);
  pw85::Index ix;
  pw85_index *c = nullptr;
  g_assert_cmpint(
      periodic ? pw85::Index::periodic(box, ix) : pw85::Index::open(ix), ==,
      PW85_SUCCESS);
  g_assert_true(static_cast<bool>(ix));
  g_assert_cmpint(pw85_index_create(periodic ? box : nullptr, &c), ==,
                  PW85_SUCCESS);
  std::size_t const n = 150;
  // Half one at a time, half through insert_many.
  std::vector<std::size_t> ids;
  std::vector<double> centres, forms;
  for (std::size_t id = 0; id < n; ++id) {
    Ellipsoid const e = random_ellipsoid(rng);
    if (id % 2) {
      g_assert_cmpint(ix.insert(id, e.c, e.q), ==, PW85_SUCCESS);
      g_assert_cmpint(pw85_index_insert(c, id, e.c, e.q), ==, PW85_SUCCESS);
    } else {
      ids.push_back(id);
      centres.insert(centres.end(), e.c, e.c + 3);
      forms.insert(forms.end(), e.q, e.q + 6);
    }
  }
  g_assert_cmpint(
      ix.insert_many(ids.size(), ids.data(), centres.data(), forms.data()), ==,
      PW85_SUCCESS);
  g_assert_cmpint(pw85_index_insert_many(c, ids.size(), ids.data(),
                                         centres.data(), forms.data()),
                  ==, PW85_SUCCESS);
  same_answers(ix, c, rng, n + 5);
  {  // insert_many() on threads (pw85_index_insert_many_threads()): the same
    pw85::Index t;
    g_assert_cmpint(
        periodic ? pw85::Index::periodic(box, t) : pw85::Index::open(t), ==,
        PW85_SUCCESS);
    for (std::size_t id = 1; id < n; id += 2) {
      double cc[3], qq[6];
      g_assert_cmpint(pw85_index_get(c, id, cc, qq), ==, PW85_SUCCESS);
      g_assert_cmpint(t.insert(id, cc, qq), ==, PW85_SUCCESS);
    }
    g_assert_cmpint(t.insert_many(ids.size(), ids.data(), centres.data(),
                                  forms.data(), 0), ==, PW85_EINVAL);
    g_assert_cmpint(t.insert_many(ids.size(), ids.data(), centres.data(),
                                  forms.data(), 2), ==, PW85_SUCCESS);
    same_answers(t, c, rng, n + 5);
  }
  // Overlaps there are, else the comparisons of the pairs prove little.
  Overlaps overlaps;
  g_assert_cmpint(ix.overlapping_pairs(1, overlaps), ==, PW85_SUCCESS);
  g_assert_cmpuint(overlaps.size(), >, 10);

  for (int step = 0; step < 300; ++step) {
    std::size_t const id = (std::size_t)g_rand_int_range(rng, 0, (gint32)n + 5);
    Ellipsoid const e = random_ellipsoid(rng);
    int status, status_c;
    switch (g_rand_int_range(rng, 0, 3)) {
      case 0:
        status = ix.update(id, e.c, e.q);
        status_c = pw85_index_update(c, id, e.c, e.q);
        break;
      case 1:
        status = ix.remove(id);
        status_c = pw85_index_remove(c, id);
        break;
      default:
        status = ix.insert(id, e.c, e.q);
        status_c = pw85_index_insert(c, id, e.c, e.q);
    }
    g_assert_cmpint(status, ==, status_c);
  }
  same_answers(ix, c, rng, n + 5);
  pw85_index_destroy(c);
  g_rand_free(rng);
}

void test_same_open() { twin_configuration(false); }
void test_same_periodic() { twin_configuration(true); }

// Many more results than the first guess of the wrapper (16 for within,
// 64 for the pairs) and than a stale output's capacity, and fewer than
// it: the vectors end with exactly the C function's results.
void test_capacity() {
  GRand *rng = g_rand_new_with_seed(3);
  pw85::Index ix;
  pw85_index *c = nullptr;
  g_assert_cmpint(pw85::Index::periodic(box, ix), ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_index_create(box, &c), ==, PW85_SUCCESS);
  for (std::size_t id = 0; id < 100; ++id) {
    Ellipsoid const e = random_ellipsoid(rng);
    g_assert_cmpint(ix.insert(id, e.c, e.q), ==, PW85_SUCCESS);
    g_assert_cmpint(pw85_index_insert(c, id, e.c, e.q), ==, PW85_SUCCESS);
  }
  Ellipsoid const e = random_ellipsoid(rng);
  Neighbours near;
  g_assert_cmpint(ix.within(e.c, e.q, 400., pw85::index_no_id, near), ==,
                  PW85_SUCCESS);
  g_assert_cmpuint(near.size(), >, 1000);  // every ellipsoid, many images
  same_within(ix, c, e, 400., pw85::index_no_id);
  Pairs pairs;
  g_assert_cmpint(ix.pairs_within(40., 2, pairs), ==, PW85_SUCCESS);
  g_assert_cmpuint(pairs.size(), >, 10000);
  same_pairs_within(ix, c, 40., 2);

  // A reused vector: larger than needed (shrinks), then smaller (grows
  // past its capacity), each time the C results exactly.
  std::size_t const big = pairs.size();
  g_assert_cmpint(ix.pairs_within(1.2, 1, pairs), ==, PW85_SUCCESS);
  g_assert_cmpuint(pairs.size(), <, big);
  g_assert_cmpuint(pairs.capacity(), >=, big);
  CResults r = c_query(2, [&](std::size_t cap, std::size_t *ids, int *sh, int *,
                              double *ml, std::size_t *n) {
    return pw85_index_pairs_within(c, 1.2, 1, cap, ids, sh, ml, n);
  });
  g_assert_cmpuint(pairs.size(), ==, r.ids.size() / 2);
  pairs.shrink_to_fit();
  std::size_t const small = pairs.size();
  g_assert_cmpint(ix.pairs_within(40., 1, pairs), ==, PW85_SUCCESS);
  g_assert_cmpuint(pairs.size(), ==, big);
  g_assert_cmpuint(small, <, big);
  pw85_index_destroy(c);
  g_rand_free(rng);
}

double const unit_q[pw85::sym] = {1., 0., 0., 1., 0., 1.};
double const origin[pw85::dim] = {0., 0., 0.};

// Every member of an Index that holds no index returns PW85_EFAULT and
// writes nothing.
void check_empty(pw85::Index &ix) {
  g_assert_false(static_cast<bool>(ix));
  g_assert_null(ix.handle());
  std::size_t n = 7, id = 7;
  int result = 7;
  double c[pw85::dim] = {7., 7., 7.}, q[pw85::sym] = {7., 7., 7., 7., 7., 7.};
  g_assert_cmpint(ix.count(n), ==, PW85_EFAULT);
  g_assert_cmpint(ix.insert(0, origin, unit_q), ==, PW85_EFAULT);
  g_assert_cmpint(ix.insert_many(1, &id, origin, unit_q), ==, PW85_EFAULT);
  g_assert_cmpint(ix.update(0, origin, unit_q), ==, PW85_EFAULT);
  g_assert_cmpint(ix.remove(0), ==, PW85_EFAULT);
  g_assert_cmpint(ix.get(0, c, q), ==, PW85_EFAULT);
  g_assert_cmpint(ix.overlap_any(origin, unit_q, pw85::index_no_id, result, id),
                  ==, PW85_EFAULT);
  g_assert_cmpint(ix.overlap_any_batch(1, origin, unit_q, nullptr, &result, &id), ==,
                  PW85_EFAULT);
  g_assert_cmpuint(n, ==, 7);
  g_assert_cmpuint(id, ==, 7);
  g_assert_cmpint(result, ==, 7);
  g_assert_cmpfloat(c[0], ==, 7.);
  g_assert_cmpfloat(q[5], ==, 7.);
  Neighbours near(2);
  Overlaps overlaps(3);
  Pairs pairs(4);
  g_assert_cmpint(ix.within(origin, unit_q, 1., pw85::index_no_id, near), ==,
                  PW85_EFAULT);
  g_assert_cmpint(ix.overlapping_pairs(1, overlaps), ==, PW85_EFAULT);
  g_assert_cmpint(ix.pairs_within(1., 1, pairs), ==, PW85_EFAULT);
  g_assert_cmpuint(near.size(), ==, 2);
  g_assert_cmpuint(overlaps.size(), ==, 3);
  g_assert_cmpuint(pairs.size(), ==, 4);
}

std::size_t count_of(pw85::Index const &ix) {
  std::size_t n = 0;
  g_assert_cmpint(ix.count(n), ==, PW85_SUCCESS);
  return n;
}

// Moves: the index goes with the move, the moved-from object holds none
// and is destroyed (or reused) safely; assignment destroys the index the
// target held (LeakSanitizer sees it otherwise, in the sanitizer build).
void test_move() {
  static_assert(!std::is_copy_constructible<pw85::Index>::value, "move-only");
  static_assert(!std::is_copy_assignable<pw85::Index>::value, "move-only");
  static_assert(std::is_nothrow_move_constructible<pw85::Index>::value, "");
  static_assert(std::is_nothrow_move_assignable<pw85::Index>::value, "");
  pw85::Index empty;
  check_empty(empty);

  pw85::Index a;
  g_assert_cmpint(pw85::Index::periodic(box, a), ==, PW85_SUCCESS);
  g_assert_cmpint(a.insert(3, origin, unit_q), ==, PW85_SUCCESS);
  pw85_index *const handle = a.handle();
  pw85::Index b(std::move(a));
  check_empty(a);
  g_assert_true(b.handle() == handle);
  g_assert_cmpuint(count_of(b), ==, 1);

  pw85::Index c;
  g_assert_cmpint(pw85::Index::open(c), ==, PW85_SUCCESS);
  g_assert_cmpint(c.insert(0, origin, unit_q), ==, PW85_SUCCESS);
  c = std::move(b);  // c's own index destroyed
  check_empty(b);
  g_assert_true(c.handle() == handle);
  pw85::Index &alias = c;
  c = std::move(alias);  // into itself: nothing changes
  g_assert_true(c.handle() == handle);
  g_assert_cmpuint(count_of(c), ==, 1);

  // The moved-from object is reused; creating into a live Index destroys
  // the index it held.
  g_assert_cmpint(pw85::Index::open(a), ==, PW85_SUCCESS);
  g_assert_cmpuint(count_of(a), ==, 0);
  g_assert_cmpint(pw85::Index::open(a), ==, PW85_SUCCESS);
  g_assert_cmpint(a.insert(1, origin, unit_q), ==, PW85_SUCCESS);

  // Ownership of an index created by the C function.
  pw85_index *raw = nullptr;
  g_assert_cmpint(pw85_index_create(nullptr, &raw), ==, PW85_SUCCESS);
  pw85::Index adopted(raw);
  g_assert_true(adopted.handle() == raw);
  g_assert_cmpint(adopted.insert(0, origin, unit_q), ==, PW85_SUCCESS);
  pw85::Index none(nullptr);
  check_empty(none);
  // a, c, adopted destroyed here with their indexes; b, empty, none hold
  // none.
}

// What a failed call must not change: the count, every stored ellipsoid,
// a query on a candidate and the all-pairs query.
struct Snapshot {
  std::size_t count;
  std::vector<double> stored;
  Neighbours near;
  Pairs pairs;
};

Snapshot snapshot(pw85::Index const &ix) {
  Snapshot s;
  s.count = count_of(ix);
  for (std::size_t id = 0; id < 12; ++id) {
    double c[pw85::dim], q[pw85::sym];
    if (ix.get(id, c, q) != PW85_SUCCESS) continue;
    s.stored.push_back((double)id);
    s.stored.insert(s.stored.end(), c, c + pw85::dim);
    s.stored.insert(s.stored.end(), q, q + pw85::sym);
  }
  double const centre[pw85::dim] = {1., 2., 3.};
  g_assert_cmpint(ix.within(centre, unit_q, 30., pw85::index_no_id, s.near), ==,
                  PW85_SUCCESS);
  g_assert_cmpint(ix.pairs_within(30., 1, s.pairs), ==, PW85_SUCCESS);
  return s;
}

void same_snapshot(Snapshot const &a, Snapshot const &b) {
  g_assert_cmpuint(a.count, ==, b.count);
  g_assert_cmpuint(a.stored.size(), ==, b.stored.size());
  g_assert_cmpmem(a.stored.data(), a.stored.size() * sizeof(double),
                  b.stored.data(), b.stored.size() * sizeof(double));
  g_assert_cmpuint(a.near.size(), ==, b.near.size());
  for (std::size_t k = 0; k < a.near.size(); ++k) {
    g_assert_cmpuint(a.near[k].id, ==, b.near[k].id);
    same_double(a.near[k].mu2, b.near[k].mu2);
  }
  g_assert_cmpuint(a.pairs.size(), ==, b.pairs.size());
  for (std::size_t k = 0; k < a.pairs.size(); ++k) {
    g_assert_cmpuint(a.pairs[k].i, ==, b.pairs[k].i);
    g_assert_cmpuint(a.pairs[k].j, ==, b.pairs[k].j);
    same_double(a.pairs[k].mu2, b.pairs[k].mu2);
  }
}

// Runs op, which must return `expected`, and checks that the index is as
// it was.
template <typename Op>
void fails(pw85::Index &ix, int expected, Op op) {
  Snapshot const before = snapshot(ix);
  g_assert_cmpint(op(), ==, expected);
  same_snapshot(before, snapshot(ix));
}

// Every status of pw85_index.h through the members, each leaving the
// index, and the outputs, as they were.
void test_errors() {
  pw85::Index ix;
  double const bad_boxes[][pw85::dim] = {
      {nan, 1., 1.}, {1., inf, 1.}, {0., 1., 1.}, {1., 1., -2.}};
  int const bad_box_status[] = {PW85_EDOM, PW85_EDOM, PW85_EINVAL, PW85_EINVAL};
  g_assert_cmpint(pw85::Index::periodic(nullptr, ix), ==, PW85_EFAULT);
  check_empty(ix);
  for (std::size_t k = 0; k < 4; ++k) {
    g_assert_cmpint(pw85::Index::periodic(bad_boxes[k], ix), ==,
                    bad_box_status[k]);
    check_empty(ix);
  }
  g_assert_cmpint(pw85::Index::periodic(box, ix), ==, PW85_SUCCESS);
  pw85_index *const handle = ix.handle();
  // A failed creation into a live Index keeps the index it holds.
  g_assert_cmpint(pw85::Index::periodic(bad_boxes[0], ix), ==, PW85_EDOM);
  g_assert_true(ix.handle() == handle);

  double const c1[pw85::dim] = {1., 1., 1.}, c2[pw85::dim] = {1.5, 1., 1.};
  double const big[pw85::dim] = {1., 1., 1e12};
  double const c_nan[pw85::dim] = {1., nan, 1.};
  double const q_nan[pw85::sym] = {1., 0., 0., 1., 0., inf};
  double const q_indef[pw85::sym] = {1., 2., 0., 1., 0., 1.};
  double const q_wide[pw85::sym] = {16.1, 0., 0., 1., 0., 1.};  // 2·√16.1 > 8
  g_assert_cmpint(ix.insert(0, c1, unit_q), ==, PW85_SUCCESS);
  g_assert_cmpint(ix.insert(1, c2, unit_q), ==, PW85_SUCCESS);
  g_assert_cmpint(ix.insert(5, origin, unit_q), ==, PW85_SUCCESS);

  fails(ix, PW85_EINVAL, [&] { return ix.insert(1, origin, unit_q); });
  fails(ix, PW85_EINVAL,
        [&] { return ix.insert(pw85::index_max_id + 1, origin, unit_q); });
  fails(ix, PW85_EFAULT, [&] { return ix.insert(2, nullptr, unit_q); });
  fails(ix, PW85_EFAULT, [&] { return ix.insert(2, origin, nullptr); });
  fails(ix, PW85_EDOM, [&] { return ix.insert(2, c_nan, unit_q); });
  fails(ix, PW85_EDOM, [&] { return ix.insert(2, origin, q_nan); });
  fails(ix, PW85_ENOTPOSDEF, [&] { return ix.insert(2, origin, q_indef); });
  fails(ix, PW85_EINVAL, [&] { return ix.insert(2, origin, q_wide); });
  fails(ix, PW85_EINVAL, [&] { return ix.insert(2, big, unit_q); });

  // insert_many: all or none (the first two are good).
  std::size_t const dup_ids[] = {2, 3, 2};
  std::size_t const used_ids[] = {2, 3, 5};
  std::size_t const new_ids[] = {2, 3, 4};
  double const centres[] = {3., 3., 3., 5., 5., 5., 6., 6., 6.};
  double forms[3 * pw85::sym];
  for (std::size_t k = 0; k < 3; ++k)
    std::memcpy(forms + pw85::sym * k, unit_q, sizeof unit_q);
  fails(ix, PW85_EINVAL,
        [&] { return ix.insert_many(3, dup_ids, centres, forms); });
  fails(ix, PW85_EINVAL,
        [&] { return ix.insert_many(3, used_ids, centres, forms); });
  std::memcpy(forms + 2 * pw85::sym, q_indef, sizeof q_indef);
  fails(ix, PW85_ENOTPOSDEF,
        [&] { return ix.insert_many(3, new_ids, centres, forms); });
  fails(ix, PW85_EFAULT,
        [&] { return ix.insert_many(3, nullptr, centres, forms); });

  fails(ix, PW85_EINVAL, [&] { return ix.update(7, c1, unit_q); });
  fails(ix, PW85_ENOTPOSDEF, [&] { return ix.update(0, c2, q_indef); });
  fails(ix, PW85_EDOM, [&] { return ix.update(0, c_nan, unit_q); });
  fails(ix, PW85_EINVAL, [&] { return ix.update(0, origin, q_wide); });
  fails(ix, PW85_EINVAL, [&] { return ix.remove(7); });
  fails(ix, PW85_EINVAL, [&] { return ix.remove(pw85::index_no_id); });

  double c[pw85::dim] = {7., 7., 7.}, q[pw85::sym] = {7., 7., 7., 7., 7., 7.};
  fails(ix, PW85_EINVAL, [&] { return ix.get(7, c, q); });
  fails(ix, PW85_EFAULT, [&] { return ix.get(0, nullptr, q); });
  g_assert_cmpfloat(c[0], ==, 7.);
  g_assert_cmpfloat(q[0], ==, 7.);

  int result = 7;
  std::size_t id = 7;
  fails(ix, PW85_ENOTPOSDEF, [&] {
    return ix.overlap_any(c1, q_indef, pw85::index_no_id, result, id);
  });
  fails(ix, PW85_EDOM, [&] {
    return ix.overlap_any(c_nan, unit_q, pw85::index_no_id, result, id);
  });
  fails(ix, PW85_EINVAL, [&] {
    return ix.overlap_any(big, unit_q, pw85::index_no_id, result, id);
  });
  g_assert_cmpint(result, ==, 7);
  g_assert_cmpuint(id, ==, 7);

  // The output vectors keep their contents on error.
  Neighbours near(1);
  near[0].id = 42;
  Overlaps overlaps(1);
  overlaps[0].i = 42;
  Pairs pairs(1);
  pairs[0].i = 42;
  double const tiny_q[pw85::sym] = {1e-20, 0., 0., 1e-20, 0., 1e-20};
  fails(ix, PW85_EINVAL,
        [&] { return ix.within(c1, unit_q, 0., pw85::index_no_id, near); });
  fails(ix, PW85_EINVAL,
        [&] { return ix.within(c1, unit_q, -1., pw85::index_no_id, near); });
  fails(ix, PW85_EDOM,
        [&] { return ix.within(c1, unit_q, nan, pw85::index_no_id, near); });
  fails(ix, PW85_ENOTPOSDEF,
        [&] { return ix.within(c1, q_indef, 1., pw85::index_no_id, near); });
  fails(ix, PW85_ERANGE,
        [&] { return ix.within(c1, tiny_q, 1e300, pw85::index_no_id, near); });
  fails(ix, PW85_EINVAL, [&] { return ix.overlapping_pairs(0, overlaps); });
  fails(ix, PW85_EINVAL, [&] { return ix.overlapping_pairs(-3, overlaps); });
  fails(ix, PW85_EDOM, [&] { return ix.pairs_within(inf, 1, pairs); });
  fails(ix, PW85_EINVAL, [&] { return ix.pairs_within(0., 1, pairs); });
  fails(ix, PW85_EINVAL, [&] { return ix.pairs_within(1., 0, pairs); });
  fails(ix, PW85_ERANGE, [&] { return ix.pairs_within(1e300, 1, pairs); });
  g_assert_cmpuint(near.size(), ==, 1);
  g_assert_cmpuint(near[0].id, ==, 42);
  g_assert_cmpuint(overlaps.size(), ==, 1);
  g_assert_cmpuint(overlaps[0].i, ==, 42);
  g_assert_cmpuint(pairs.size(), ==, 1);
  g_assert_cmpuint(pairs[0].i, ==, 42);
}

void test_constants() {
  static_assert(pw85::index_max_id == PW85_INDEX_MAX_ID, "max id");
  static_assert(pw85::index_no_id == PW85_INDEX_NO_ID, "no id");
  g_assert_cmpint(pw85::Index::openmp(), ==, pw85_index_openmp() != 0);
}

}  // namespace

int main(int argc, char **argv) {
  g_test_init(&argc, &argv, nullptr);
  g_test_add_func("/pw85/index-hpp/constants", test_constants);
  g_test_add_func("/pw85/index-hpp/same/open", test_same_open);
  g_test_add_func("/pw85/index-hpp/same/periodic", test_same_periodic);
  g_test_add_func("/pw85/index-hpp/capacity", test_capacity);
  g_test_add_func("/pw85/index-hpp/move", test_move);
  g_test_add_func("/pw85/index-hpp/errors", test_errors);
  return g_test_run();
}
