// SPDX-License-Identifier: BSD-3-Clause
// The certified packer (pack.hpp; docs/packing.rst), written once for
// ellipsoids (D = 3, pw85_pack()) and ellipses (D = 2, pw85_2d_pack());
// what differs, the orientations (a unit quaternion or an angle), their
// turning, the forms and the volume of a shape, is the struct
// Orientation<D>. "Ellipsoid", "volume" and "box" read "ellipse", "area"
// and "rectangle" in 2D.
//
// 1. Random placement in the box of the target (counter-based random
//    numbers per ellipsoid: splitmix64, Steele, Lea and Flood, OOPSLA
//    2014), isotropic orientations by Shoemake's uniform quaternions
//    (Graphics Gems III, 1992), in 2D uniform angles, or aligned.
// 2. FIRE (Bitzek et al., PRL 97, 170201, 2006; the semi-implicit Euler
//    form and half-step correction of Guénolé et al., Comput. Mater. Sci.
//    175, 109584, 2020) on the overlap energy Σ(1 − μ)² of the shapes
//    inflated by 1 + 2⁻¹⁰ (index/energy.hpp), over centres and rotations,
//    in mass-weighted coordinates (mass m = (ℓ/c)², c the ellipsoid's
//    smallest semi-axis, ℓ the smallest of all, so that the stiffness of
//    its contacts, of order 1/c², gives every ellipsoid about the same
//    frequency against time steps in units of ℓ; inertia m·a², a its
//    largest; a move at most max_move·c), until the energy is exactly 0:
//    the jamming protocol of O'Hern, Silbert, Liu and Nagel (PRE 68,
//    011306, 2003). (With m = (c/ℓ)² and moves of max_move·ℓ, a sphere
//    100 times the smallest moved by 1e-8 of its size per step: sizes
//    30 : 1 and beyond stalled far below jamming.)
// 3. Where the energy stalls above 0, the configuration grown to contact
//    is certified (a lower bound of the jamming fraction), and the box
//    grows to the midpoint: bisection between the densest certified and
//    the least jammed fraction.
// 4. A configuration of zero energy is certified by the all-pairs overlap
//    query on the real shapes (never trusted from the inflation alone);
//    any configuration is certified by scaling box and centres by
//    (1 + 2⁻²⁰)/min μ (μ(s·r) = s·μ(r): the smallest μ is the largest
//    uniform growth that keeps every pair apart), checked the same way.
#include "pack/pack.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <new>

#include "compiler.hpp"
#include "ellipsoid.hpp"
#include "index/buffer.hpp"
#include "index/energy.hpp"
#include "index/index.hpp"

namespace pw85::detail {

namespace {

constexpr double pi = 3.14159265358979323846;
// The inflation of the shapes whose energy is minimised.
constexpr double inflation = 1.0 + 0x1p-10;
// FIRE's parameters (Bitzek et al.): N_delay, f_inc, f_dec, α_start, f_α;
// the time steps in units of ℓ (the smallest semi-axis; the smallest
// ellipsoids of mass 1 and stiffness of order 1/ℓ²) and the largest move
// per step, in units of each ellipsoid's smallest semi-axis.
constexpr int fire_delay = 5;
constexpr double fire_inc = 1.1, fire_dec = 0.5, fire_alpha0 = 0.1,
                 fire_falpha = 0.99;
constexpr double dt_start = 0.1, dt_max = 1.0, dt_min = 1e-3;
constexpr double max_move = 0.1;
// The energy stalls when it fell by less than stall_drop (a factor of 2)
// over a window of stall_window steps: below jamming it falls by orders
// of magnitude in a hundred steps (10⁴ spheres at 0.60: U/N from 2e-4 to
// 3e-10 in 200 steps), above it creeps (10⁴ of 1 : 0.8 : 0.6 at 0.74: by
// 10% per 500 steps); a stall declared near jamming costs a
// decompression of at most `backoff`. Bisection stops when the bracket is
// below bisect_tol relative. With sizes far apart the window is longer:
// a small ellipsoid moves by at most max_move times its own size per step,
// and may have to cross a large one (c_max/ℓ of its sizes); the window is
// then window_per_size·c_max/ℓ steps (c_max the largest of the smallest
// semi-axes), up to max_window. (20 unit spheres and 180 of 0.01 at 0.3:
// jammed near 0.24 with 500 steps, the target with 5000.)
constexpr std::size_t stall_window = 500;
constexpr double window_per_size = 50.0;
constexpr std::size_t max_window = 5000;
constexpr double stall_drop = 0.5;
constexpr double bisect_tol = 1e-3;
// The largest decompression after a stall.
constexpr double backoff = 0.98;

std::uint64_t splitmix64(std::uint64_t x) noexcept {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// Draw k of item i: uniform in [0, 1), a function of (seed, i, k) alone.
double uniform(std::uint64_t seed, std::uint64_t i, std::uint64_t k) noexcept {
  std::uint64_t const h = splitmix64(seed ^ splitmix64(i * 8 + k));
  return double(h >> 11) * 0x1p-53;
}

// r = a·b (Hamilton product; (w, x, y, z)).
void qmul(double const a[4], double const b[4], double r[4]) noexcept {
  r[0] = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
  r[1] = a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2];
  r[2] = a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1];
  r[3] = a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0];
}

