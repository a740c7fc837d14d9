// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file pw85_index.hpp
 * @brief pw85::Index, the C++ owner of a pw85_index (pw85_index.h): the
 *        spatial index of ellipsoids, its queries returning std::vector.
 *
 * Header-only over the C ABI of pw85_index.h, whose description of each
 * function is the contract here (the domain, the image rule and the side
 * rule of a periodic box, the certification, the order of the results);
 * link the same -lpw85. Needs C++11, as pw85.hpp, which includes this
 * header: either one gives pw85::Index.
 *
 * Conventions of pw85.hpp: vectors `double[3]`, quadratic forms
 * `double[6]` (upper triangle, row by row); lengths in the caller's unit,
 * Q in that unit squared; every member returns the PW85_* status of the C
 * function it calls and none throws. A failed call leaves the index and
 * every output as they were (the vectors of the queries included).
 *
 * Memory. The queries return their results in a std::vector given by the
 * caller (resized to the number of results; its capacity is reused by the
 * next call). A vector that cannot grow is reported as PW85_ENOMEM, like
 * every allocation of the library, when exceptions are enabled; compiled
 * with -fno-exceptions, the C++ library's own rule applies (it aborts).
 *
 * Threads: those of pw85_index.h. Calls that modify an index (insert,
 * insert_many, update, remove, the assignments, destruction) need
 * exclusive access to it; the const members only read it and may run
 * concurrently from several threads (each with its own output vector).
 * Only overlapping_pairs() and pairs_within() start threads, and only as
 * many as asked.
 *
 * @since 2.2.0
 */
#ifndef PW85_INDEX_HPP
#define PW85_INDEX_HPP

#include <array>
#include <cstddef>
#include <type_traits>
#include <vector>

#include "pw85.hpp"
#include "pw85_index.h"

namespace pw85 {

/** The largest id of an ellipsoid (PW85_INDEX_MAX_ID, 2³² − 2).
 *  @since 2.2.0 */
constexpr std::size_t index_max_id = PW85_INDEX_MAX_ID;
/** No id (PW85_INDEX_NO_ID): the `exclude` of the queries on a candidate
 *  when nothing is to be skipped, and the id Index::overlap_any() gives
 *  when nothing overlaps.
 *  @since 2.2.0 */
constexpr std::size_t index_no_id = PW85_INDEX_NO_ID;

namespace index_detail {

/// @cond INTERNAL
using detail_vector::resize;  // pw85.hpp

// The table of the C functions of an index header, whose functions are
// PREFIX_create, PREFIX_destroy, PREFIX_count, ..., for BasicIndex: the
// struct NAME with the header's handle type and sizes (dim, sym) and a
// static member per function, forwarding its arguments (Api3 below;
// pw85_2d_index.hpp makes Api2).
#define PW85_INDEX_CXX_API(NAME, PREFIX, HANDLE, DIM, SYM)                    \
  struct NAME {                                                               \
    using handle = HANDLE;                                                    \
    static constexpr std::size_t dim = DIM;                                   \
    static constexpr std::size_t sym = SYM;                                   \
    static void destroy(HANDLE *h) noexcept { PREFIX##_destroy(h); }          \
    PW85_INDEX_CXX_CALL_(PREFIX, create)                                      \
    PW85_INDEX_CXX_CALL_(PREFIX, count)                                       \
    PW85_INDEX_CXX_CALL_(PREFIX, insert)                                      \
    PW85_INDEX_CXX_CALL_(PREFIX, insert_many)                                 \
    PW85_INDEX_CXX_CALL_(PREFIX, insert_many_threads)                         \
    PW85_INDEX_CXX_CALL_(PREFIX, update)                                      \
    PW85_INDEX_CXX_CALL_(PREFIX, remove)                                      \
    PW85_INDEX_CXX_CALL_(PREFIX, get)                                         \
    PW85_INDEX_CXX_CALL_(PREFIX, overlap_any)                                 \
    PW85_INDEX_CXX_CALL_(PREFIX, overlap_any_batch)                           \
    PW85_INDEX_CXX_CALL_(PREFIX, within)                                      \
    PW85_INDEX_CXX_CALL_(PREFIX, overlapping_pairs)                           \
    PW85_INDEX_CXX_CALL_(PREFIX, pairs_within)                                \
    PW85_INDEX_CXX_CALL_(PREFIX, energy)                                      \
  }
#define PW85_INDEX_CXX_CALL_(PREFIX, FN)                                      \
  template <typename... Args>                                                 \
  static int FN(Args... args) noexcept {                                      \
    return PREFIX##_##FN(args...);                                            \
  }

PW85_INDEX_CXX_API(Api3, pw85_index, pw85_index, PW85_DIM, PW85_SYM);
/// @endcond

/**
 * @brief What pw85::Index (ellipsoids, pw85_index.h) and pw85::d2::Index
 *        (ellipses, pw85_2d_index.h) share, written once: ownership, the
 *        storage calls and the queries (internal: use the two classes).
 *
 * Derived: the class itself; Api: the C functions of its header, with its
 * `handle` type and its sizes `dim` (coordinates of a centre, of an image
 * shift) and `sym` (stored entries of a quadratic form). Each member calls
 * the C function of the same name of that header, whose description is
 * its contract.
 */
template <class Derived, class Api>
class BasicIndex {
  using handle_type = typename Api::handle;  // the C handle of the index

