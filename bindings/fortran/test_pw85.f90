! SPDX-License-Identifier: BSD-3-Clause
! Tests of the module pw85: each interface reaches its C function with the
! arguments in place, each wrapper keeps its contract. Prints one line per
! check; exits with status 1 if one failed.
! Usage: test-fortran EXPECTED-VERSION
program test_pw85
  use, intrinsic :: iso_c_binding, only: c_double, c_int, c_size_t
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, &
                                           ieee_is_nan
  use pw85
  implicit none

  real(c_double), parameter :: one = 1._c_double, zero = 0._c_double
  real(c_double) :: n(PW85_DIM), q1(PW85_SYM), q2(PW85_SYM), r12(PW85_DIM)
  real(c_double) :: out(2), mu2, lambda, l(PW85_SYM), x(PW85_DIM)
  real(c_double) :: params(PW85_DIM + 2 * PW85_SYM), res(3), strided(2 * PW85_DIM)
  real(c_double) :: bad(PW85_SYM), axes(PW85_DIM), p(4)
  integer(c_int) :: status, overlap
  integer :: failures = 0
  character(len=32) :: expected_version

  call get_command_argument(1, expected_version)

  ! The tutorial's pair (docs/tutorial.rst).
  n = [zero, zero, one]
  call pw85_spheroid(10._c_double, 0.1_c_double, n, q1)
  call check('spheroid: Q = a²I + (c² − a²)nnᵀ', &
             all(q1 == [100._c_double, zero, zero, 100._c_double, zero, 0.1_c_double**2]))
  n = [one, zero, zero]
  call pw85_spheroid(0.5_c_double, 5._c_double, n, q2)
  call check('spheroid: second form', &
             all(q2 == [25._c_double, zero, zero, 0.25_c_double, zero, 0.25_c_double]))
  r12 = [0.7_c_double, -0.7_c_double, 1.1_c_double]

  out = -one
  status = pw85_contact_function(r12, q1, q2, out)
  call check('contact_function: success', status == PW85_SUCCESS)
  call check('contact_function: mu^2 and lambda', &
             abs(out(1) - 3.3627060406386291_c_double) < 1e-15_c_double .and. &
             abs(out(2) - 0.16685895534055478_c_double) < 1e-12_c_double)

  ! The wrapper: the same answer bit for bit, from a strided section too.
  strided = zero
  strided(1::2) = r12
  status = pw85_contact(strided(1::2), q1, q2, mu2, lambda)
  call check('pw85_contact: same mu^2 and lambda, strided r12', &
             status == PW85_SUCCESS .and. mu2 == out(1) .and. lambda == out(2))
  mu2 = -one
  status = pw85_contact(r12(1:2), q1, q2, mu2, lambda)
  call check('pw85_contact: wrong size is PW85_EINVAL, outputs untouched', &
             status == PW85_EINVAL .and. mu2 == -one)

  ! f at the maximiser is mu^2.
  params = [r12, q1, q2]
  call check('f_neg: -f(lambda) = -mu^2', &
             abs(pw85_f_neg(out(2), params) + out(1)) <= 1e-14_c_double * out(1))
  call pw85__residual(out(2), r12, q1, q2, res)
  call check('residual: f(lambda) = mu^2', abs(res(1) - out(1)) <= 1e-14_c_double * out(1))

  ! Cholesky: L·Lᵀ·x = b solved back.
  call pw85__cholesky_decomp(q2, l)
  call pw85__cholesky_solve(l, r12, x)
  call check('cholesky: Q2·x = r12', &
             abs(25._c_double * x(1) - r12(1)) < 1e-14_c_double .and. &
             abs(0.25_c_double * x(2) - r12(2)) < 1e-14_c_double .and. &
             abs(0.25_c_double * x(3) - r12(3)) < 1e-14_c_double)

  overlap = 42
  status = pw85_overlap(r12, q1, q2, overlap)
  call check('overlap: disjoint (+1)', status == PW85_SUCCESS .and. overlap == 1)
  status = pw85_overlap(0.1_c_double * r12, q1, q2, overlap)
  call check('overlap: overlapping (-1)', status == PW85_SUCCESS .and. overlap == -1)

  ! Errors: statuses and messages come through.
  bad = q1
  bad(4) = -one
  out = -one
  status = pw85_contact_function(r12, bad, q2, out)
  call check('not positive definite: PW85_ENOTPOSDEF, out untouched', &
             status == PW85_ENOTPOSDEF .and. all(out == -one))
  call check('pw85_message names it', &
             len(pw85_message(status)) > 0 .and. &
             pw85_message(status) == pw85_message(PW85_ENOTPOSDEF) .and. &
             pw85_message(status) /= pw85_message(PW85_SUCCESS))
  bad = q1
  bad(1) = ieee_value(one, ieee_quiet_nan)
  status = pw85_contact_function(r12, bad, q2, out)
  call check('NaN: PW85_EDOM', status == PW85_EDOM)
  call check('unknown status: a message', len(pw85_message(-12345_c_int)) > 0)

  call check('version: ' // pw85_library_version(), &
             pw85_library_version() == trim(expected_version))

  ! Since 2.3.0: the spheroid's preconditions checked (issue 30), and a
  ! form back to semi-axes and a quaternion. Hand-derived: diag(4, 9, 1)
  ! has semi-axes 3, 2, 1 along y, x, −z: the half-turn about
  ! (1, 1, 0)/√2, p = (0, √½, √½, 0).
  ! (Each status is assigned first: Fortran may evaluate the operands of
  ! .and. in any order.)
  n = [zero, zero, one]
  q1 = -7
  status = pw85_spheroid_checked(zero, 2._c_double, n, q1)
  call check('spheroid_checked: a = 0 refused, q untouched', &
             status == PW85_EINVAL .and. all(q1 == -7))
  status = pw85_spheroid_checked(-one, 2._c_double, n, q1)
  call check('spheroid_checked: a < 0 refused', status == PW85_EINVAL)
  status = pw85_spheroid_checked(one, 2._c_double, [one, one, zero], q1)
  call check('spheroid_checked: non-unit axis refused', status == PW85_EINVAL)
  status = pw85_spheroid_checked(2._c_double, 3._c_double, n, q1)
  call check('spheroid_checked: Q = a²I + (c² − a²)nnᵀ', &
             status == PW85_SUCCESS .and. all(q1 == [4._c_double, zero, &
             zero, 4._c_double, zero, 9._c_double]))
  status = pw85_principal_axes_quaternion([4._c_double, zero, zero, &
                                           9._c_double, zero, one], axes, p)
  call check('principal_axes_quaternion: semi-axes and p', &
             status == PW85_SUCCESS &
             .and. all(axes == [3._c_double, 2._c_double, one]) &
             .and. p(1) == zero .and. p(4) == zero &
             .and. abs(p(2) - sqrt(0.5_c_double)) <= epsilon(one) &
             .and. abs(p(3) - sqrt(0.5_c_double)) <= epsilon(one))

  call test_2d()

  if (failures > 0) then
    write(*, '(i0, a)') failures, ' check(s) failed'
    error stop 1
  end if

