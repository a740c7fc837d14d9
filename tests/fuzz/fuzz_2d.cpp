// SPDX-License-Identifier: BSD-3-Clause
// fuzz-2d: the functions of include/pw85/pw85_2d.h. Any 8 doubles (r12[2],
// q1[3], q2[3], raw bytes, zero-padded), then one byte for the exponent k
// of the scaling relation, one byte of mode (bits 0-2: a symmetry of the
// square; bit 3: threads 2 rather than 1 in the batches), a uint16 for the
// angle of a rotation and a uint16 for the λ of pw85_2d_f_neg.
//
// Oracles: those of the contact function, the overlap test
// (fuzz::check_contact<2>) and the geometry and derivatives
// (fuzz::check_geometry<2>), written once for both dimensions; here
//  - the symmetries of the square (x ↔ y, x → −x, y → −y) map the doubles
//    exactly: μ² and the overlap test unchanged, bit for bit, where μ² is
//    correctly rounded;
//  - a rotation of the whole configuration by an angle: μ² within the
//    bound that the rounding of the rotated inputs allows (below);
//  - pw85_2d_f_neg: NaN for bad input, never positive, f ≤ μ², the
//    binary128 f, the swapping relation;
//  - the batches: every pair or item bit for bit as the single call, the
//    statuses, the first failing status;
//  - pw85_2d_ellipse and pw85_2d_principal_axes: statuses, outputs
//    untouched on error, the stated accuracy against binary128 and long
//    double references, the definiteness rule of the contact function.
#include "fuzz_common.h"
#include "quad_ref.h"

