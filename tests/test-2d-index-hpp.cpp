// SPDX-License-Identifier: BSD-3-Clause
// pw85_2d_index.hpp: pw85::d2::Index against the C functions of
// pw85_2d_index.h called directly on the same configurations (the same
// results, bit for bit, the vectors' capacity protocol with many
// results), moves, an object that holds no index, and failed calls that
// leave the outputs as they were.
#include <glib.h>

#include <cmath>
#include <cstring>
#include <pw85/pw85_2d_index.hpp>
#include <type_traits>
#include <utility>
#include <vector>

namespace {

using Index = pw85::d2::Index;
constexpr int D = PW85_2D_DIM, S = PW85_2D_SYM;
double const box[D] = {9., 7.5};

struct Ellipse {
  double c[D];
  double q[S];
};

Ellipse random_ellipse(GRand *rng) {
  Ellipse e;
  double const a[D] = {g_rand_double_range(rng, .2, 1.2),
                       g_rand_double_range(rng, .2, 1.2)};
  g_assert_cmpint(pw85_2d_ellipse(a, g_rand_double_range(rng, -3.2, 3.2), e.q), ==,
                  PW85_SUCCESS);
  for (int k = 0; k < D; ++k) e.c[k] = g_rand_double_range(rng, -.5 * box[k], 1.5 * box[k]);
  return e;
}

// The C answers, asked with exactly the room they need.
struct C {
  std::vector<std::size_t> ids;
  std::vector<int> shifts, results;
  std::vector<double> ml;
};

C c_pairs(pw85_2d_index const *ix, bool within, double t) {
  C r;
  std::size_t n = 0;
  g_assert_cmpint(within ? pw85_2d_index_pairs_within(ix, t, 2, 0, nullptr, nullptr, nullptr, &n)
                         : pw85_2d_index_overlapping_pairs(ix, 2, 0, nullptr, nullptr, nullptr, &n),
                  ==, PW85_SUCCESS);
  r.ids.resize(2 * n + 2), r.shifts.resize(D * n + D), r.results.resize(n + 1);
  r.ml.resize(2 * n + 2);
  g_assert_cmpint(within ? pw85_2d_index_pairs_within(ix, t, 2, n, r.ids.data(), r.shifts.data(),
                                                      r.ml.data(), &n)
                         : pw85_2d_index_overlapping_pairs(ix, 2, n, r.ids.data(),
                                                           r.shifts.data(), r.results.data(), &n),
                  ==, PW85_SUCCESS);
  r.ids.resize(2 * n), r.shifts.resize(D * n), r.results.resize(n), r.ml.resize(2 * n);
  return r;
}

// Both ways into the same configuration (the C++ one periodic or open as
// the C one), then every query compared.
void test_same(gconstpointer data) {
  bool const periodic = GPOINTER_TO_INT(data) != 0;
  GRand *rng = g_rand_new_with_seed(periodic ? 61 : 62);
  Index ix;
  g_assert_cmpint(periodic ? Index::periodic(box, ix) : Index::open(ix), ==, PW85_SUCCESS);
  pw85_2d_index *c = nullptr;
  g_assert_cmpint(pw85_2d_index_create(periodic ? box : nullptr, &c), ==, PW85_SUCCESS);
  std::size_t const n = 150;
  std::vector<std::size_t> ids(n);
  std::vector<double> cs(D * n), qs(S * n);
  for (std::size_t i = 0; i < n; ++i) {
    Ellipse const e = random_ellipse(rng);
    ids[i] = 3 * i;
    std::memcpy(&cs[D * i], e.c, sizeof e.c);
    std::memcpy(&qs[S * i], e.q, sizeof e.q);
  }
  g_assert_cmpint(ix.insert_many(n / 2, ids.data(), cs.data(), qs.data()), ==, PW85_SUCCESS);
  g_assert_cmpint(ix.insert_many(n - n / 2, &ids[n / 2], &cs[D * (n / 2)], &qs[S * (n / 2)], 2),
                  ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_2d_index_insert_many(c, n, ids.data(), cs.data(), qs.data()), ==,
                  PW85_SUCCESS);
  for (std::size_t i = 0; i < n; i += 7) {  // moves, a removal, insertions
    Ellipse const e = random_ellipse(rng);
    g_assert_cmpint(ix.update(ids[i], e.c, e.q), ==, PW85_SUCCESS);
    g_assert_cmpint(pw85_2d_index_update(c, ids[i], e.c, e.q), ==, PW85_SUCCESS);
  }
  g_assert_cmpint(ix.remove(ids[4]), ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_2d_index_remove(c, ids[4]), ==, PW85_SUCCESS);
  std::size_t count = 0;
  g_assert_cmpint(ix.count(count), ==, PW85_SUCCESS);
  g_assert_cmpuint(count, ==, n - 1);

  // all pairs: overlapping, and within t = 4 (thousands of pairs, beyond
  // the vectors' first guess)
  std::vector<Index::OverlappingPair> overlaps;
  g_assert_cmpint(ix.overlapping_pairs(2, overlaps), ==, PW85_SUCCESS);
  C const co = c_pairs(c, false, 1.);
  g_assert_cmpuint(overlaps.size(), ==, co.results.size());
  for (std::size_t k = 0; k < overlaps.size(); ++k) {
    g_assert_cmpuint(overlaps[k].i, ==, co.ids[2 * k]);
    g_assert_cmpuint(overlaps[k].j, ==, co.ids[2 * k + 1]);
    g_assert_true(std::memcmp(overlaps[k].shift.data(), &co.shifts[D * k], D * sizeof(int)) == 0);
    g_assert_cmpint(overlaps[k].result, ==, co.results[k]);
  }
  std::vector<Index::Pair> pairs;
  g_assert_cmpint(ix.pairs_within(4., 1, pairs), ==, PW85_SUCCESS);
  C const cp = c_pairs(c, true, 4.);
  g_assert_cmpuint(pairs.size(), ==, cp.ids.size() / 2);
  g_assert_cmpuint(pairs.size(), >, 64);
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    g_assert_cmpuint(pairs[k].i, ==, cp.ids[2 * k]);
    g_assert_cmpuint(pairs[k].j, ==, cp.ids[2 * k + 1]);
    g_assert_true(std::memcmp(pairs[k].shift.data(), &cp.shifts[D * k], D * sizeof(int)) == 0);
    g_assert_true(pairs[k].mu2 == cp.ml[2 * k] && pairs[k].lambda == cp.ml[2 * k + 1]);
  }