void qnormalise(double p[4]) noexcept {
  double const s = 1.0 / std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2] +
                                   p[3] * p[3]);
  for (int k = 0; k < 4; ++k) p[k] *= s;
}

// The rotation by angle |w| about w (lab frame), applied to p.
void rotate(double const w[dim], double p[4]) noexcept {
  double const t = std::sqrt(dot(w, w));
  if (!(t > 0.0)) return;
  double const s = std::sin(0.5 * t) / t;
  double const r[4] = {std::cos(0.5 * t), s * w[0], s * w[1], s * w[2]};
  double out[4];
  qmul(r, p, out);
  qnormalise(out);
  std::memcpy(p, out, sizeof out);
}

// Shoemake's uniform random rotation from three uniforms.
void isotropic(double u1, double u2, double u3, double p[4]) noexcept {
  double const a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
  p[0] = a * std::sin(2 * pi * u2);
  p[1] = a * std::cos(2 * pi * u2);
  p[2] = b * std::sin(2 * pi * u3);
  p[3] = b * std::cos(2 * pi * u3);
  qnormalise(p);
}

// A rotation taking e_m to the unit vector `axis`, then turning by angle
// about it.
void aligned_rotation(int m, double const axis[dim], double angle,
                      double p[4]) noexcept {
  double e[dim] = {0, 0, 0};
  e[m] = 1.0;
  double const d = dot(e, axis);
  double q1[4];
  if (d < -1.0 + 1e-12) {  // half a turn about an axis normal to e_m
    q1[0] = 0.0;
    q1[1] = q1[2] = q1[3] = 0.0;
    q1[1 + (m + 1) % 3] = 1.0;
  } else {  // the shortest arc: (1 + d, e × axis), normalised
    q1[0] = 1.0 + d;
    q1[1] = e[1] * axis[2] - e[2] * axis[1];
    q1[2] = e[2] * axis[0] - e[0] * axis[2];
    q1[3] = e[0] * axis[1] - e[1] * axis[0];
    qnormalise(q1);
  }
  double const s = std::sin(0.5 * angle);
  double const q2[4] = {std::cos(0.5 * angle), s * axis[0], s * axis[1],
                        s * axis[2]};
  qmul(q2, q1, p);
  qnormalise(p);
}

// What differs between the dimensions: an orientation (a unit quaternion
// (w, x, y, z) in 3D, pw85_ellipsoid_quaternion(); an angle θ in 2D,
// pw85_2d_ellipse()), its turning by a rotation vector (3D) or an angle
// (2D), the form of semi-axes and an orientation, the random and aligned
// orientations, and the volume (area) of a shape.
template <int D>
struct Orientation;