namespace {

using fuzz::quad;
const double u = DBL_EPSILON / 2;

bool is_status(int s) {
  return s == PW85_SUCCESS || s == PW85_EDOM || s == PW85_ENOTPOSDEF ||
         s == PW85_ERANGE || s == PW85_ENOMEM || s == PW85_EINVAL;
}

quad qabs(quad x) { return x < 0 ? -x : x; }

// √x in quad: a Newton step from the long double root (≈ 2⁻¹²⁶ relative).
quad qsqrt(quad x) {
  if (!(x > 0)) return 0;
  quad const y = (quad)std::sqrt((long double)x);
  return (y + x / y) / 2;
}

double ulp(double x) {
  return std::nextafter(std::fabs(x), INFINITY) - std::fabs(x);
}

// The largest diagonal entry of a form: ≤ ‖Q‖₂.
quad max_diag(const quad q[3]) { return q[0] > q[2] ? q[0] : q[2]; }

// ---------------------------------------------------------------------------
// Symmetries of the square: r → P·r, Q → P·Q·Pᵀ with P a signed
// permutation, exact in floating point.
void symmetry(unsigned g, const double r[2], const double q[3], double rs[2],
              double qs[3]) {
  double r0 = r[0], r1 = r[1], a = q[0], b = q[1], c = q[2];
  if (g & 1) {  // x ↔ y
    std::swap(r0, r1);
    std::swap(a, c);
  }
  if (g & 2) {  // x → −x
    r0 = -r0;
    b = -b;
  }
  if (g & 4) {  // y → −y
    r1 = -r1;
    b = -b;
  }
  rs[0] = r0, rs[1] = r1, qs[0] = a, qs[1] = b, qs[2] = c;
}

void check_symmetry(unsigned g, const double r[2], const double q1[3],
                    const double q2[3]) {
  double rs[2], q1s[3], q2s[3], out[2], outs[2];
  symmetry(g, r, q1, rs, q1s);
  symmetry(g, r, q2, rs, q2s);
  int const st = pw85_2d_contact_function(r, q1, q2, out);
  int const sts = pw85_2d_contact_function(rs, q1s, q2s, outs);
  // Finiteness and exact definiteness do not change.
  if (st == PW85_EDOM || st == PW85_ENOTPOSDEF || sts == PW85_EDOM ||
      sts == PW85_ENOTPOSDEF)
    CHECK(st == sts, "symmetry %u: status %d, %d", g, st, sts);
  if (st != PW85_SUCCESS ||
      !fuzz::exact_swap_domain<2>(r, q1, q2, out[0]))
    return;
  // The exact μ² is the same: correctly rounded, the same double.
  CHECK(sts == PW85_SUCCESS && fuzz::same_bits(out[0], outs[0]),
        "symmetry %u: status %d, mu2 %a, not %a", g, sts, outs[0], out[0]);
  int res, ress;
  CHECK(pw85_2d_overlap(r, q1, q2, &res) == PW85_SUCCESS &&
            pw85_2d_overlap(rs, q1s, q2s, &ress) == PW85_SUCCESS &&
            res == ress,
        "symmetry %u: overlap %d, %d", g, res, ress);
}

// ---------------------------------------------------------------------------
// Rotation of the whole configuration by φ, with c = cos φ, s = sin φ as
// doubles: R = [[c, −s], [s, c]] = ρ·O, O orthogonal, ρ² = c² + s² (≠ 1
// by a few u), so r″ = R·r, Qᵢ″ = R·Qᵢ·Rᵀ is a similarity times a scaling
// by ρ, under which μ² is exactly invariant (pw85_2d.h). The rotated
// inputs are r′, Qᵢ′: r″, Qᵢ″ rounded to double along the way, with
// |r′ − r″| ≤ ε_r·|r″| and ‖Qᵢ′ − Qᵢ″‖₂ ≤ εᵢ·‖Qᵢ″‖₂, ε measured in quad
// (Frobenius norm over the largest diagonal entry: upper bounds).
//
// The bound: with κ ≥ cond(Qᵢ) (fuzz::cond_bound), cond(Q(λ)) ≤ κ for
// every λ (eigenvalues of a convex combination: λmax ≤ the combination of
// the λmax, λmin ≥ that of the λmin). Eᵢ = Qᵢ′ − Qᵢ″: ‖E(λ)‖ ≤
// (1−λ)ε1‖Q1″‖ + λε2‖Q2″‖ ≤ (ε1 + ε2)·‖Q″(λ)‖ (each term of Q″(λ) is
// positive semi-definite), so (1 − η_Q)·Q″(λ) ≼ Q′(λ) ≼ (1 + η_Q)·Q″(λ),
// η_Q = κ·(ε1 + ε2), and rᵀQ′(λ)⁻¹r lies within factors 1/(1 ± η_Q) of
// rᵀQ″(λ)⁻¹r. For r: in the norm of A = Q′(λ)⁻¹, √(r′ᵀAr′) ≤ √(r″ᵀAr″) +
// √‖A‖·|δr| ≤ (1 + √κ′·ε_r)·√(r″ᵀAr″), κ′ = κ(1 + η_Q)/(1 − η_Q) ≥
// cond(A). So at every λ, f′(λ) ≤ (1 + η)·f(λ) and f′(λ) ≥ (1 − η)·f(λ),
// η = (1 + √κ′·ε_r)²/(1 − η_Q) − 1, and the maxima obey
// |μ′² − μ²| ≤ η·μ²: rigorous, not to first order. Both computed μ² are
// correctly rounded in the documented domain (half an ulp each). Checked
// where η ≤ 1/4; there the rotated forms are positive definite
// (η_Q < 1), so the rotated call must succeed.
void check_rotation(unsigned turn, const double r[2], const double q1[3],
                    const double q2[3]) {
  double out[2];
  if (pw85_2d_contact_function(r, q1, q2, out) != PW85_SUCCESS) return;
  long double const k1 = fuzz::cond_bound<2>(q1), k2 = fuzz::cond_bound<2>(q2);
  if (!(k1 < 1e16L && k2 < 1e16L) || !(out[0] >= DBL_MIN)) return;
  double const phi = turn * (2 * M_PI / 65536);
  double const c = std::cos(phi), s = std::sin(phi);
  // In double, as a caller would.
  double const rr[2] = {c * r[0] - s * r[1], s * r[0] + c * r[1]};
  auto rotate = [&](const double q[3], double qr[3]) {
    double const m00 = c * q[0] - s * q[1], m01 = c * q[1] - s * q[2],
                 m10 = s * q[0] + c * q[1], m11 = s * q[1] + c * q[2];
    qr[0] = m00 * c - m01 * s;
    qr[1] = m00 * s + m01 * c;
    qr[2] = m10 * s + m11 * c;
  };
  double qr1[3], qr2[3];
  rotate(q1, qr1);
  rotate(q2, qr2);
  if (!fuzz::all_finite(rr, 2) || !fuzz::all_finite(qr1, 3) ||
      !fuzz::all_finite(qr2, 3))
    return;
  // Exactly (to 2⁻¹¹⁰) in quad: products of doubles are exact there.
  quad const C = c, S = s;
  quad const re[2] = {C * r[0] - S * r[1], S * r[0] + C * r[1]};
  auto eps_form = [&](const double q[3], const double qr[3]) {
    quad const m00 = C * q[0] - S * q[1], m01 = C * q[1] - S * q[2],
               m10 = S * q[0] + C * q[1], m11 = S * q[1] + C * q[2];
    quad const e[3] = {m00 * C - m01 * S, m00 * S + m01 * C,
                       m10 * S + m11 * C};
    quad const d0 = qr[0] - e[0], d1 = qr[1] - e[1], d2 = qr[2] - e[2];
    return qsqrt(d0 * d0 + 2 * d1 * d1 + d2 * d2) / max_diag(e) + 0x1p-100Q;
  };
  quad const nr = qsqrt(re[0] * re[0] + re[1] * re[1]);
  quad const dr0 = rr[0] - re[0], dr1 = rr[1] - re[1];
  quad const eps_r =
      nr > 0 ? qsqrt(dr0 * dr0 + dr1 * dr1) / nr + 0x1p-100Q : 0;
  quad const kappa = (quad)std::fmax(k1, k2);
  quad const eta_q = kappa * (eps_form(q1, qr1) + eps_form(q2, qr2));
  if (!(eta_q < 0.25Q)) return;
  quad const kp = kappa * (1 + eta_q) / (1 - eta_q);
  quad const g = 1 + qsqrt(kp) * eps_r;
  quad const eta = g * g / (1 - eta_q) - 1;
  if (!(eta <= 0.25Q)) return;
  double rot[2];
  int const st = pw85_2d_contact_function(rr, qr1, qr2, rot);
  CHECK(st == PW85_SUCCESS, "rotated by %u/65536 turn: status %d", turn, st);
  if (!(fuzz::cond_bound<2>(qr1) < 1e16L && fuzz::cond_bound<2>(qr2) < 1e16L &&
        rot[0] >= DBL_MIN))
    return;
  quad const big = out[0] > rot[0] ? out[0] : rot[0];
  quad const tol = eta * big * (1 + 4 * (quad)u) + ulp(out[0]) / 2 +
                   ulp(rot[0]) / 2;
  CHECK(qabs((quad)rot[0] - out[0]) <= tol,
        "rotated by %u/65536 turn: mu2 %a, not %a (eta %Lg)", turn, rot[0],
        out[0], (long double)eta);
}

// ---------------------------------------------------------------------------
// pw85_2d_f_neg (pw85_2d.h): NaN for non-finite input or a form not
// positive definite; never positive on [0, 1], 0 at its ends; within
// the range it states (|r12|² and the entries between 1e-150 and 1e150;
// 1e-140 and 1e140 here): f ≤ μ², and where cond(Q(λ)) < 1e8 (the
// factorisation in double, κ·u at most 1.2e-8), against the binary128 f
// within 8·u·κ̄ + u relative (a backward-stable solve; it states
// correct rounding as measured, not as promised); swapping:
// f(λ; r, Q1, Q2) = f(1 − λ; −r, Q2, Q1), 1 − λ exact for λ ≥ ½.
void check_f(double lambda, const double p[8]) {
  double const fneg = pw85_2d_f_neg(lambda, p);
  bool const finite_in = std::isfinite(lambda) && fuzz::all_finite(p, 8);
  if (!finite_in ||
      !(fuzz::exactly_definite<2>(p + 2) && fuzz::exactly_definite<2>(p + 5)))
    CHECK(std::isnan(fneg), "bad input: -f = %a", fneg);
  if (std::isnan(fneg)) return;
  CHECK(!(fneg > 0), "-f(%a) = %a > 0", lambda, fneg);
  if (lambda == 0 || lambda == 1) CHECK(fneg == 0, "-f(%a) = %a", lambda, fneg);
  for (int i = 0; i < 8; ++i)
    if (!(p[i] == 0 || (std::fabs(p[i]) >= 1e-70 && std::fabs(p[i]) <= 1e70)))
      return;
  if (!(p[2] >= 1e-140 && p[4] >= 1e-140 && p[5] >= 1e-140 && p[7] >= 1e-140))
    return;
  // f ≤ μ² (correctly rounded), f within 8·u·κ̄ ≤ 1e-7 relative.
  double out[2];
  if (pw85_2d_contact_function(p, p + 2, p + 5, out) == PW85_SUCCESS &&
      fuzz::cond_bound<2>(p + 2) < 1e8L && fuzz::cond_bound<2>(p + 5) < 1e8L)
    CHECK(-fneg <= out[0] * (1 + 1e-7) + DBL_TRUE_MIN,
          "f(%a) = %a > mu2 = %a", lambda, -fneg, out[0]);
  if (lambda > 0 && lambda < 1) {
    fuzz::QuadArray<2> const r(p);
    fuzz::QuadArray<3> const a(p + 2), b(p + 5);
    quad s[2], cond, f;
    if (fuzz::quad_solve<2>(lambda, 1 - (quad)lambda, r.v, a.v, b.v, s,
                            &cond) &&
        cond < 1e8Q &&
        fuzz::quad_f<2>(lambda, r.v, a.v, b.v, &f, nullptr)) {
      quad const tol = f * (8 * (quad)u * cond + (quad)u) + DBL_TRUE_MIN;
      CHECK(qabs(-(quad)fneg - f) <= tol, "-f(%a) = %a, binary128 %a",
            lambda, fneg, -(double)f);
    }
  }
  if (lambda >= 0.5 && lambda <= 1) {
    double const sw[8] = {-p[0], -p[1], p[5], p[6], p[7], p[2], p[3], p[4]};
    double const g = pw85_2d_f_neg(1 - lambda, sw);
    CHECK(std::fabs(g - fneg) <= 4 * DBL_EPSILON * std::fabs(fneg) +
                                     4 * DBL_TRUE_MIN,
          "-f(%a) = %a, swapped %a", lambda, fneg, g);
  }
}

// ---------------------------------------------------------------------------
// Batches (pw85.h, "Batches"): pair i as the single call computes it,
// outputs of a failing pair left as it leaves them (sentinels compared
// byte for byte), status[i] its status, the first failing status returned.
// Three pairs: (r, q1, q2), (−r, q2, q1), (r, q2, q1), as records of 8
// doubles (strides 8); then contiguous r12 and q1 with q2_stride 0.
constexpr int N = 3;

struct Singles {
  int st_cf[N], st_ov[N], st_g[N], st_d[N];
  double cf[N][2], g[N][PW85_2D_GEOM_SIZE], gd[N][PW85_2D_GEOM_SIZE],
      d[N][PW85_2D_DERIV_SIZE];
  int ov[N];
};

int first_failure(const int *st) {
  for (int i = 0; i < N; ++i)
    if (st[i] != PW85_SUCCESS) return st[i];
  return PW85_SUCCESS;
}

void run_singles(const double *r, size_t rs, const double *q1, size_t s1,
                 const double *q2, size_t s2, Singles *o) {
  fuzz::fill_sentinel(o, sizeof *o);
  for (int i = 0; i < N; ++i) {
    const double *ri = r + i * rs, *a = q1 + i * s1, *b = q2 + i * s2;
    o->st_cf[i] = pw85_2d_contact_function(ri, a, b, o->cf[i]);
    o->st_ov[i] = pw85_2d_overlap(ri, a, b, &o->ov[i]);
    o->st_g[i] = pw85_2d_contact_geometry(ri, a, b, o->g[i]);
    o->st_d[i] = pw85_2d_contact_derivatives(ri, a, b, o->gd[i], o->d[i]);
  }
}

void check_batches_with(const double *r, size_t rs, const double *q1,
                        size_t s1, const double *q2, size_t s2, int threads) {
  Singles one, all;
  run_singles(r, rs, q1, s1, q2, s2, &one);
  fuzz::fill_sentinel(&all, sizeof all);
  int st[N];
  int ret = pw85_2d_contact_function_batch(N, r, rs, q1, s1, q2, s2,
                                           &all.cf[0][0], st, threads);
  CHECK(ret == first_failure(one.st_cf) &&
            std::memcmp(st, one.st_cf, sizeof st) == 0 &&
            std::memcmp(all.cf, one.cf, sizeof all.cf) == 0,
        "contact function batch: %d", ret);
  ret = pw85_2d_overlap_batch(N, r, rs, q1, s1, q2, s2, all.ov, st, threads);
  CHECK(ret == first_failure(one.st_ov) &&
            std::memcmp(st, one.st_ov, sizeof st) == 0 &&
            std::memcmp(all.ov, one.ov, sizeof all.ov) == 0,
        "overlap batch: %d", ret);
  ret = pw85_2d_contact_geometry_batch(N, r, rs, q1, s1, q2, s2,
                                       &all.g[0][0], st, threads);
  CHECK(ret == first_failure(one.st_g) &&
            std::memcmp(st, one.st_g, sizeof st) == 0 &&
            std::memcmp(all.g, one.g, sizeof all.g) == 0,
        "geometry batch: %d", ret);
  ret = pw85_2d_contact_derivatives_batch(N, r, rs, q1, s1, q2, s2,
                                          &all.gd[0][0], &all.d[0][0], st,
                                          threads);
  CHECK(ret == first_failure(one.st_d) &&
            std::memcmp(st, one.st_d, sizeof st) == 0 &&
            std::memcmp(all.gd, one.gd, sizeof all.gd) == 0 &&
            std::memcmp(all.d, one.d, sizeof all.d) == 0,
        "derivatives batch: %d", ret);
}

void check_batches(const double x[8], int threads) {
  double rec[N][8];
  double const *r = x, *q1 = x + 2, *q2 = x + 5;
  for (int i = 0; i < N; ++i) {
    double const sign = i == 1 ? -1 : 1;
    rec[i][0] = sign * r[0];
    rec[i][1] = sign * r[1];
    std::memcpy(rec[i] + 2, i == 0 ? q1 : q2, 3 * sizeof(double));
    std::memcpy(rec[i] + 5, i == 0 ? q2 : q1, 3 * sizeof(double));
  }
  check_batches_with(&rec[0][0], 8, &rec[0][2], 8, &rec[0][5], 8, threads);
  double rc[N][2], qc[N][3];
  for (int i = 0; i < N; ++i) {
    std::memcpy(rc[i], rec[i], sizeof rc[i]);
    std::memcpy(qc[i], rec[i] + 2, sizeof qc[i]);
  }
  check_batches_with(&rc[0][0], 2, &qc[0][0], 3, q2, 0, threads);
}

// ---------------------------------------------------------------------------
// Constructors.
//
// pw85_2d_principal_axes: ENOTPOSDEF exactly where the contact function
// says so (the exact rule); ERANGE only for forms singular to
// double-double precision (κ̄ beyond 1e25: a Rayleigh quotient of 2⁻¹⁰⁶
// relative precision); on success a0 ≥ a1 > 0, θ in [−π/2, π/2], and, for
// entries between 2^-900 and 2^900, the accuracy it states: aⱼ within
// u·(1 + u·(a0/aⱼ)²) relative of √ of the eigenvalue (binary128:
// λmax = (tr + √((Q00 − Q11)² + 4Q01²))/2, λmin = det/λmax, det exact
// but for one rounding, error ≈ κ·2⁻¹¹³); θ within the effect of a
// rounding of Q00 − Q11 on ½·atan2 (≤ u/4) plus an ulp of atan2 and of θ
// (reference in long double, 2⁻⁶⁴), modulo π; θ = 0 for a circle.
void check_axes(const double q[3]) {
  double a[2], theta;
  fuzz::fill_sentinel(a, sizeof a);
  fuzz::fill_sentinel(&theta, sizeof theta);
  int const st = pw85_2d_principal_axes(q, a, &theta);
  CHECK(is_status(st), "principal axes %d", st);
  if (!fuzz::all_finite(q, 3)) {
    CHECK(st == PW85_EDOM, "non-finite q: principal axes %d", st);
  } else {
    bool const pd = fuzz::exactly_definite<2>(q);
    CHECK(pd == (st != PW85_ENOTPOSDEF), "principal axes %d, definite %d",
          st, pd);
    CHECK(st != PW85_ERANGE || fuzz::cond_bound<2>(q) > 1e25L,
          "principal axes ERANGE, cond bound %Lg", fuzz::cond_bound<2>(q));
  }
  if (st != PW85_SUCCESS) {
    CHECK(fuzz::is_sentinel(a, sizeof a) &&
              fuzz::is_sentinel(&theta, sizeof theta),
          "principal axes: status %d wrote outputs", st);
    return;
  }
  CHECK(a[0] >= a[1] && a[1] > 0 && std::isfinite(a[0]) &&
            std::fabs(theta) <= M_PI_2,
        "a = {%a, %a}, theta %a", a[0], a[1], theta);
  if (q[1] == 0 && q[0] == q[2]) CHECK(theta == 0, "circle: theta %a", theta);
  for (int k = 0; k < 3; ++k)
    if (!(q[k] == 0 ||
          (std::fabs(q[k]) >= 0x1p-900 && std::fabs(q[k]) <= 0x1p900)))
      return;
  long double const kb = fuzz::cond_bound<2>(q);
  quad const x = (quad)q[0] - q[2], y = 2 * (quad)q[1];
  quad const lmax = ((quad)q[0] + q[2] + qsqrt(x * x + y * y)) / 2;
  quad const det = (quad)q[0] * q[2] - (quad)q[1] * q[1];
  quad const ev[2] = {lmax, det / lmax};
  for (int j = 0; j < 2; ++j) {
    quad const ref = qsqrt(ev[j]);
    quad const ratio = qsqrt(ev[0]) / ref;  // a0/aⱼ of the form, not of a
    quad const tol = ref * ((quad)u * (1 + (quad)u * ratio * ratio) +
                            (quad)kb * 0x1p-110Q);
    CHECK(qabs((quad)a[j] - ref) <= tol, "a[%d] = %a, reference %a", j,
          a[j], (double)ref);
  }
  long double const xl = (long double)q[0] - q[2], yl = 2 * (long double)q[1];
  long double const t_ref = std::atan2(yl, xl) / 2;
  long double dt = theta - t_ref;
  if (dt > M_PI_2) dt -= M_PIl;
  if (dt < -M_PI_2) dt += M_PIl;
  long double const tol = u / 4 + ulp(2 * theta) + ulp(theta) + 0x1p-62L;
  CHECK(std::fabs(dt) <= tol, "theta = %a, reference %La", theta, t_ref);
}

// pw85_2d_ellipse: EDOM, EINVAL, ERANGE (fl(aₘ²) outside [DBL_MIN,
// DBL_MAX]) as it states, q untouched on error, and on success the
// stated accuracy: |q[k] − Q_k| ≤ 2u·(|Q_k| + Σₘ |R_im·R_jm|·aₘ²), Q_k
// exact for the θ given (cos θ, sin θ in long double: 2⁻⁶⁴ relative,
// allowed 2⁻⁶⁰·Σ).
void check_ellipse(const double a[2], double theta) {
  double q[3];
  fuzz::fill_sentinel(q, sizeof q);
  int const st = pw85_2d_ellipse(a, theta, q);
  int expect = PW85_SUCCESS;
  if (!fuzz::all_finite(a, 2) || !std::isfinite(theta)) {
    expect = PW85_EDOM;
  } else if (!(a[0] > 0 && a[1] > 0)) {
    expect = PW85_EINVAL;
  } else {
    for (int m = 0; m < 2; ++m)
      if (!(a[m] * a[m] >= DBL_MIN && a[m] * a[m] <= DBL_MAX))
        expect = PW85_ERANGE;
  }
  CHECK(st == expect, "ellipse: status %d, expected %d", st, expect);
  if (st != PW85_SUCCESS) {
    CHECK(fuzz::is_sentinel(q, sizeof q), "ellipse: status %d wrote q", st);
    return;
  }
  CHECK(fuzz::all_finite(q, 3), "ellipse: q not finite");
  long double const c = std::cos((long double)theta),
                    s = std::sin((long double)theta);
  long double const a0 = (long double)a[0] * a[0], a1 = (long double)a[1] * a[1];
  // R = [[c, −s], [s, c]]: Q = R·diag(a0², a1²)·Rᵀ.
  long double const ref[3] = {c * c * a0 + s * s * a1, c * s * (a0 - a1),
                              s * s * a0 + c * c * a1};
  long double const mag[3] = {c * c * a0 + s * s * a1,
                              std::fabs(c * s) * (a0 + a1),
                              s * s * a0 + c * c * a1};
  // + DBL_TRUE_MIN: an entry below DBL_MIN (Q01 for θ near 0) is a
  // subnormal, where the double-double products underflow too; pw85_2d.h's
  // bound omits it (pw85_ellipsoid_rotation states the same bound). The
  // fuzzer found q[1] = 0 where Q01 = −0.529·2^-1074 (mpmath, 120
  // digits), for a = (0x1.6666666666666p-1, 0x1.6666676936666p-1),
  // θ = 0x0.0000000bf66e6p-1022: one unit of DBL_TRUE_MIN off.
  for (int k = 0; k < 3; ++k)
    CHECK(std::fabs(q[k] - ref[k]) <= 2 * u * (std::fabs(ref[k]) + mag[k]) +
                                          0x1p-60L * mag[k] +
                                          0x1p-1074L,
          "ellipse: q[%d] = %a, reference %La", k, q[k], ref[k]);
  check_axes(q);
}

// The constructors' batches: each item as the single call.
void check_constructor_batches(const double x[8], int threads) {
  double q[2][3], a[2][2], th[2], qb[2][3], ab[2][2], thb[2];
  int st[2], stb[2];
  fuzz::fill_sentinel(q, sizeof q);
  fuzz::fill_sentinel(qb, sizeof qb);
  double const angles[2] = {x[2], x[5]};
  for (int i = 0; i < 2; ++i) st[i] = pw85_2d_ellipse(x + 3 * i, angles[i], q[i]);
  int ret = pw85_2d_ellipse_batch(2, x, 3, angles, 1, &qb[0][0], stb, threads);
  CHECK(ret == (st[0] != PW85_SUCCESS ? st[0] : st[1]) &&
            std::memcmp(st, stb, sizeof st) == 0 &&
            std::memcmp(q, qb, sizeof q) == 0,
        "ellipse batch %d", ret);
  fuzz::fill_sentinel(a, sizeof a);
  fuzz::fill_sentinel(ab, sizeof ab);
  fuzz::fill_sentinel(th, sizeof th);
  fuzz::fill_sentinel(thb, sizeof thb);
  for (int i = 0; i < 2; ++i)
    st[i] = pw85_2d_principal_axes(x + 2 + 3 * i, a[i], &th[i]);
  ret = pw85_2d_principal_axes_batch(2, x + 2, 3, &ab[0][0], thb, stb,
                                     threads);
  CHECK(ret == (st[0] != PW85_SUCCESS ? st[0] : st[1]) &&
            std::memcmp(st, stb, sizeof st) == 0 &&
            std::memcmp(a, ab, sizeof a) == 0 &&
            std::memcmp(th, thb, sizeof th) == 0,
        "principal axes batch %d", ret);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  fuzz::Bytes in(data, size);
  double x[8];
  for (double &v : x) v = in.f64();
  int const k = int(in.u8() % 41) - 20;
  unsigned const mode = in.u8();
  unsigned const turn = in.u16();
  double const lambda = in.u16() / 65535.0;
  int const threads = mode & 8 ? 2 : 1;
  const double *r = x, *q1 = x + 2, *q2 = x + 5;
  fuzz::check_contact<2>(r, q1, q2, k);
  fuzz::check_geometry<2>(r, q1, q2);
  check_symmetry(mode & 7, r, q1, q2);
  check_rotation(turn, r, q1, q2);
  check_f(lambda, x);
  check_batches(x, threads);
  check_ellipse(x, x[2]);
  check_axes(q1);
  check_axes(q2);
  check_constructor_batches(x, threads);
  return 0;
}

extern "C" int LLVMFuzzerInitialize(int *, char ***) {
  // NULL pointers and bad strides, once: PW85_EFAULT or PW85_EINVAL,
  // outputs untouched (status filled with the code); n = 0: success.
  double const r[2] = {1, 0}, q[3] = {1, 0, 1}, a[2] = {1, 1};
  double out[PW85_2D_GEOM_SIZE], d[PW85_2D_DERIV_SIZE], th;
  int res, st[2];
  fuzz::fill_sentinel(out, sizeof out);
  fuzz::fill_sentinel(d, sizeof d);
  fuzz::fill_sentinel(&res, sizeof res);
  fuzz::fill_sentinel(&th, sizeof th);
  CHECK(pw85_2d_contact_function(nullptr, q, q, out) == PW85_EFAULT &&
            pw85_2d_contact_function(r, nullptr, q, out) == PW85_EFAULT &&
            pw85_2d_contact_function(r, q, nullptr, out) == PW85_EFAULT &&
            pw85_2d_contact_function(r, q, q, nullptr) == PW85_EFAULT,
        "contact function: NULL");
  CHECK(pw85_2d_overlap(nullptr, q, q, &res) == PW85_EFAULT &&
            pw85_2d_overlap(r, q, q, nullptr) == PW85_EFAULT,
        "overlap: NULL");
  CHECK(pw85_2d_contact_geometry(r, q, nullptr, out) == PW85_EFAULT &&
            pw85_2d_contact_geometry(r, q, q, nullptr) == PW85_EFAULT &&
            pw85_2d_contact_derivatives(r, q, q, out, nullptr) ==
                PW85_EFAULT &&
            pw85_2d_contact_derivatives(r, q, q, nullptr, d) == PW85_EFAULT,
        "geometry: NULL");
  CHECK(pw85_2d_ellipse(nullptr, 0, out) == PW85_EFAULT &&
            pw85_2d_ellipse(a, 0, nullptr) == PW85_EFAULT &&
            pw85_2d_principal_axes(nullptr, out, &th) == PW85_EFAULT &&
            pw85_2d_principal_axes(q, nullptr, &th) == PW85_EFAULT &&
            pw85_2d_principal_axes(q, out, nullptr) == PW85_EFAULT,
        "constructors: NULL");
  CHECK(std::isnan(pw85_2d_f_neg(0.5, nullptr)), "f_neg(NULL)");
  CHECK(fuzz::is_sentinel(out, sizeof out) && fuzz::is_sentinel(d, sizeof d) &&
            fuzz::is_sentinel(&res, sizeof res) &&
            fuzz::is_sentinel(&th, sizeof th),
        "outputs written on EFAULT");
  CHECK(pw85_2d_contact_function_batch(2, r, 1, q, 3, q, 3, out, st, 1) ==
                PW85_EINVAL &&
            st[0] == PW85_EINVAL && st[1] == PW85_EINVAL &&
            pw85_2d_overlap_batch(2, r, 2, q, 2, q, 3, &res, st, 1) ==
                PW85_EINVAL &&
            pw85_2d_contact_geometry_batch(2, r, 2, q, 3, q, 3, out, st,
                                           -1) == PW85_EINVAL &&
            pw85_2d_contact_derivatives_batch(2, r, 2, q, 3, nullptr, 3,
                                              out, d, st, 1) == PW85_EFAULT &&
            st[0] == PW85_EFAULT && st[1] == PW85_EFAULT &&
            pw85_2d_ellipse_batch(2, a, 1, &th, 1, out, st, 1) ==
                PW85_EINVAL &&
            pw85_2d_principal_axes_batch(2, q, 2, out, &th, st, 1) ==
                PW85_EINVAL &&
            pw85_2d_contact_function_batch(0, nullptr, 0, nullptr, 0,
                                           nullptr, 0, nullptr, nullptr,
                                           1) == PW85_SUCCESS,
        "batches: strides, NULL, n = 0");
  CHECK(fuzz::is_sentinel(out, sizeof out) && fuzz::is_sentinel(d, sizeof d) &&
            fuzz::is_sentinel(&res, sizeof res),
        "batches: outputs written on a failed call");
  return 0;
}