 public:
  /** A result of within(): stored ellipsoid `id`, its image `shift` n
   *  (the image is at c_id + n∘L), μ² and λ of the contact function
   *  (pw85_contact_function(), pw85_2d_contact_function()) of the
   *  candidate and the stored shape, r from the candidate's centre to that
   *  image (λ weighs the stored shape's form). */
  struct Neighbour {
    std::size_t id;                   ///< the stored shape's id
    std::array<int, Api::dim> shift;  ///< its image shift n
    double mu2;                       ///< μ² (dimensionless)
    double lambda;                    ///< λ, in [0, 1]
  };

  /** A result of overlapping_pairs(): shapes i < j, the image shift n of
   *  j, and the overlap test (pw85_overlap(), pw85_2d_overlap()) of
   *  r = (c_j + n∘L) − c_i, q_i, q_j: −1 (overlap) or 0 (tangent to 4
   *  ulps). */
  struct OverlappingPair {
    std::size_t i;                    ///< the first id
    std::size_t j;                    ///< the second id, j > i
    std::array<int, Api::dim> shift;  ///< the image shift n of j
    int result;                       ///< −1 (overlap) or 0 (tangent)
  };

  /** A result of pairs_within(): shapes i ≤ j (i = j for a shape and one
   *  of its own images, n then lexicographically positive), the image
   *  shift n of j, μ² and λ of the contact function of
   *  r = (c_j + n∘L) − c_i, q_i, q_j. */
  struct Pair {
    std::size_t i;                    ///< the first id
    std::size_t j;                    ///< the second id, j ≥ i
    std::array<int, Api::dim> shift;  ///< the image shift n of j
    double mu2;                       ///< μ² (dimensionless)
    double lambda;                    ///< λ, in [0, 1]
  };

  /** Holds no index (see the class description). */
  BasicIndex() noexcept = default;

  /** Takes ownership of an index made by the header's create function
   *  (pw85_index_create(), pw85_2d_index_create()), or nullptr: destroyed
   *  with this object. */
  explicit BasicIndex(handle_type *owned) noexcept : handle_(owned) {}

  /** Destroys the index held, if any (pw85_index_destroy(),
   *  pw85_2d_index_destroy()). */
  ~BasicIndex() { Api::destroy(handle_); }

  /** Not copyable: an index has one owner. */
  BasicIndex(BasicIndex const &) = delete;
  /** Not copyable: an index has one owner. */
  BasicIndex &operator=(BasicIndex const &) = delete;

  /** Takes other's index; other then holds none. */
  BasicIndex(BasicIndex &&other) noexcept : handle_(other.handle_) {
    other.handle_ = nullptr;
  }