template <>
struct Orientation<3> {
  static constexpr int size = 4;  // doubles of an orientation
  static constexpr int rot = 3;   // doubles of a rotation (a torque)
  // 4π/3·a0·a1·a2
  static double measure(double product) noexcept {
    return 4.0 / 3.0 * pi * product;
  }
  // The side of a cube of volume v.
  static double side(double v) noexcept { return std::cbrt(v); }
  static Status form(double const *a, double const *p, double *q) noexcept {
    return ellipsoid_quaternion(a, p, q);
  }
  static void turn(double const *w, double *p) noexcept { rotate(w, p); }
  // Draws 3, 4, 5 of ellipsoid i; m: its largest semi-axis.
  static void place(std::uint64_t seed, std::uint64_t i, bool aligned,
                    int m, double const *axis, double *p) noexcept {
    double const u1 = uniform(seed, i, 3), u2 = uniform(seed, i, 4),
                 u3 = uniform(seed, i, 5);
    if (aligned)
      aligned_rotation(m, axis, 2 * pi * u1, p);
    else
      isotropic(u1, u2, u3, p);
  }
  // Aligned: only the turning about the axis.
  static void constrain(double const *axis, double *t) noexcept {
    double const along = dot(t, axis);
    for (int k = 0; k < 3; ++k) t[k] = along * axis[k];
  }
};

template <>
struct Orientation<2> {
  static constexpr int size = 1;
  static constexpr int rot = 1;
  static double measure(double product) noexcept { return pi * product; }
  // The side of a square of area v.
  static double side(double v) noexcept { return std::sqrt(v); }
  static Status form(double const *a, double const *p, double *q) noexcept {
    return ellipse_angle(a, p[0], q);
  }
  // θ + w, kept in [−π, π]: one turn of 2π takes back a move (capped,
  // below 2π); FIRE's half step back is not capped, so a larger w is
  // reduced by std::remainder (never reached in the tests and benchmarks;
  // elsewhere the angles are bit for bit those of one correction).
  static void turn(double const *w, double *p) noexcept {
    double t = p[0] + w[0];
    if (t > pi) t -= 2 * pi;
    if (t < -pi) t += 2 * pi;
    if (PW85_UNLIKELY(!(t >= -pi && t <= pi)) && std::isfinite(t))
      t = std::remainder(t, 2 * pi);
    p[0] = t;
  }
  // Draw 3 of ellipse i, uniform in [−π, π); aligned: the semi-axis m
  // along the axis (a[0] lies along θ, a[1] along θ + π/2).
  static void place(std::uint64_t seed, std::uint64_t i, bool aligned,
                    int m, double const *axis, double *p) noexcept {
    if (aligned) {
      p[0] = std::atan2(axis[1], axis[0]) - (m == 1 ? 0.5 * pi : 0.0);
      if (p[0] < -pi) p[0] += 2 * pi;  // (exact: Sterbenz)
    } else {
      p[0] = 2 * pi * uniform(seed, i, 3) - pi;
    }
  }
  // Aligned: no turning at all.
  static void constrain(double const *, double *t) noexcept { t[0] = 0.0; }
};

// x·x of a rotation (R = 1 or 3) or a vector.
template <int N>
double norm2(double const *x) noexcept {
  if constexpr (N == 1)
    return x[0] * x[0];
  else
    return dot<N>(x, x);
}

// Σ_k (x_k + y_k) added to s in the order of k, x of D terms, y of R: the
// sums of FIRE over a move (D) and a turn (R), in 3D the order in which
// they were first written (x_k + y_k formed, then added).
template <int D, int R, typename X, typename Y>
double paired_sum(double s, X const &x, Y const &y) noexcept {
  constexpr int m = D > R ? D : R;
  for (int k = 0; k < m; ++k) {
    if (k < D && k < R)
      s += x(k) + y(k);
    else if (k < D)
      s += x(k);
    else
      s += y(k);
  }
  return s;
}

template <int D>
double volume_of(std::size_t n, double const *a) noexcept {
  double v = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    double product = a[D * i];
    for (int k = 1; k < D; ++k) product *= a[D * i + k];
    v += product;
  }
  return Orientation<D>::measure(v);
}

// x wrapped into [0, L).
double wrap(double x, double side) noexcept {
  double y = x - std::floor(x / side) * side;
  if (!(y < side)) y = 0.0;
  if (y < 0.0) y = 0.0;
  return y;
}