contains

  ! Ellipses (pw85_2d.h): two pairs of data/pw85_2d_pairs.h5 (records 0,
  ! generic, and 305, needles; mpmath references, correctly rounded: μ²
  ! must be equal, λ within its LAMBDA_WINDOW), a constructor case of
  ! pw85_2d_geometry.h5 (constructors, record 5), closed forms, the
  ! batches against the single calls, and the error statuses.
  subroutine test_2d()
    real(c_double) :: r(PW85_2D_DIM, 2), qa(PW85_2D_SYM, 2), &
                      qb(PW85_2D_SYM, 2), ref_mu2(2), ref_lambda(2), &
                      window(2)
    real(c_double) :: out(2), outs(2, 2), g(PW85_2D_GEOM_SIZE), &
                      gs(PW85_2D_GEOM_SIZE, 2), d(PW85_2D_DERIV_SIZE), &
                      ds(PW85_2D_DERIV_SIZE, 2), q(PW85_2D_SYM), &
                      qs(PW85_2D_SYM, 2), a(PW85_2D_DIM), as(PW85_2D_DIM, 2), &
                      theta, thetas(2), params(8), mu2, lambda, nan
    integer(c_int) :: status, result, results(2), statuses(2), k
    real(c_double), parameter :: u = epsilon(one) / 2
    integer(c_size_t), parameter :: two = 2, zero_stride = 0, &
                                    dim2 = PW85_2D_DIM, sym2 = PW85_2D_SYM, &
                                    one_stride = 1

    r(:, 1) = [1.9989159046617608_c_double, -3.044689301411269_c_double]
    qa(:, 1) = [0.2417720451269342_c_double, 0.2850317448721523_c_double, &
                0.48931277063246487_c_double]
    qb(:, 1) = [0.28553482236021804_c_double, -0.14094123595110067_c_double, &
                0.1244247848425048_c_double]
    ref_mu2(1) = 16.878830868251367_c_double
    ref_lambda(1) = 0.30368373455936615_c_double
    window(1) = 7.249211032001643e-09_c_double
    r(:, 2) = [0.032140944055141306_c_double, -0.08389241585244309_c_double]
    qa(:, 2) = [773943.2895381401_c_double, 348993.80348200165_c_double, &
                157371.57556351958_c_double]
    qb(:, 2) = [1567872.5893307645_c_double, 707280.0624238843_c_double, &
                319059.7855222649_c_double]
    ref_mu2(2) = 0.24472390461969842_c_double
    ref_lambda(2) = 0.5863494102016485_c_double
    window(2) = 8.555775542587639e-09_c_double

    do k = 1, 2
      out = -one
      status = pw85_2d_contact_function(r(:, k), qa(:, k), qb(:, k), out)
      call check('2d_contact_function: reference mu^2 (bit for bit), lambda', &
                 status == PW85_SUCCESS .and. out(1) == ref_mu2(k) .and. &
                 abs(out(2) - ref_lambda(k)) <= window(k) + spacing(ref_lambda(k)))
      status = pw85_2d_contact(r(:, k), qa(:, k), qb(:, k), mu2, lambda)
      call check('pw85_2d_contact: the same mu^2 and lambda', &
                 status == PW85_SUCCESS .and. mu2 == out(1) .and. lambda == out(2))
      result = 42
      status = pw85_2d_overlap(r(:, k), qa(:, k), qb(:, k), result)
      call check('2d_overlap: the sign of mu^2 - 1', status == PW85_SUCCESS &
                 .and. result == merge(1, -1, ref_mu2(k) > one))
      params = [r(:, k), qa(:, k), qb(:, k)]
      call check('2d_f_neg: -f(lambda) = -mu^2 at the maximiser', &
                 abs(pw85_2d_f_neg(out(2), params) + out(1)) <= 4 * u * out(1))
      status = pw85_2d_contact_derivatives(r(:, k), qa(:, k), qb(:, k), g, d)
      call check('2d_contact_derivatives: mu^2, |n| = 1, n.r12 > 0', &
                 status == PW85_SUCCESS .and. g(PW85_2D_GEOM_MU2 + 1) == out(1) &
                 .and. abs(norm2(g(PW85_2D_GEOM_NORMAL + 1:PW85_2D_GEOM_NORMAL + 2)) &
                           - one) <= 4 * u &
                 .and. dot_product(g(PW85_2D_GEOM_NORMAL + 1:PW85_2D_GEOM_NORMAL + 2), &
                                   r(:, k)) > 0)
      ! Euler: μ² is homogeneous of degree 2 in r12, so r12·∂μ²/∂r12 =
      ! 2μ²; measured 0 and 2.04 u relative to 2μ² on these two pairs
      ! (the second: needles, cond(Q1) = 3.3e11; and the rounding of the dot
      ! product); held to 16 u.
      call check('2d_contact_derivatives: r12 . dmu^2/dr12 = 2 mu^2', &
                 abs(dot_product(r(:, k), d(PW85_2D_DERIV_R12 + 1:PW85_2D_DERIV_R12 + 2)) &
                     - 2 * out(1)) <= 16 * u * 2 * out(1))
      status = pw85_2d_contact_geometry(r(:, k), qa(:, k), qb(:, k), gs(:, 1))
      call check('2d_contact_geometry: the geometry of the derivatives', &
                 status == PW85_SUCCESS .and. all(gs(:, 1) == g))
    end do

    ! The batches: the two pairs in one call, the same bits as alone.
    status = pw85_2d_contact_function_batch(two, r, dim2, qa, sym2, qb, sym2, &
                                            outs, statuses, 1_c_int)
    call check('2d_contact_function_batch: reference mu^2', &
               status == PW85_SUCCESS .and. all(outs(1, :) == ref_mu2) .and. &
               all(statuses == PW85_SUCCESS))
    status = pw85_2d_overlap_batch(two, r, dim2, qa, sym2, qb, sym2, results, &
                                   statuses, 2_c_int)
    call check('2d_overlap_batch: +1 then -1', &
               status == PW85_SUCCESS .and. all(results == [1, -1]))
    status = pw85_2d_contact_derivatives_batch(two, r, dim2, qa, sym2, qb, &
                                               sym2, gs, ds, statuses, 1_c_int)
    call check('2d_contact_derivatives_batch: as pair 2 alone', &
               status == PW85_SUCCESS .and. all(gs(:, 2) == g) .and. all(ds(:, 2) == d))
    status = pw85_2d_contact_geometry_batch(two, r, dim2, qa, sym2, qb, sym2, &
                                            gs, statuses, 1_c_int)
    call check('2d_contact_geometry_batch: as pair 2 alone', &
               status == PW85_SUCCESS .and. all(gs(:, 2) == g))
    status = pw85_2d_contact_function_batch(two, r, one_stride, qa, sym2, qb, &
                                            sym2, outs, statuses, 1_c_int)
    call check('2d_contact_function_batch: stride 1 is PW85_EINVAL', &
               status == PW85_EINVAL)

    ! Constructors: case 5 of the constructors of pw85_2d_geometry.h5
    ! (the bound of pw85_2d.h, 2u·(|Q_k| + Σ|R_im·R_jm|·a_m²) ≤ 2u·(|Q_k| +
    ! a0² + a1²)); the semi-axes correctly rounded, θ within 2 ulps.
    a = [0.00251694804667738_c_double, 0.12496376264403215_c_double]
    theta = -1.3013165446603447_c_double
    status = pw85_2d_ellipse(a, theta, q)
    call check('2d_ellipse: reference Q', status == PW85_SUCCESS .and. &
               all(abs(q - [0.014509557560258637_c_double, &
                            0.004005763268284064_c_double, &
                            0.0011127194413650422_c_double]) &
                   <= 2 * u * (abs(q) + sum(a**2))))
    q = [0.014509557560258637_c_double, 0.004005763268284064_c_double, &
         0.0011127194413650422_c_double]
    status = pw85_2d_principal_axes(q, a, theta)
    call check('2d_principal_axes: reference semi-axes and angle', &
               status == PW85_SUCCESS .and. &
               all(a == [0.12496376264403215_c_double, &
                         0.0025169480466774186_c_double]) .and. &
               abs(theta - 0.2694797821345518_c_double) <= &
                   2 * spacing(0.2694797821345518_c_double))
    status = pw85_2d_ellipse([3._c_double, 0.5_c_double], zero, q)
    call check('2d_ellipse: theta = 0 gives diag(a^2) exactly', &
               status == PW85_SUCCESS .and. all(q == [9._c_double, zero, 0.25_c_double]))
    thetas = [zero, 0.4_c_double]
    status = pw85_2d_ellipse_batch(two, [3._c_double, 0.5_c_double], &
                                   zero_stride, thetas, one_stride, qs, &
                                   statuses, 1_c_int)
    status = pw85_2d_ellipse([3._c_double, 0.5_c_double], 0.4_c_double, q)
    call check('2d_ellipse_batch: as alone', all(qs(:, 2) == q) .and. &
               all(qs(:, 1) == [9._c_double, zero, 0.25_c_double]))
    status = pw85_2d_principal_axes_batch(two, qs, sym2, as, thetas, &
                                          statuses, 1_c_int)
    call check('2d_principal_axes_batch: semi-axes 3 and 0.5', &
               status == PW85_SUCCESS .and. all(as(:, 1) == [3._c_double, 0.5_c_double]) &
               .and. thetas(1) == zero)

    ! Circles of radii 1 and 2, centres 6 apart: μ² = 4 exactly, λ = 1/3.
    status = pw85_2d_contact_function([zero, 6._c_double], [one, zero, one], &
                                      [4._c_double, zero, 4._c_double], out)
    call check('2d_contact_function: circles, mu^2 = 4, lambda = 1/3', &
               status == PW85_SUCCESS .and. out(1) == 4 .and. &
               abs(out(2) - one / 3) <= 2 * u)

    ! Errors: statuses, outputs untouched.
    nan = ieee_value(one, ieee_quiet_nan)
    out = -one
    status = pw85_2d_contact_function([nan, one], qa(:, 1), qb(:, 1), out)
    call check('2d: NaN is PW85_EDOM, out untouched', &
               status == PW85_EDOM .and. all(out == -one))
    status = pw85_2d_contact_function(r(:, 1), [one, 2._c_double, one], &
                                      qb(:, 1), out)
    call check('2d: not positive definite is PW85_ENOTPOSDEF', &
               status == PW85_ENOTPOSDEF .and. all(out == -one))
    result = 42
    status = pw85_2d_overlap(r(:, 1), qa(:, 1), [one, 2._c_double, one], result)
    call check('2d_overlap: PW85_ENOTPOSDEF, result untouched', &
               status == PW85_ENOTPOSDEF .and. result == 42)
    q = -7
    status = pw85_2d_ellipse([zero, one], zero, q)
    call check('2d_ellipse: a semi-axis 0 is PW85_EINVAL, q untouched', &
               status == PW85_EINVAL .and. all(q == -7))
    status = pw85_2d_principal_axes([one, nan, one], a, theta)
    call check('2d_principal_axes: NaN is PW85_EDOM', status == PW85_EDOM)
    mu2 = -one
    status = pw85_2d_contact(r(:, 1), qa(:, 1), qb(1:2, 1), mu2, lambda)
    call check('pw85_2d_contact: wrong size is PW85_EINVAL', &
               status == PW85_EINVAL .and. mu2 == -one)
    call check('2d_f_neg: NaN for a form not positive definite', &
               ieee_is_nan(pw85_2d_f_neg(0.5_c_double, [r(:, 1), &
                           [one, 2._c_double, one], qb(:, 1)])))
  end subroutine

  subroutine check(what, ok)
    character(len=*), intent(in) :: what
    logical, intent(in) :: ok
    if (ok) then
      write(*, '(2a)') 'ok: ', what
    else
      write(*, '(2a)') 'FAIL: ', what
      failures = failures + 1
    end if
  end subroutine

end program test_pw85