  /** Destroys the index held, then takes other's; other then holds none.
   *  Moving an index into itself changes nothing. */
  BasicIndex &operator=(BasicIndex &&other) noexcept {
    if (this != &other) {
      Api::destroy(handle_);
      handle_ = other.handle_;
      other.handle_ = nullptr;
    }
    return *this;
  }

  /**
   * @brief Creates an empty index for an open domain (an open plane in
   *        2D) into `out` (the create function with no box).
   * @param[out] out receives the new index; the index it held before is
   *             destroyed. Unchanged on error.
   * @return PW85_SUCCESS; PW85_ENOMEM.
   */
  static int open(Derived &out) noexcept { return create(nullptr, out); }

  /**
   * @brief Creates an empty index for a periodic box (a rectangle in 2D)
   *        into `out` (pw85_index_create(), pw85_2d_index_create()).
   * @param[in] box the sides L_k (`dim` lengths, > 0 and at most 2⁹⁹²).
   * @param[out] out as open().
   * @return PW85_SUCCESS; PW85_EFAULT if box is nullptr; PW85_EDOM if a
   *         side is not finite; PW85_EINVAL if a side is not > 0 or is
   *         above 2⁹⁹²; PW85_ENOMEM. `out` is unchanged on error.
   */
  static int periodic(double const box[Api::dim], Derived &out) noexcept {
    return box == nullptr ? PW85_EFAULT : create(box, out);
  }

  /** Does this libpw85 run the all-pairs queries on several threads
   *  (pw85_index_openmp())? */
  static bool openmp() noexcept { return pw85_index_openmp() != 0; }

  /** Does this object hold an index? */
  explicit operator bool() const noexcept { return handle_ != nullptr; }

  /** The index held (nullptr if none), still owned by this object: for
   *  the C functions of its header. */
  handle_type *handle() const noexcept { return handle_; }

  /**
   * @brief The number of shapes stored (pw85_index_count(),
   *        pw85_2d_index_count()).
   * @param[out] n that number (unchanged on error).
   * @return PW85_SUCCESS; PW85_EFAULT if no index is held.
   */
  int count(std::size_t &n) const noexcept { return Api::count(handle_, &n); }

  /**
   * @brief Inserts a shape, O(1) amortised (pw85_index_insert(),
   *        pw85_2d_index_insert()).
   * @param[in] id its id, not in use, at most index_max_id.
   * @param[in] centre its centre c.
   * @param[in] q its quadratic form Q.
   * @return PW85_SUCCESS; PW85_EFAULT if no index is held or a pointer is
   *         nullptr; PW85_EDOM if an entry is not finite; PW85_ENOTPOSDEF
   *         if q is not positive definite; PW85_EINVAL if id is in use or
   *         above index_max_id, or if |c_k| > 2¹⁰²¹ in an open domain,
   *         or, in a periodic box, if 2·√Q_kk·(1 + 2⁻²⁰) ≥ L_k or
   *         |c_k| > 2²⁹·L_k; PW85_ENOMEM.
   */
  int insert(std::size_t id, double const centre[Api::dim],
             double const q[Api::sym]) noexcept {
    return Api::insert(handle_, id, centre, q);
  }

  /**
   * @brief Inserts n shapes, all or none (pw85_index_insert_many(),
   *        pw85_2d_index_insert_many()).
   * @param[in] n their number (0 does nothing).
   * @param[in] ids n distinct ids, not in use.
   * @param[in] centres dim·n doubles, centre i at centres[dim·i].
   * @param[in] q sym·n doubles, form i at q[sym·i].
   * @return the statuses of insert(), the first error met in the order of
   *         the arrays; on error none is inserted.
   */
  int insert_many(std::size_t n, std::size_t const *ids, double const *centres,
                  double const *q) noexcept {
    return Api::insert_many(handle_, n, ids, centres, q);
  }