  // candidates: overlap_any, its batch, within
  std::vector<double> bc, bq;
  std::vector<int> br;
  std::vector<std::size_t> bi;
  for (int k = 0; k < 30; ++k) {
    Ellipse const e = random_ellipse(rng);
    std::size_t const exclude = k % 3 ? pw85::index_no_id : ids[k];
    int r1 = 9, r2 = 8;
    std::size_t i1 = 9, i2 = 8;
    g_assert_cmpint(ix.overlap_any(e.c, e.q, exclude, r1, i1), ==, PW85_SUCCESS);
    g_assert_cmpint(pw85_2d_index_overlap_any(c, e.c, e.q, exclude, &r2, &i2), ==, PW85_SUCCESS);
    g_assert_cmpint(r1, ==, r2);
    g_assert_cmpuint(i1, ==, i2);
    bc.insert(bc.end(), e.c, e.c + D), bq.insert(bq.end(), e.q, e.q + S);
    br.push_back(r1), bi.push_back(i1);
    std::vector<Index::Neighbour> near;
    g_assert_cmpint(ix.within(e.c, e.q, 6., exclude, near), ==, PW85_SUCCESS);
    std::size_t m = 0;
    std::vector<std::size_t> ci(near.size() + 1);
    std::vector<int> cs2(D * near.size() + D);
    std::vector<double> cm(2 * near.size() + 2);
    g_assert_cmpint(pw85_2d_index_within(c, e.c, e.q, 6., exclude, near.size() + 1, ci.data(),
                                         cs2.data(), cm.data(), &m),
                    ==, PW85_SUCCESS);
    g_assert_cmpuint(m, ==, near.size());
    for (std::size_t a = 0; a < m; ++a) {
      g_assert_cmpuint(near[a].id, ==, ci[a]);
      g_assert_true(std::memcmp(near[a].shift.data(), &cs2[D * a], D * sizeof(int)) == 0);
      g_assert_true(near[a].mu2 == cm[2 * a] && near[a].lambda == cm[2 * a + 1]);
    }
  }
  std::vector<int> results(30, 7), status(30, 7);
  std::vector<std::size_t> found(30, 7);
  g_assert_cmpint(ix.overlap_any_batch(30, bc.data(), bq.data(), nullptr, results.data(),
                                       found.data(), status.data(), 2),
                  ==, PW85_SUCCESS);
  for (int k = 0; k < 30; ++k) {  // exclude = none: the same as alone when k % 3 ≠ 0
    g_assert_cmpint(status[k], ==, PW85_SUCCESS);
    if (k % 3) g_assert_true(results[k] == br[k] && found[k] == bi[k]);
  }
  double gc[D], gq[S], cc[D], cq[S];
  g_assert_cmpint(ix.get(ids[1], gc, gq), ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_2d_index_get(c, ids[1], cc, cq), ==, PW85_SUCCESS);
  g_assert_true(std::memcmp(gc, cc, sizeof gc) == 0 && std::memcmp(gq, cq, sizeof gq) == 0);
  pw85_2d_index_destroy(c);
  g_rand_free(rng);
}

