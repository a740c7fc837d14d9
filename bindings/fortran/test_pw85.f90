! SPDX-License-Identifier: BSD-3-Clause
! Tests of the module pw85: each interface reaches its C function with the
! arguments in place, each wrapper keeps its contract. Prints one line per
! check; exits with status 1 if one failed.
! Usage: test-fortran EXPECTED-VERSION
program test_pw85
  use, intrinsic :: iso_c_binding, only: c_double, c_int
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
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

  if (failures > 0) then
    write(*, '(i0, a)') failures, ' check(s) failed'
    error stop 1
  end if

contains

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