  /**
   * @brief insert_many() on `threads` threads, with the same result for
   *        any count (pw85_index_insert_many_threads(),
   *        pw85_2d_index_insert_many_threads()).
   * @param[in] n their number (0 does nothing).
   * @param[in] ids n distinct ids, not in use.
   * @param[in] centres dim·n doubles, centre i at centres[dim·i].
   * @param[in] q sym·n doubles, form i at q[sym·i].
   * @param[in] threads the number of threads (≥ 1).
   * @return the statuses of insert_many(); PW85_EINVAL also if
   *         threads < 1.
   * @since 2.3.0
   */
  int insert_many(std::size_t n, std::size_t const *ids, double const *centres,
                  double const *q, int threads) noexcept {
    return Api::insert_many_threads(handle_, n, ids, centres, q, threads);
  }

  /**
   * @brief Moves or reshapes a stored shape, O(1) amortised
   *        (pw85_index_update(), pw85_2d_index_update()).
   * @param[in] id the id of a stored shape.
   * @param[in] centre its new centre.
   * @param[in] q its new quadratic form.
   * @return the statuses of insert(); PW85_EINVAL if id is not stored.
   */
  int update(std::size_t id, double const centre[Api::dim],
             double const q[Api::sym]) noexcept {
    return Api::update(handle_, id, centre, q);
  }

  /**
   * @brief Removes a stored shape, O(1) (pw85_index_remove(),
   *        pw85_2d_index_remove()).
   * @param[in] id the id of a stored shape; it becomes free.
   * @return PW85_SUCCESS; PW85_EFAULT if no index is held; PW85_EINVAL if
   *         id is not stored.
   */
  int remove(std::size_t id) noexcept { return Api::remove(handle_, id); }

  /**
   * @brief The centre and form of a stored shape, as given
   *        (pw85_index_get(), pw85_2d_index_get()).
   * @param[in] id the id of a stored shape.
   * @param[out] centre its centre (not wrapped into the box).
   * @param[out] q its quadratic form.
   * @return PW85_SUCCESS; PW85_EFAULT if no index is held or a pointer is
   *         nullptr; PW85_EINVAL if id is not stored. The outputs are
   *         written on success only.
   */
  int get(std::size_t id, double centre[Api::dim],
          double q[Api::sym]) const noexcept {
    return Api::get(handle_, id, centre, q);
  }

  /**
   * @brief Does a candidate overlap a stored shape? Stops at the first
   *        overlap (pw85_index_overlap_any(), pw85_2d_index_overlap_any()).
   * @param[in] centre the candidate's centre (|c_k| ≤ 2¹⁰²¹ in an open
   *            domain, |c_k| ≤ 2²⁹·L_k in a periodic box).
   * @param[in] q the candidate's quadratic form.
   * @param[in] exclude the id of a stored shape to skip, or index_no_id.
   * @param[out] result −1 if some stored shape overlaps the candidate,
   *             else 0 if some is tangent to it (4 ulps), else +1.
   * @param[out] id a shape with that result, or index_no_id for +1.
   * @return PW85_SUCCESS; PW85_EFAULT if no index is held or a pointer is
   *         nullptr; PW85_EDOM, PW85_ENOTPOSDEF, PW85_EINVAL, PW85_ERANGE
   *         as the C function. The outputs are written on success only.
   */
  int overlap_any(double const centre[Api::dim], double const q[Api::sym],
                  std::size_t exclude, int &result,
                  std::size_t &id) const noexcept {
    return Api::overlap_any(handle_, centre, q, exclude, &result, &id);
  }