// L0·L1(·L2).
template <int D>
double box_measure(double const *box) noexcept {
  double v = box[0];
  for (int k = 1; k < D; ++k) v *= box[k];
  return v;
}

// A configuration: box, centres, orientations, real forms.
template <int D>
struct Config {
  double box[D] = {};
  Buffer<double> c, p, q;
  double phi = 0.0;
  bool set = false;
};

using Clock = std::chrono::steady_clock;

template <int D>
class Packer {
 public:
  // Doubles per ellipsoid: orientation, rotation (torque), form, FIRE
  // velocity (a move and a turn).
  static constexpr int O = Orientation<D>::size, R = Orientation<D>::rot,
                       S = sym_size(D), V = D + R;

  Packer(std::size_t n, double const *a, PackParams const &params) noexcept
      : n_(n), a_(a), prm_(params), start_(Clock::now()) {}

  Status run(double *box, double *c, double *p, double *q, double *phi,
             PackOutcome *outcome) noexcept;

 private:
  Status init() noexcept;
  Status reindex() noexcept;
  Status forms_of(double const *p, double scale, double *q) noexcept;
  Status step(bool *zero) noexcept;
  Status certify_current(Config<D> *out, bool expand) noexcept;
  Status check(Config<D> const &cf, bool *ok) noexcept;
  void rescale(double phi) noexcept;
  double elapsed() const noexcept {
    return std::chrono::duration<double>(Clock::now() - start_).count();
  }
  bool out_of_time() const noexcept {
    return (prm_.time_limit > 0.0 && elapsed() > prm_.time_limit) ||
           (prm_.step_limit > 0 && steps_ >= prm_.step_limit);
  }
  void reset_fire() noexcept {
    for (std::size_t k = 0; k < u_.size(); ++k) u_[k] = 0.0;
    dt_ = dt_start * ell_;
    alpha_ = fire_alpha0;
    npos_ = 0;
  }

  std::size_t n_;
  double const *a_;
  PackParams const &prm_;
  Clock::time_point start_;
  double volume_ = 0.0, ell_ = 0.0;
  std::size_t window_ = stall_window;
  double box_[D] = {};
  double phi_ = 0.0;
  Buffer<double> c_, p_, qi_;   // centres, orientations, inflated forms
  Buffer<double> ai_;           // inflated semi-axes
  Buffer<double> m_, inertia_;  // FIRE masses
  Buffer<double> u_;            // mass-weighted velocities (V per ellipsoid)
  Buffer<double> f_, t_;        // forces, torques
  spatial::Index<D> *index_ = nullptr;
  double dt_ = 0.0, alpha_ = fire_alpha0;
  int npos_ = 0;
  std::size_t steps_ = 0, pairs_ = 0;
  double energy_ = 0.0;
  Config<D> best_;
};

template <int D>
Status Packer<D>::forms_of(double const *p, double scale, double *q) noexcept {
  for (std::size_t i = 0; i < n_; ++i) {
    double a[D];
    for (int k = 0; k < D; ++k)
      a[k] = scale == 1.0 ? a_[D * i + k] : ai_[D * i + k];
    Status const s = Orientation<D>::form(a, p + O * i, q + S * i);
    if (s != Status::success) return s;
  }
  return Status::success;
}