double const unit_q[S] = {1., 0., 1.};
double const origin[D] = {0., 0.};

// An object that holds no index: PW85_EFAULT, nothing written.
void check_empty(Index &ix) {
  g_assert_false(static_cast<bool>(ix));
  g_assert_null(ix.handle());
  std::size_t n = 7, id = 7;
  int result = 7;
  double c[D] = {7., 7.}, q[S] = {7., 7., 7.};
  g_assert_cmpint(ix.count(n), ==, PW85_EFAULT);
  g_assert_cmpint(ix.insert(0, origin, unit_q), ==, PW85_EFAULT);
  g_assert_cmpint(ix.insert_many(1, &id, origin, unit_q, 2), ==, PW85_EFAULT);
  g_assert_cmpint(ix.update(0, origin, unit_q), ==, PW85_EFAULT);
  g_assert_cmpint(ix.remove(0), ==, PW85_EFAULT);
  g_assert_cmpint(ix.get(0, c, q), ==, PW85_EFAULT);
  g_assert_cmpint(ix.overlap_any(origin, unit_q, pw85::index_no_id, result, id), ==,
                  PW85_EFAULT);
  std::vector<Index::Neighbour> near(2);
  std::vector<Index::Pair> pairs(3);
  g_assert_cmpint(ix.within(origin, unit_q, 1., pw85::index_no_id, near), ==, PW85_EFAULT);
  g_assert_cmpint(ix.pairs_within(1., 1, pairs), ==, PW85_EFAULT);
  g_assert_true(n == 7 && id == 7 && result == 7 && c[0] == 7. && q[2] == 7.);
  g_assert_cmpuint(near.size(), ==, 2);
  g_assert_cmpuint(pairs.size(), ==, 3);
}

void test_moves_and_errors() {
  static_assert(!std::is_copy_constructible<Index>::value, "move-only");
  static_assert(std::is_nothrow_move_constructible<Index>::value, "");
  static_assert(std::is_nothrow_move_assignable<Index>::value, "");
  Index empty;
  check_empty(empty);
  Index a;
  g_assert_cmpint(Index::periodic(box, a), ==, PW85_SUCCESS);
  g_assert_cmpint(a.insert(2, origin, unit_q), ==, PW85_SUCCESS);
  pw85_2d_index *const handle = a.handle();
  Index b(std::move(a));
  check_empty(a);
  g_assert_true(b.handle() == handle);
  a = std::move(b);
  check_empty(b);
  g_assert_true(a.handle() == handle);

  // failed calls: statuses of the C functions, outputs unchanged
  double const bad_box[D] = {1., -1.};
  g_assert_cmpint(Index::periodic(nullptr, b), ==, PW85_EFAULT);
  g_assert_cmpint(Index::periodic(bad_box, b), ==, PW85_EINVAL);
  check_empty(b);
  double const nan_c[D] = {NAN, 0.};
  g_assert_cmpint(a.insert(3, nan_c, unit_q), ==, PW85_EDOM);
  g_assert_cmpint(a.insert(2, origin, unit_q), ==, PW85_EINVAL);  // in use
  double const wide[S] = {4.6 * 4.6, 0., 1.};  // 2·4.6 > L0 = 9
  g_assert_cmpint(a.insert(3, origin, wide), ==, PW85_EINVAL);
  std::vector<Index::Neighbour> near(5);
  g_assert_cmpint(a.within(origin, unit_q, -1., pw85::index_no_id, near), ==, PW85_EINVAL);
  g_assert_cmpuint(near.size(), ==, 5);
  std::vector<Index::OverlappingPair> overlaps(4);
  g_assert_cmpint(a.overlapping_pairs(0, overlaps), ==, PW85_EINVAL);
  g_assert_cmpuint(overlaps.size(), ==, 4);
  std::size_t n = 0;
  g_assert_cmpint(a.count(n), ==, PW85_SUCCESS);
  g_assert_cmpuint(n, ==, 1);
  g_assert_cmpint(Index::open(a), ==, PW85_SUCCESS);  // the old index destroyed
  g_assert_cmpint(a.count(n), ==, PW85_SUCCESS);
  g_assert_cmpuint(n, ==, 0);
}

}  // namespace

int main(int argc, char **argv) {
  g_test_init(&argc, &argv, nullptr);
  g_test_add_data_func("/pw85/2d-index-hpp/same/open", GINT_TO_POINTER(0), test_same);
  g_test_add_data_func("/pw85/2d-index-hpp/same/periodic", GINT_TO_POINTER(1), test_same);
  g_test_add_func("/pw85/2d-index-hpp/moves-and-errors", test_moves_and_errors);
  return g_test_run();
}