  /**
   * @brief overlap_any() for n candidates, on threads
   *        (pw85_index_overlap_any_batch(),
   *        pw85_2d_index_overlap_any_batch()).
   * @param[in] n the number of candidates.
   * @param[in] centres n centres, contiguous (dim·n doubles).
   * @param[in] q n quadratic forms, contiguous (sym·n doubles).
   * @param[in] exclude nullptr, or n ids to skip (one per candidate).
   * @param[out] results n results (−1, 0, +1).
   * @param[out] ids n ids, or index_no_id.
   * @param[out] status nullptr, or n statuses.
   * @param[in] threads 1, 0 (OpenMP's default) or up to k.
   * @return PW85_SUCCESS, or the status of the first failing candidate;
   *         PW85_EFAULT if no index is held, or as the C function.
   */
  int overlap_any_batch(std::size_t n, double const *centres,
                        double const *q, std::size_t const *exclude,
                        int *results, std::size_t *ids, int *status = nullptr,
                        int threads = 1) const noexcept {
    return Api::overlap_any_batch(handle_, n, centres, Api::dim, q, Api::sym,
                                  exclude, results, ids, status, threads);
  }

  /**
   * @brief Every stored shape and image with μ² < t from a candidate,
   *        sorted by id then shift (pw85_index_within(),
   *        pw85_2d_index_within()).
   * @param[in] centre the candidate's centre (as overlap_any()).
   * @param[in] q the candidate's quadratic form.
   * @param[in] t the threshold (dimensionless, > 0 and finite; 1 for
   *            overlaps, above 1 for near neighbours).
   * @param[in] exclude as overlap_any().
   * @param[out] out the results, resized to their number.
   * @return the statuses of overlap_any(); PW85_EDOM if t is not finite;
   *         PW85_EINVAL if t ≤ 0; PW85_ERANGE as the C function;
   *         PW85_ENOMEM if out or a scratch array cannot grow. `out` is
   *         unchanged on error.
   */
  int within(double const centre[Api::dim], double const q[Api::sym],
             double t, std::size_t exclude,
             std::vector<Neighbour> &out) const noexcept {
    Results<1> r;
    int const status = collect(
        [&](std::size_t cap, std::size_t *ids, int *shifts, double *values,
            std::size_t *n) {
          return Api::within(handle_, centre, q, t, exclude, cap, ids, shifts,
                             values, n);
        },
        out.capacity() > 16 ? out.capacity() : 16, r);
    if (status != PW85_SUCCESS) return status;
    return fill(r, out, [&](Neighbour &x, std::size_t k) {
      x.id = r.ids[k];
      x.mu2 = r.values[2 * k];
      x.lambda = r.values[2 * k + 1];
    });
  }

  /**
   * @brief Every overlapping (or tangent) pair, each once, sorted by i,
   *        j, then shift; the same for any thread count
   *        (pw85_index_overlapping_pairs(),
   *        pw85_2d_index_overlapping_pairs()).
   * @param[in] threads the number of threads (≥ 1; serial without
   *            OpenMP, see openmp()).
   * @param[out] out the pairs, resized to their number.
   * @return PW85_SUCCESS; PW85_EFAULT if no index is held; PW85_EINVAL if
   *         threads < 1; PW85_ERANGE as the overlap test on some pair;
   *         PW85_ENOMEM. `out` is unchanged on error.
   */
  int overlapping_pairs(int threads,
                        std::vector<OverlappingPair> &out) const noexcept {
    Results<2, int> r;
    int const status = collect(
        [&](std::size_t cap, std::size_t *ids, int *shifts, int *values,
            std::size_t *n) {
          return Api::overlapping_pairs(handle_, threads, cap, ids, shifts,
                                        values, n);
        },
        out.capacity() > 64 ? out.capacity() : 64, r);
    if (status != PW85_SUCCESS) return status;
    return fill(r, out, [&](OverlappingPair &x, std::size_t k) {
      x.i = r.ids[2 * k];
      x.j = r.ids[2 * k + 1];
      x.result = r.values[k];
    });
  }