template <int D>
Status Packer<D>::init() noexcept {
  volume_ = volume_of<D>(n_, a_);
  ell_ = HUGE_VAL;
  for (std::size_t k = 0; k < D * n_; ++k) ell_ = std::min(ell_, a_[k]);
  if (!c_.resize(D * n_) || !p_.resize(O * n_) || !qi_.resize(S * n_) ||
      !ai_.resize(D * n_) || !m_.resize(n_) || !inertia_.resize(n_) ||
      !u_.resize(V * n_) || !f_.resize(D * n_) || !t_.resize(R * n_))
    return Status::no_memory;
  phi_ = prm_.target;
  pack_box<D>(n_, a_, prm_.aspect, phi_, box_);
  for (std::size_t i = 0; i < n_; ++i) {
    double const *a = a_ + D * i;
    double amin = a[0], amax = a[0];
    int m = 0;  // the largest semi-axis (the first of equals)
    for (int k = 1; k < D; ++k) {
      amin = std::min(amin, a[k]);
      amax = std::max(amax, a[k]);
      if (a[k] > a[m]) m = k;
    }
    m_[i] = (ell_ / amin) * (ell_ / amin);
    double const w = window_per_size * (amin / ell_);
    if (w > double(window_))
      window_ = w < double(max_window) ? std::size_t(w) : max_window;
    inertia_[i] = m_[i] * amax * amax;
    for (int k = 0; k < D; ++k) {
      ai_[D * i + k] = a[k] * inflation;
      c_[D * i + k] = uniform(prm_.seed, i, std::uint64_t(k)) * box_[k];
    }
    Orientation<D>::place(prm_.seed, i, prm_.aligned, m, prm_.axis,
                          p_.data() + O * i);
  }
  reset_fire();
  return reindex();
}

// A new index of the inflated shapes in the current box.
template <int D>
Status Packer<D>::reindex() noexcept {
  delete index_;
  index_ = new (std::nothrow) spatial::Index<D>(box_);
  if (index_ == nullptr) return Status::no_memory;
  Status s = forms_of(p_.data(), inflation, qi_.data());
  if (s != Status::success) return s;
  Buffer<std::size_t> ids;
  if (!ids.resize_uninitialised(n_)) return Status::no_memory;
  for (std::size_t i = 0; i < n_; ++i) ids[i] = i;
  return index_->insert_many(n_, ids.data(), c_.data(), qi_.data());
}

// The box and centres scaled to packing fraction phi (affine).
template <int D>
void Packer<D>::rescale(double phi) noexcept {
  double nb[D];
  pack_box<D>(n_, a_, prm_.aspect, phi, nb);
  for (std::size_t i = 0; i < n_; ++i)
    for (int k = 0; k < D; ++k)
      c_[D * i + k] = wrap(c_[D * i + k] * (nb[k] / box_[k]), nb[k]);
  std::memcpy(box_, nb, sizeof nb);
  phi_ = phi;
}

