// SPDX-License-Identifier: BSD-3-Clause
// fuzz-geometry: any 15 doubles (r12, q1, q2, raw bytes, zero-padded: the
// layout of fuzz-contact-raw, whose corpus it starts from) through
// pw85_contact_geometry and pw85_contact_derivatives, and the first 7
// (semi-axes, quaternion) and the first 12 (semi-axes, rotation) through
// the constructors and pw85_principal_axes. Oracles: the statuses and the
// μ² of pw85_contact_function; outputs untouched on error; finite outputs
// and a unit normal on success; the swapping symmetry, exactly; the
// constructors' statuses, and a positive, sorted set of semi-axes from
// every Q they build that is positive definite.
#include "fuzz_common.h"
#include "quad_ref.h"

namespace {

void check_geometry(const double r[3], const double q1[6],
                    const double q2[6]) {
  double cf[2], g[PW85_GEOM_SIZE], g2[PW85_GEOM_SIZE], d[PW85_DERIV_SIZE];
  fuzz::fill_sentinel(cf, sizeof cf);
  fuzz::fill_sentinel(g, sizeof g);
  fuzz::fill_sentinel(g2, sizeof g2);
  fuzz::fill_sentinel(d, sizeof d);
  int const st_cf = pw85_contact_function(r, q1, q2, cf);
  int const st = pw85_contact_geometry(r, q1, q2, g);
  int const st2 = pw85_contact_derivatives(r, q1, q2, g2, d);
  // A derivative alone may overflow: PW85_ERANGE from the derivatives only.
  bool const d_overflow = st == PW85_SUCCESS && st2 == PW85_ERANGE;
  CHECK(st == st2 || d_overflow, "geometry %d, derivatives %d", st, st2);
  if (d_overflow)
    CHECK(std::memcmp(g, g2, sizeof g) == 0 &&
              !fuzz::all_finite(d, PW85_DERIV_SIZE),
          "derivatives: ERANGE with finite derivatives");
  bool const written = !fuzz::is_sentinel(g, sizeof g);
  if (st != PW85_SUCCESS && st != PW85_ERANGE) {
    CHECK(st == st_cf, "geometry %d, contact function %d", st, st_cf);
    CHECK(!written && fuzz::is_sentinel(g2, sizeof g2) &&
              fuzz::is_sentinel(d, sizeof d),
          "status %d wrote outputs", st);
    return;
  }
  if (!written) {
    // PW85_ERANGE before the search, as the contact function; or where
    // Q(λ) cannot be factorised at the maximiser (pw85.h): then only far
    // beyond the documented domain.
    CHECK(st == PW85_ERANGE, "status %d, nothing written", st);
    CHECK((st_cf == PW85_ERANGE && fuzz::is_sentinel(cf, sizeof cf)) ||
              fuzz::cond_bound(q1) > 1e17 || fuzz::cond_bound(q2) > 1e17,
          "ERANGE, nothing written; contact function %d", st_cf);
    return;
  }
  CHECK(std::memcmp(g, g2, sizeof g) == 0, "geometries differ");
  CHECK(st_cf == PW85_SUCCESS || st_cf == PW85_ERANGE, "contact function %d",
        st_cf);
  CHECK(fuzz::same_bits(g[PW85_GEOM_MU2], cf[0]), "mu2 %a, contact %a",
        g[PW85_GEOM_MU2], cf[0]);
  double const lambda = g[PW85_GEOM_LAMBDA];
  CHECK(lambda >= 0.0 && lambda <= 1.0, "lambda %a", lambda);
  bool const zero = r[0] == 0.0 && r[1] == 0.0 && r[2] == 0.0;
  double nn = 0.0;
  for (int i = 0; i < 3; ++i)
    nn += g[PW85_GEOM_NORMAL + i] * g[PW85_GEOM_NORMAL + i];
  CHECK(zero ? nn == 0.0 : std::fabs(nn - 1.0) <= 8 * DBL_EPSILON,
        "|n|^2 = %a", nn);
  if (st == PW85_SUCCESS)
    CHECK(fuzz::all_finite(g, PW85_GEOM_SIZE) &&
              (d_overflow || fuzz::all_finite(d, PW85_DERIV_SIZE)),
          "success with a non-finite output");
  // Against the binary128 reference (quad_ref.h) inside the documented
  // domain: the accuracy pw85.h states, 1.5·u·κ (x − c1, n, λ relative to
  // min(λ, 1 − λ)), 1.2·u·κ (∂μ²/∂r12), 1.1·u·κ (torques, relative to
  // |∂μ²/∂r12|·|x − cᵢ|), κ = cond(Q(λ)), held to 8·u·κ̄ as the tests do
  // (κ̄ = tr·tr⁻¹ ≥ κ), plus the rounding of each output.
  if (st2 == PW85_SUCCESS && !zero && fuzz::cond_bound(q1) < 1e16L &&
      fuzz::cond_bound(q2) < 1e16L && g[PW85_GEOM_MU2] >= DBL_MIN) {
    fuzz::QuadRef const ref = fuzz::quad_contact(r, q1, q2);
    fuzz::QuadGeometry qg;
    if (ref.ok && quad_geometry(ref.lambda, ref.other, r, q1, q2, &qg) &&
        qg.cond < 1e16Q) {
      long double const u = DBL_EPSILON / 2;
      long double const tol = 8 * u * (long double)qg.cond;
      auto norm = [](const long double v[3]) {
        return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      };
      // |out − ref| / |ref| for a block of 3
      // Blocks whose scale lies below 2^−960 are not compared: their
      // values may underflow (a torque of 1e-461 is returned as 0).
      auto rel = [&](const double *out, const fuzz::quad *rq,
                     long double scale) {
        long double d[3], q3[3];
        for (int i = 0; i < 3; ++i) {
          q3[i] = (long double)rq[i];
          d[i] = (long double)out[i] - q3[i];
        }
        long double const s = scale > 0 ? scale : norm(q3);
        return s > 0x1p-960L ? norm(d) / s : 0.0L;
      };
      long double const lam_ref = (long double)ref.lambda;
      long double const near =
          std::fmin(lam_ref, (long double)ref.other);
      // + u absolute: λ may be computed as 1 − λ near 1 (pw85.h).
      CHECK(std::fabs((long double)lambda - lam_ref) <=
                tol * near + lam_ref * 0x1p-53L + 0x1p-53L,
            "lambda %a, reference %La (tol %Lg)", lambda, lam_ref, tol);
      CHECK(rel(g + PW85_GEOM_POINT, qg.point, 0) <= tol + 2 * u,
            "x - c1 off by %Lg (tol %Lg)", rel(g + PW85_GEOM_POINT, qg.point, 0),
            tol);
      CHECK(rel(g + PW85_GEOM_NORMAL, qg.normal, 0) <= tol + 2 * u,
            "n off by %Lg (tol %Lg)", rel(g + PW85_GEOM_NORMAL, qg.normal, 0),
            tol);
      CHECK(rel(d + PW85_DERIV_R12, qg.d_r12, 0) <= tol + 2 * u,
            "d/dr12 off by %Lg (tol %Lg)", rel(d + PW85_DERIV_R12, qg.d_r12, 0),
            tol);
      long double dr[3], x1[3], x2[3];
      for (int i = 0; i < 3; ++i) {
        dr[i] = (long double)qg.d_r12[i];
        x1[i] = (long double)qg.point[i];
        x2[i] = (long double)qg.point2[i];  // not x1 − r: it cancels
      }
      long double const s1 = norm(dr) * norm(x1), s2 = norm(dr) * norm(x2);
      CHECK(rel(d + PW85_DERIV_ROT1, qg.rot1, s1) <= tol + 2 * u,
            "d/drot1 off by %Lg of its scale (tol %Lg)",
            rel(d + PW85_DERIV_ROT1, qg.rot1, s1), tol);
      CHECK(rel(d + PW85_DERIV_ROT2, qg.rot2, s2) <= tol + 2 * u,
            "d/drot2 off by %Lg of its scale (tol %Lg)",
            rel(d + PW85_DERIV_ROT2, qg.rot2, s2), tol);
    }
  }
  // Swapping the ellipsoids: the same status and μ² (bit for bit), n → −n
  // and the derivatives exchanged, exactly (a zero may change sign); where
  // the contact function's swapping is exact.
  if (st2 != PW85_SUCCESS ||
      !fuzz::exact_swap_domain(r, q1, q2, g[PW85_GEOM_MU2]))
    return;
  double const mr[3] = {-r[0], -r[1], -r[2]};
  double gs[PW85_GEOM_SIZE], ds[PW85_DERIV_SIZE];
  int const sts = pw85_contact_derivatives(mr, q2, q1, gs, ds);
  CHECK(sts == st, "swapped status %d, %d", sts, st);
  CHECK(fuzz::same_bits(gs[PW85_GEOM_MU2], g[PW85_GEOM_MU2]), "swapped mu2");
  for (int i = 0; i < 3; ++i) {
    CHECK(gs[PW85_GEOM_NORMAL + i] == -g[PW85_GEOM_NORMAL + i],
          "swapped normal %d", i);
    CHECK(ds[PW85_DERIV_R12 + i] == -d[PW85_DERIV_R12 + i],
          "swapped d/dr12 %d", i);
    CHECK(ds[PW85_DERIV_ROT1 + i] == d[PW85_DERIV_ROT2 + i] &&
              ds[PW85_DERIV_ROT2 + i] == d[PW85_DERIV_ROT1 + i],
          "swapped d/drot %d", i);
  }
  for (int k = 0; k < 6; ++k)
    CHECK(ds[PW85_DERIV_Q1 + k] == d[PW85_DERIV_Q2 + k] &&
              ds[PW85_DERIV_Q2 + k] == d[PW85_DERIV_Q1 + k],
          "swapped d/dq %d", k);
}

bool is_constructor_status(int st) {
  return st == PW85_SUCCESS || st == PW85_EDOM || st == PW85_EINVAL ||
         st == PW85_ERANGE;
}

void check_axes_of(const double q[6]) {
  double a[3], rot[9];
  fuzz::fill_sentinel(a, sizeof a);
  int const st = pw85_principal_axes(q, a, rot);
  // ERANGE (pw85.h): a form positive definite but singular to double
  // precision (its factorisation in double fails: cond near 1/ε or
  // beyond; cond_bound() overestimates cond by up to 9), or cond above
  // about 1e270.
  CHECK(st == PW85_SUCCESS || st == PW85_ENOTPOSDEF || st == PW85_EDOM ||
            (st == PW85_ERANGE && fuzz::cond_bound(q) > 1e15),
        "principal axes %d, cond bound %Lg", st, fuzz::cond_bound(q));
  if (st != PW85_SUCCESS) {
    CHECK(fuzz::is_sentinel(a, sizeof a), "status %d wrote a", st);
    return;
  }
  CHECK(a[0] >= a[1] && a[1] >= a[2] && a[2] > 0.0 &&
            fuzz::all_finite(a, 3) && fuzz::all_finite(rot, 9),
        "a = %a %a %a", a[0], a[1], a[2]);
}

void check_constructors(const double x[15]) {
  double q[6];
  fuzz::fill_sentinel(q, sizeof q);
  int st = pw85_ellipsoid_quaternion(x, x + 3, q);
  CHECK(is_constructor_status(st), "quaternion %d", st);
  if (st != PW85_SUCCESS)
    CHECK(fuzz::is_sentinel(q, sizeof q), "status %d wrote q", st);
  else
    CHECK(fuzz::all_finite(q, 6), "quaternion: q not finite");
  check_axes_of(st == PW85_SUCCESS ? q : x + 3);
  fuzz::fill_sentinel(q, sizeof q);
  st = pw85_ellipsoid_rotation(x, x + 3, q);
  CHECK(is_constructor_status(st), "rotation %d", st);
  if (st != PW85_SUCCESS)
    CHECK(fuzz::is_sentinel(q, sizeof q), "status %d wrote q", st);
  else
    CHECK(fuzz::all_finite(q, 6), "rotation: q not finite");
  if (st == PW85_SUCCESS) check_axes_of(q);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  fuzz::Bytes in(data, size);
  double x[15];
  for (double &v : x) v = in.f64();
  check_geometry(x, x + 3, x + 9);
  check_constructors(x);
  return 0;
}