  /**
   * @brief Every pair and image with μ² < t, each once, sorted by i, j,
   *        then shift; the same for any thread count
   *        (pw85_index_pairs_within(), pw85_2d_index_pairs_within()).
   * @param[in] t the threshold (> 0 and finite).
   * @param[in] threads the number of threads (≥ 1).
   * @param[out] out the pairs, resized to their number.
   * @return the statuses of overlapping_pairs(); PW85_EDOM if t is not
   *         finite; PW85_EINVAL if t ≤ 0; PW85_ERANGE also as within().
   *         `out` is unchanged on error.
   */
  int pairs_within(double t, int threads,
                   std::vector<Pair> &out) const noexcept {
    Results<2> r;
    int const status = collect(
        [&](std::size_t cap, std::size_t *ids, int *shifts, double *values,
            std::size_t *n) {
          return Api::pairs_within(handle_, t, threads, cap, ids, shifts,
                                   values, n);
        },
        out.capacity() > 64 ? out.capacity() : 64, r);
    if (status != PW85_SUCCESS) return status;
    return fill(r, out, [&](Pair &x, std::size_t k) {
      x.i = r.ids[2 * k];
      x.j = r.ids[2 * k + 1];
      x.mu2 = r.values[2 * k];
      x.lambda = r.values[2 * k + 1];
    });
  }

  /**
   * @brief The overlap energy ε·Σ(1 − μ)² over the pairs with μ < 1, the
   *        force and torque on every ellipsoid or ellipse
   *        (pw85_index_energy(), pw85_2d_index_energy(),
   *        PW85_ENERGY_OVERLAP).
   * @param[in] eps ε (> 0 and finite).
   * @param[in] threads the number of threads (≥ 1).
   * @param[in] n the rows of forces and torques: above every stored id.
   * @param[out] energy the total energy.
   * @param[out] forces resized to dim·n: the force on id k at
   *             dim·k..dim·k + dim − 1 (dim = 3 for ellipsoids, 2 for
   *             ellipses).
   * @param[out] torques resized to 3·n (ellipsoids: as forces) or n
   *             (ellipses: the torque on id k, ∂/∂θ, at k).
   * @return the statuses of pw85_index_energy() or
   *         pw85_2d_index_energy(); nothing is changed on error.
   * @since 2.4.0 (pw85::Index), 2.5.0 (pw85::d2::Index)
   */
  int overlap_energy(double eps, int threads, std::size_t n, double &energy,
                     std::vector<double> &forces,
                     std::vector<double> &torques) const noexcept {
    return energy_of(PW85_ENERGY_OVERLAP, eps, nullptr, nullptr, threads, n,
                     energy, forces, torques);
  }

  /**
   * @brief A caller's pair energy over the pairs with μ² < t, the force
   *        and torque on every ellipsoid or ellipse (pw85_index_energy(),
   *        pw85_2d_index_energy(), PW85_ENERGY_USER).
   * @param[in] t the threshold on μ² (> 0 and finite).
   * @param[in] u a callable `bool u(double mu2, double &U, double &dU)`
   *            setting U(μ²) and dU/dμ² and returning true to go on (false
   *            stops: PW85_ECANCELLED); called in the calling thread, in
   *            the order of the pairs. An exception it throws stops the
   *            call (PW85_ECANCELLED) and is not rethrown.
   * @param[in] threads, n, energy, forces, torques as overlap_energy().
   * @return the statuses of pw85_index_energy() or
   *         pw85_2d_index_energy(); nothing is changed on error.
   * @since 2.4.0 (pw85::Index), 2.5.0 (pw85::d2::Index)
   */
  template <typename U>
  int energy(double t, U &&u, int threads, std::size_t n, double &energy,
             std::vector<double> &forces,
             std::vector<double> &torques) const noexcept {
    // A function named as u is held by a pointer, whose address (an
    // object's) passes through void *; any other callable by reference.
    using F = typename std::remove_reference<U>::type;
    typename std::conditional<std::is_function<F>::value, F *, F &>::type
        held = u;
    using G = typename std::remove_reference<decltype(held)>::type;
    return energy_of(PW85_ENERGY_USER, t, &call_energy<G>,
                     const_cast<void *>(static_cast<void const *>(&held)),
                     threads, n, energy, forces, torques);
  }

 private:
  handle_type *handle_ = nullptr;