// One FIRE step: forces at the current configuration, then the move.
// *zero: the energy is small enough to certify (no move made).
template <int D>
Status Packer<D>::step(bool *zero) noexcept {
  EnergySpec const spec{EnergyKind::overlap, 1.0, nullptr, nullptr};
  Status s = assembly_energy(*index_, spec, prm_.threads, n_, &energy_,
                             f_.data(), t_.data(), &pairs_);
  if (s != Status::success) return s;
  // Every inflated pair has 1 − μ ≤ √U, and μ of the real shapes is
  // (1 + δ) times that of the inflated ones (δ = inflation − 1): below
  // √U < δ/2 no real pair overlaps (certified by the caller).
  *zero = std::sqrt(energy_) < 0.5 * (inflation - 1.0);
  if (*zero) return Status::success;
  ++steps_;
  // Generalised forces G (mass-weighted), power P = Σ u·G.
  double power = 0.0, gnorm = 0.0, unorm = 0.0;
  for (std::size_t i = 0; i < n_; ++i) {
    double *fi = f_.data() + D * i, *tq = t_.data() + R * i;
    double const *ui = u_.data() + V * i;
    if (prm_.aligned) Orientation<D>::constrain(prm_.axis, tq);
    double const sm = 1.0 / std::sqrt(m_[i]), si = 1.0 / std::sqrt(inertia_[i]);
    for (int k = 0; k < D; ++k) fi[k] *= sm;
    for (int k = 0; k < R; ++k) tq[k] *= si;
    power = paired_sum<D, R>(
        power, [&](int k) { return ui[k] * fi[k]; },
        [&](int k) { return ui[D + k] * tq[k]; });
  }
  if (power > 0.0) {
    if (++npos_ > fire_delay) {
      dt_ = std::min(dt_ * fire_inc, dt_max * ell_);
      alpha_ *= fire_falpha;
    }
  } else {
    npos_ = 0;
    dt_ = std::max(dt_ * fire_dec, dt_min * ell_);
    alpha_ = fire_alpha0;
    // Half a step back (Guénolé et al.), then at rest.
    for (std::size_t i = 0; i < n_; ++i) {
      double const sm = 1.0 / std::sqrt(m_[i]),
                   si = 1.0 / std::sqrt(inertia_[i]);
      double w[R];
      for (int k = 0; k < D; ++k)
        c_[D * i + k] -= 0.5 * dt_ * u_[V * i + k] * sm;
      for (int k = 0; k < R; ++k) w[k] = -0.5 * dt_ * u_[V * i + D + k] * si;
      Orientation<D>::turn(w, p_.data() + O * i);
    }
    for (std::size_t k = 0; k < u_.size(); ++k) u_[k] = 0.0;
  }
  // Semi-implicit Euler, then FIRE's mixing.
  for (std::size_t i = 0; i < n_; ++i) {
    for (int k = 0; k < D; ++k) u_[V * i + k] += dt_ * f_[D * i + k];
    for (int k = 0; k < R; ++k) u_[V * i + D + k] += dt_ * t_[R * i + k];
  }
  for (std::size_t i = 0; i < n_; ++i) {
    double const *ui = u_.data() + V * i, *fi = f_.data() + D * i,
                 *tq = t_.data() + R * i;
    unorm = paired_sum<D, R>(
        unorm, [&](int k) { return ui[k] * ui[k]; },
        [&](int k) { return ui[D + k] * ui[D + k]; });
    gnorm = paired_sum<D, R>(
        gnorm, [&](int k) { return fi[k] * fi[k]; },
        [&](int k) { return tq[k] * tq[k]; });
  }
  double const mix = gnorm > 0.0 ? alpha_ * std::sqrt(unorm / gnorm) : 0.0;
  for (std::size_t i = 0; i < n_; ++i) {
    for (int k = 0; k < D; ++k)
      u_[V * i + k] = (1.0 - alpha_) * u_[V * i + k] + mix * f_[D * i + k];
    for (int k = 0; k < R; ++k)
      u_[V * i + D + k] =
          (1.0 - alpha_) * u_[V * i + D + k] + mix * t_[R * i + k];
  }
  // The move, at most max_move·c (and as much at the largest semi-axis's
  // tip for rotations) per ellipsoid, c its smallest semi-axis.
  for (std::size_t i = 0; i < n_; ++i) {
    double const sm = 1.0 / std::sqrt(m_[i]), si = 1.0 / std::sqrt(inertia_[i]);
    double dx[D], w[R];
    for (int k = 0; k < D; ++k) dx[k] = dt_ * u_[V * i + k] * sm;
    for (int k = 0; k < R; ++k) w[k] = dt_ * u_[V * i + D + k] * si;
    double const step_len = std::sqrt(norm2<D>(dx));
    double const cap = max_move * ell_ / std::sqrt(m_[i]);  // max_move·amin
    if (step_len > cap)
      for (int k = 0; k < D; ++k) dx[k] *= cap / step_len;
    double const amax = std::sqrt(inertia_[i] / m_[i]);
    double const turn = std::sqrt(norm2<R>(w)) * amax;
    if (turn > cap)
      for (int k = 0; k < R; ++k) w[k] *= cap / turn;
    for (int k = 0; k < D; ++k)
      c_[D * i + k] = wrap(c_[D * i + k] + dx[k], box_[k]);
    Orientation<D>::turn(w, p_.data() + O * i);
    s = Orientation<D>::form(ai_.data() + D * i, p_.data() + O * i,
                             qi_.data() + S * i);
    if (s != Status::success) return s;
    s = index_->update(i, c_.data() + D * i, qi_.data() + S * i);
    if (s != Status::success) return s;
  }
  return Status::success;
}

