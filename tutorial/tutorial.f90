! SPDX-License-Identifier: BSD-3-Clause
! Do two spheroids overlap? The Fortran tutorial (seed chapter 2.2, as
! tutorial.c), through the module pw85 (bindings/fortran/pw85.f90).
program tutorial
  use, intrinsic :: iso_c_binding, only: c_double, c_int
  use, intrinsic :: iso_fortran_env, only: error_unit
  use pw85
  implicit none

  ! E1: oblate spheroid centred at x1, radii a1 (equatorial), c1 (polar),
  ! axis n1. E2: prolate spheroid centred at x2.
  real(c_double), parameter :: x1(PW85_DIM) = [-0.5_c_double, 0.4_c_double, -0.7_c_double]
  real(c_double), parameter :: n1(PW85_DIM) = [0._c_double, 0._c_double, 1._c_double]
  real(c_double), parameter :: a1 = 10._c_double, c1 = 0.1_c_double

  real(c_double), parameter :: x2(PW85_DIM) = [0.2_c_double, -0.3_c_double, 0.4_c_double]
  real(c_double), parameter :: n2(PW85_DIM) = [1._c_double, 0._c_double, 0._c_double]
  real(c_double), parameter :: a2 = 0.5_c_double, c2 = 5._c_double

  real(c_double) :: q1(PW85_SYM), q2(PW85_SYM), out(2)
  integer(c_int) :: status

  call pw85_spheroid(a1, c1, n1, q1)
  call pw85_spheroid(a2, c2, n2, q2)

  status = pw85_contact_function(x2 - x1, q1, q2, out)
  if (status /= PW85_SUCCESS) then
    write(error_unit, '(2a)') 'pw85_contact_function: ', pw85_message(status)
    error stop 1
  end if
  ! g0.6: six significant digits, as %g in tutorial.c.
  write(*, '(a, g0.6)') 'mu^2 = ', out(1)
  write(*, '(a, g0.6)') 'lambda = ', out(2)
end program tutorial