  template <typename F>
  static int call_energy(double mu2, void *data, double out[2]) noexcept {
    F &f = *static_cast<F *>(data);
#if defined(__cpp_exceptions) || defined(__EXCEPTIONS) || defined(_CPPUNWIND)
    try {
      return f(mu2, out[0], out[1]) ? 0 : 1;
    } catch (...) {
      return 1;
    }
#else
    return f(mu2, out[0], out[1]) ? 0 : 1;
#endif
  }

  int energy_of(int kind, double param, pw85_pair_energy fn, void *data,
                int threads, std::size_t n, double &energy,
                std::vector<double> &forces,
                std::vector<double> &torques) const noexcept {
    // (dim·n wraps around only where the C function returns
    // PW85_ENOMEM before it writes anything.) A moved-from index is
    // PW85_EFAULT, as the C function says, before any allocation.
    if (handle() == nullptr) return PW85_EFAULT;
    std::vector<double> f, t;
    int status = resize(f, Api::dim * n);
    if (status == PW85_SUCCESS) status = resize(t, (Api::dim == 3 ? 3 : 1) * n);
    double e = 0.0;
    if (status == PW85_SUCCESS)
      status = Api::energy(handle(), kind, param, fn, data, threads, n, &e,
                           f.data(), t.data());
    if (status != PW85_SUCCESS) return status;
    energy = e;
    forces.swap(f);
    torques.swap(t);
    return PW85_SUCCESS;
  }

  static int create(double const *box, Derived &out) noexcept {
    handle_type *created = nullptr;
    int const status = Api::create(box, &created);
    if (status == PW85_SUCCESS) out = Derived(created);
    return status;
  }

  // The arrays of the C queries: IDS ids, dim shifts and one result (int)
  // or two values (μ², λ) per result.
  template <std::size_t IDS, typename Value = double>
  struct Results {
    std::vector<std::size_t> ids;
    std::vector<int> shifts;
    std::vector<Value> values;
    std::size_t count = 0;
  };

  // The protocol of the C queries: call with room for `guess` results,
  // and once more with room for all of them if they did not fit.
  template <typename Call, std::size_t IDS, typename Value>
  static int collect(Call call, std::size_t guess,
                     Results<IDS, Value> &r) noexcept {
    std::size_t cap = guess;
    for (;;) {
      int status = resize(r.ids, IDS * cap);
      if (status == PW85_SUCCESS) status = resize(r.shifts, Api::dim * cap);
      if (status == PW85_SUCCESS)
        status =
            resize(r.values, (std::is_same<Value, int>::value ? 1 : 2) * cap);
      if (status == PW85_SUCCESS)
        status =
            call(cap, r.ids.data(), r.shifts.data(), r.values.data(), &r.count);
      if (status != PW85_SUCCESS || r.count <= cap) return status;
      cap = r.count;
    }
  }

  // out = the r.count results, each from set(x, k) and the shifts.
  template <typename T, std::size_t IDS, typename Value, typename Set>
  static int fill(Results<IDS, Value> const &r, std::vector<T> &out,
                  Set set) noexcept {
    int const status = resize(out, r.count);
    if (status != PW85_SUCCESS) return status;
    for (std::size_t k = 0; k < r.count; ++k) {
      for (std::size_t d = 0; d < Api::dim; ++d)
        out[k].shift[d] = r.shifts[Api::dim * k + d];
      set(out[k], k);
    }
    return PW85_SUCCESS;
  }
};

}  // namespace index_detail

/**
 * @brief A spatial index of ellipsoids (pw85_index.h), owned: created by
 *        open() or periodic(), destroyed with the object.
 *
 * Move-only. An Index that holds no index (default-constructed, moved
 * from, or whose creation failed) is valid: it can be destroyed, assigned
 * to, or created into again; it converts to false, handle() is nullptr,
 * and the members that query or modify an index return PW85_EFAULT (the
 * status of the C functions given a NULL index) and change nothing.
 * @since 2.2.0
 */
class Index : public index_detail::BasicIndex<Index, index_detail::Api3> {
 public:
  using BasicIndex::BasicIndex;
};

}  // namespace pw85

#endif  // PW85_INDEX_HPP