// Does the configuration have no overlapping pair (the all-pairs query of
// a new index of its real shapes)?
template <int D>
Status Packer<D>::check(Config<D> const &cf, bool *ok) noexcept {
  spatial::Index<D> idx(cf.box);
  Buffer<std::size_t> ids;
  if (!ids.resize_uninitialised(n_)) return Status::no_memory;
  for (std::size_t i = 0; i < n_; ++i) ids[i] = i;
  Status s = idx.insert_many(n_, ids.data(), cf.c.data(), cf.q.data());
  if (s != Status::success) return s;
  Buffer<spatial::OverlapPair<D>> hits;
  s = idx.overlapping_pairs(prm_.threads, &hits, nullptr);
  if (s != Status::success) return s;
  *ok = hits.empty();
  return Status::success;
}

// The current configuration, certified: as it is (expand false; *out
// left unset if a pair overlaps), or with box and centres scaled by
// (1 + 2⁻²⁰)/min μ (expand true).
template <int D>
Status Packer<D>::certify_current(Config<D> *out, bool expand) noexcept {
  Config<D> cf;
  if (!cf.c.resize(D * n_) || !cf.p.resize(O * n_) || !cf.q.resize(S * n_))
    return Status::no_memory;
  std::memcpy(cf.p.data(), p_.data(), O * n_ * sizeof(double));
  Status s = forms_of(cf.p.data(), 1.0, cf.q.data());
  if (s != Status::success) return s;
  double scale = 1.0;
  if (expand) {
    spatial::Index<D> idx(box_);
    Buffer<std::size_t> ids;
    if (!ids.resize_uninitialised(n_)) return Status::no_memory;
    for (std::size_t i = 0; i < n_; ++i) ids[i] = i;
    s = idx.insert_many(n_, ids.data(), c_.data(), cf.q.data());
    if (s != Status::success) return s;
    Buffer<spatial::PairHit<D>> hits;
    s = idx.pairs(true, 1.0, prm_.threads, &hits, nullptr);
    if (s != Status::success) return s;
    double mu2 = 1.0;
    for (std::size_t k = 0; k < hits.size(); ++k) mu2 = std::min(mu2, hits[k].mu2);
    if (!(mu2 > 0x1p-60)) return Status::success;  // coincident centres
    scale = (1.0 + 0x1p-20) / std::sqrt(mu2);
  }
  for (int attempt = 0; attempt < 8; ++attempt) {
    for (int k = 0; k < D; ++k) cf.box[k] = box_[k] * scale;
    for (std::size_t i = 0; i < n_; ++i)
      for (int k = 0; k < D; ++k)
        cf.c[D * i + k] = wrap(c_[D * i + k] * scale, cf.box[k]);
    bool ok = false;
    s = check(cf, &ok);
    if (s != Status::success) return s;
    if (ok) {
      cf.phi = volume_ / box_measure<D>(cf.box);
      cf.set = true;
      *out = static_cast<Config<D> &&>(cf);
      return Status::success;
    }
    if (!expand) return Status::success;
    scale *= 1.0 + 0x1p-16;
  }
  return Status::success;
}

template <int D>
Status Packer<D>::run(double *box, double *c, double *p, double *q,
                      double *phi, PackOutcome *outcome) noexcept {
  Status s = init();
  PackOutcome result = PackOutcome::limit;
  double phi_lo = 0.0, phi_hi = HUGE_VAL;
  double window_energy = HUGE_VAL;
  std::size_t window_start = 0;
  if (s == Status::success) s = certify_current(&best_, true);
  while (s == Status::success) {
    if (out_of_time()) {
      result = PackOutcome::limit;
      break;
    }
    bool zero = false;
    s = step(&zero);
    if (s != Status::success) break;
    if (prm_.callback != nullptr && steps_ % prm_.progress_every == 0 &&
        !zero) {
      PackProgress const pr{best_.phi, phi_, energy_ / double(n_), elapsed(),
                            steps_, pairs_};
      if (prm_.callback(&pr, prm_.data) != 0) {
        result = PackOutcome::cancelled;
        break;
      }
    }
    bool stalled = false;
    if (!zero && window_energy == HUGE_VAL) {  // the phase's first step
      window_energy = energy_;
      window_start = steps_;
    }
    if (!zero && steps_ - window_start >= window_) {
      stalled = energy_ > (1.0 - stall_drop) * window_energy;
      window_energy = energy_;
      window_start = steps_;
    }
    if (!zero && !stalled) continue;
    double next;
    Config<D> cf;
    if (zero) {
      s = certify_current(&cf, false);
      if (s != Status::success) break;
      // (Not expected unset: the inflation keeps a margin; taken as a
      // stall if it happens.)
      zero = cf.set;
    }
    if (zero) {
      if (cf.phi > best_.phi) best_ = static_cast<Config<D> &&>(cf);
      phi_lo = phi_;
      if (phi_ >= prm_.target) {
        result = PackOutcome::target;
        break;
      }
      next = std::min(prm_.target, 0.5 * (phi_lo + phi_hi));
    } else {
      // Stalled: the configuration grown to contact is certified, and a
      // lower bound of the jamming fraction of the run; bisect above it.
      phi_hi = phi_;
      s = certify_current(&cf, true);
      if (s != Status::success) break;
      if (cf.set) phi_lo = std::max(phi_lo, cf.phi);
      if (cf.set && cf.phi > best_.phi) best_ = static_cast<Config<D> &&>(cf);
      // (at most `backoff` at a time: the grown configuration may be far
      // below, held apart by a few deep overlaps)
      next = std::max(0.5 * (phi_lo + phi_hi), phi_hi * backoff);
    }
    if (phi_lo > 0.0 && phi_hi - phi_lo <= bisect_tol * phi_hi) {
      result = PackOutcome::jammed;
      break;
    }
    rescale(next);
    reset_fire();
    window_energy = HUGE_VAL;
    window_start = steps_;
    s = reindex();
  }
  if (s == Status::success && result != PackOutcome::target) {
    // The current configuration, grown to contact, may beat the best.
    Config<D> cf;
    s = certify_current(&cf, true);
    if (s == Status::success && cf.set && cf.phi > best_.phi)
      best_ = static_cast<Config<D> &&>(cf);
  }
  delete index_;
  index_ = nullptr;
  if (s != Status::success) return s;
  if (!best_.set) return Status::out_of_range;  // coincident centres
  // The outputs, checked once more as they are written.
  bool ok = false;
  s = check(best_, &ok);
  if (s != Status::success) return s;
  if (!ok) return Status::out_of_range;  // not reached: checked when kept
  // The index's bound on sides (pw85_pack.h). The box at the target is
  // far below it (side_rule() in pw85_pack.cpp), but the growth of a
  // configuration to contact has no bound of its own.
  for (int k = 0; k < D; ++k)
    if (!(best_.box[k] <= prm_.side_limit)) return Status::out_of_range;
  std::memcpy(box, best_.box, sizeof best_.box);
  std::memcpy(c, best_.c.data(), D * n_ * sizeof(double));
  if (p != nullptr) std::memcpy(p, best_.p.data(), O * n_ * sizeof(double));
  std::memcpy(q, best_.q.data(), S * n_ * sizeof(double));
  *phi = best_.phi;
  *outcome = result;
  return Status::success;
}

}  // namespace

template <int D>
bool pack_box(std::size_t n, double const *a, double const *aspect,
              double phi, double *box) noexcept {
  double const v = volume_of<D>(n, a);
  double shape = phi;
  for (int k = 0; k < D; ++k) shape *= aspect[k];
  double const s = Orientation<D>::side(v / shape);
  if (!std::isfinite(s) || !(s > 0.0)) return false;
  for (int k = 0; k < D; ++k) box[k] = aspect[k] * s;
  return true;
}

template <int D>
Status pack(std::size_t n, double const *a, PackParams const &params,
            double *box, double *c, double *p, double *q, double *phi,
            PackOutcome *outcome) noexcept {
  Packer<D> packer(n, a, params);
  return packer.run(box, c, p, q, phi, outcome);
}

#define PW85_PACK(D)                                                         \
  template bool pack_box<D>(std::size_t, double const *, double const *,    \
                            double, double *) noexcept;                     \
  template Status pack<D>(std::size_t, double const *, PackParams const &,  \
                          double *, double *, double *, double *, double *, \
                          PackOutcome *) noexcept;
PW85_PACK(2)
PW85_PACK(3)
#undef PW85_PACK

}  // namespace pw85::detail
