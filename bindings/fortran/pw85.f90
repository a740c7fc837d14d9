! SPDX-License-Identifier: BSD-3-Clause
!> The Fortran interface of pw85: module pw85.
!>
!> Compile this file with the program (it is installed as
!> <includedir>/pw85/pw85.f90; `pkg-config --variable=fortran_module pw85`
!> prints its path) and link libpw85:
!>
!>     gfortran -c "$(pkg-config --variable=fortran_module pw85)"
!>     gfortran my_program.f90 pw85.o $(pkg-config --libs pw85)
!>
!> Two layers. The C functions of pw85.h under their own names, as bind(C)
!> interfaces: same arguments, same contracts (pw85.h documents them);
!> vectors are real(c_double) arrays of PW85_DIM, symmetric matrices of
!> PW85_SYM (upper triangle row by row: q(1) = Q11, q(2) = Q12, q(3) = Q13,
!> q(4) = Q22, q(5) = Q23, q(6) = Q33), integer results and statuses are
!> integer(c_int). Then a few Fortran-friendly wrappers: pw85_contact (μ²
!> and λ as scalars, the sizes of the arrays checked), pw85_message and
!> pw85_library_version (the C strings as Fortran strings).
!>
!> Ellipses (pw85_2d.h, @since 2.5.0): the functions pw85_2d_* under their
!> C names, over vectors of PW85_2D_DIM = 2 and forms of PW85_2D_SYM = 3,
!> q(1) = Q11, q(2) = Q12, q(3) = Q22; and pw85_2d_contact, the
!> counterpart of pw85_contact.
module pw85
  use, intrinsic :: iso_c_binding, only: c_char, c_double, c_int, c_ptr, &
                                         c_null_char, c_associated, &
                                         c_f_pointer, c_size_t
  implicit none
  private

  !> The dimension of space, and the number of stored entries of a
  !> symmetric matrix.
  integer, parameter, public :: PW85_DIM = 3, PW85_SYM = 6
  !> The parameters of the search, as built (pw85.h).
  real(c_double), parameter, public :: PW85_LAMBDA_ATOL = 1e-6_c_double
  integer(c_int), parameter, public :: PW85_MAX_ITER = 25, PW85_NR_ITER = 3
  !> Status codes (pw85.h): values never change.
  integer(c_int), parameter, public :: PW85_SUCCESS = 0, PW85_EFAULT = 1, &
    PW85_EDOM = 2, PW85_ENOTPOSDEF = 3, PW85_ERANGE = 4, PW85_ENOMEM = 5, &
    PW85_ENOCONV = 6, PW85_EINVAL = 7, PW85_ECANCELLED = 8
  !> Tolerance of the ellipsoid constructors (pw85.h, @since 2.2.0).
  real(c_double), parameter, public :: PW85_UNIT_TOL = 1e-6_c_double
  !> Offsets (from 0, as in C) into the outputs of pw85_contact_geometry
  !> and pw85_contact_derivatives (@since 2.2.0): add 1 to index them.
  integer, parameter, public :: PW85_GEOM_MU2 = 0, PW85_GEOM_LAMBDA = 1, &
    PW85_GEOM_POINT = 2, PW85_GEOM_NORMAL = 5, PW85_GEOM_SIZE = 8
  integer, parameter, public :: PW85_DERIV_R12 = 0, PW85_DERIV_ROT1 = 3, &
    PW85_DERIV_ROT2 = 6, PW85_DERIV_Q1 = 9, PW85_DERIV_Q2 = 15, &
    PW85_DERIV_SIZE = 21
  !> Ellipses (pw85_2d.h, @since 2.5.0): the sizes of a vector and of a
  !> form, and the offsets (from 0, as in C: add 1 to index) into the
  !> outputs of pw85_2d_contact_geometry and pw85_2d_contact_derivatives.
  integer, parameter, public :: PW85_2D_DIM = 2, PW85_2D_SYM = 3
  integer, parameter, public :: PW85_2D_GEOM_MU2 = 0, &
    PW85_2D_GEOM_LAMBDA = 1, PW85_2D_GEOM_POINT = 2, &
    PW85_2D_GEOM_NORMAL = 4, PW85_2D_GEOM_SIZE = 6
  integer, parameter, public :: PW85_2D_DERIV_R12 = 0, &
    PW85_2D_DERIV_THETA1 = 2, PW85_2D_DERIV_THETA2 = 3, &
    PW85_2D_DERIV_Q1 = 4, PW85_2D_DERIV_Q2 = 7, PW85_2D_DERIV_SIZE = 10

  public :: pw85_strerror, pw85_version, pw85__cholesky_decomp, &
            pw85__cholesky_solve, pw85_spheroid, pw85_f_neg, &
            pw85__residual, pw85_contact_function, pw85_overlap, &
            pw85_ellipsoid_rotation, pw85_ellipsoid_quaternion, &
            pw85_principal_axes, pw85_contact_geometry, &
            pw85_contact_derivatives, pw85_batch_threads, &
            pw85_contact_function_batch, pw85_overlap_batch, &
            pw85_contact_geometry_batch, pw85_contact_derivatives_batch, &
            pw85_spheroid_batch, pw85_ellipsoid_rotation_batch, &
            pw85_ellipsoid_quaternion_batch, pw85_principal_axes_batch, &
            pw85_spheroid_checked, pw85_principal_axes_quaternion, &
            pw85_principal_axes_quaternion_batch
  public :: pw85_2d_f_neg, pw85_2d_contact_function, pw85_2d_overlap, &
            pw85_2d_contact_geometry, pw85_2d_contact_derivatives, &
            pw85_2d_ellipse, pw85_2d_principal_axes, &
            pw85_2d_contact_function_batch, pw85_2d_overlap_batch, &
            pw85_2d_contact_geometry_batch, &
            pw85_2d_contact_derivatives_batch, pw85_2d_ellipse_batch, &
            pw85_2d_principal_axes_batch
  public :: pw85_contact, pw85_message, pw85_library_version
  public :: pw85_2d_contact

  interface
    !> A static message naming a status code.
    type(c_ptr) function pw85_strerror(status) bind(C, name='pw85_strerror')
      import :: c_int, c_ptr
      integer(c_int), value :: status
    end function

    !> The version of the library loaded, "MAJOR.MINOR.PATCH".
    type(c_ptr) function pw85_version() bind(C, name='pw85_version')
      import :: c_ptr
    end function

    !> A = L·Lᵀ (internal, exposed for testing).
    subroutine pw85__cholesky_decomp(a, l) bind(C, name='pw85__cholesky_decomp')
      import :: c_double, PW85_SYM
      real(c_double), intent(in) :: a(PW85_SYM)
      real(c_double), intent(out) :: l(PW85_SYM)
    end subroutine

    !> Solves L·Lᵀ·x = b (internal, exposed for testing).
    subroutine pw85__cholesky_solve(l, b, x) bind(C, name='pw85__cholesky_solve')
      import :: c_double, PW85_DIM, PW85_SYM
      real(c_double), intent(in) :: l(PW85_SYM), b(PW85_DIM)
      real(c_double), intent(out) :: x(PW85_DIM)
    end subroutine

    !> The quadratic form of a spheroid: Q = a²·I + (c² − a²)·n·nᵀ.
    subroutine pw85_spheroid(a, c, n, q) bind(C, name='pw85_spheroid')
      import :: c_double, PW85_DIM, PW85_SYM
      real(c_double), value :: a, c
      real(c_double), intent(in) :: n(PW85_DIM)
      real(c_double), intent(out) :: q(PW85_SYM)
    end subroutine

    !> pw85_spheroid with its preconditions checked (a > 0, c > 0,
    !> |‖n‖² − 1| ≤ PW85_UNIT_TOL): PW85_SUCCESS, PW85_EDOM, PW85_EINVAL or
    !> PW85_ERANGE; q written on success only. Prefer it to pw85_spheroid.
    integer(c_int) function pw85_spheroid_checked(a, c, n, q) &
        bind(C, name='pw85_spheroid_checked')
      import :: c_double, c_int, PW85_DIM, PW85_SYM
      real(c_double), value :: a, c
      real(c_double), intent(in) :: n(PW85_DIM)
      real(c_double), intent(inout) :: q(PW85_SYM)
    end function

    !> −f(λ); params = r12(3), q1(6), q2(6).
    real(c_double) function pw85_f_neg(lambda, params) bind(C, name='pw85_f_neg')
      import :: c_double, PW85_DIM, PW85_SYM
      real(c_double), value :: lambda
      real(c_double), intent(in) :: params(PW85_DIM + 2 * PW85_SYM)
    end function

    !> f(λ), g(λ), g′(λ) (internal, exposed for testing).
    subroutine pw85__residual(lambda, r12, q1, q2, out) &
        bind(C, name='pw85__residual')
      import :: c_double, PW85_DIM, PW85_SYM
      real(c_double), value :: lambda
      real(c_double), intent(in) :: r12(PW85_DIM), q1(PW85_SYM), q2(PW85_SYM)
      real(c_double), intent(out) :: out(3)
    end subroutine

    !> μ² and λ: out(1) = μ², out(2) = λ; returns a status.
    integer(c_int) function pw85_contact_function(r12, q1, q2, out) &
        bind(C, name='pw85_contact_function')
      import :: c_double, c_int, PW85_DIM, PW85_SYM
      real(c_double), intent(in) :: r12(PW85_DIM), q1(PW85_SYM), q2(PW85_SYM)
      real(c_double), intent(inout) :: out(2)
    end function

    !> The certified sign of μ² − 1: result = −1, 0 or +1; returns a status.
    integer(c_int) function pw85_overlap(r12, q1, q2, result) &
        bind(C, name='pw85_overlap')
      import :: c_double, c_int, PW85_DIM, PW85_SYM
      real(c_double), intent(in) :: r12(PW85_DIM), q1(PW85_SYM), q2(PW85_SYM)
      integer(c_int), intent(inout) :: result
    end function

    !> Q = R·diag(a²)·Rᵀ, rot(3·i + j + 1) = R_ij (@since 2.2.0). Note that
    !> a Fortran array r(3, 3) passed as rot holds Rᵀ (pw85.h).
    integer(c_int) function pw85_ellipsoid_rotation(a, rot, q) &
        bind(C, name='pw85_ellipsoid_rotation')
      import :: c_double, c_int, PW85_DIM, PW85_SYM
      real(c_double), intent(in) :: a(PW85_DIM), rot(PW85_DIM * PW85_DIM)
      real(c_double), intent(inout) :: q(PW85_SYM)
    end function

    !> Q from semi-axes and a unit quaternion p = (w, x, y, z)
    !> (@since 2.2.0).
    integer(c_int) function pw85_ellipsoid_quaternion(a, p, q) &
        bind(C, name='pw85_ellipsoid_quaternion')
      import :: c_double, c_int, PW85_DIM, PW85_SYM
      real(c_double), intent(in) :: a(PW85_DIM), p(4)
      real(c_double), intent(inout) :: q(PW85_SYM)
    end function

    !> Semi-axes (decreasing) and rotation of Q (@since 2.2.0).
    integer(c_int) function pw85_principal_axes(q, a, rot) &
        bind(C, name='pw85_principal_axes')
      import :: c_double, c_int, PW85_DIM, PW85_SYM
      real(c_double), intent(in) :: q(PW85_SYM)
      real(c_double), intent(inout) :: a(PW85_DIM), rot(PW85_DIM * PW85_DIM)
    end function

    !> μ², λ, the contact point and the normal (@since 2.2.0).
    integer(c_int) function pw85_contact_geometry(r12, q1, q2, out) &
        bind(C, name='pw85_contact_geometry')
      import :: c_double, c_int, PW85_DIM, PW85_SYM, PW85_GEOM_SIZE
      real(c_double), intent(in) :: r12(PW85_DIM), q1(PW85_SYM), q2(PW85_SYM)
      real(c_double), intent(inout) :: out(PW85_GEOM_SIZE)
    end function

    !> pw85_contact_geometry and the first derivatives of μ²
    !> (@since 2.2.0).
    integer(c_int) function pw85_contact_derivatives(r12, q1, q2, geometry, d) &
        bind(C, name='pw85_contact_derivatives')
      import :: c_double, c_int, PW85_DIM, PW85_SYM, PW85_GEOM_SIZE, &
                PW85_DERIV_SIZE
      real(c_double), intent(in) :: r12(PW85_DIM), q1(PW85_SYM), q2(PW85_SYM)
      real(c_double), intent(inout) :: geometry(PW85_GEOM_SIZE), &
                                       d(PW85_DERIV_SIZE)
    end function

    ! Batches of n pairs (@since 2.2.0; pw85.h for the contract). Arrays
    ! are contiguous, the pairs one after the other (r12(3, n), q1(6, n),
    ! ... in Fortran); a stride is the number of doubles from one pair's
    ! input to the next (0: one input for every pair); status(n) must be
    ! given here (C accepts NULL).
    !> The number of threads a batch call would use.
    integer(c_int) function pw85_batch_threads(threads, n) &
        bind(C, name='pw85_batch_threads')
      import :: c_int, c_size_t
      integer(c_int), value :: threads
      integer(c_size_t), value :: n
    end function

    !> pw85_contact_function for n pairs: out(2, n).
    integer(c_int) function pw85_contact_function_batch(n, r12, r12_stride, &
        q1, q1_stride, q2, q2_stride, out, status, threads) &
        bind(C, name='pw85_contact_function_batch')
      import :: c_double, c_int, c_size_t
      integer(c_size_t), value :: n, r12_stride, q1_stride, q2_stride
      real(c_double), intent(in) :: r12(*), q1(*), q2(*)
      real(c_double), intent(inout) :: out(*)
      integer(c_int), intent(inout) :: status(*)
      integer(c_int), value :: threads
    end function

    !> pw85_overlap for n pairs: result(n).
    integer(c_int) function pw85_overlap_batch(n, r12, r12_stride, q1, &
        q1_stride, q2, q2_stride, result, status, threads) &
        bind(C, name='pw85_overlap_batch')
      import :: c_double, c_int, c_size_t
      integer(c_size_t), value :: n, r12_stride, q1_stride, q2_stride
      real(c_double), intent(in) :: r12(*), q1(*), q2(*)
      integer(c_int), intent(inout) :: result(*), status(*)
      integer(c_int), value :: threads
    end function

    !> pw85_contact_geometry for n pairs: out(PW85_GEOM_SIZE, n).
    integer(c_int) function pw85_contact_geometry_batch(n, r12, r12_stride, &
        q1, q1_stride, q2, q2_stride, out, status, threads) &
        bind(C, name='pw85_contact_geometry_batch')
      import :: c_double, c_int, c_size_t
      integer(c_size_t), value :: n, r12_stride, q1_stride, q2_stride
      real(c_double), intent(in) :: r12(*), q1(*), q2(*)
      real(c_double), intent(inout) :: out(*)
      integer(c_int), intent(inout) :: status(*)
      integer(c_int), value :: threads
    end function

    !> pw85_contact_derivatives for n pairs: geometry(PW85_GEOM_SIZE, n),
    !> d(PW85_DERIV_SIZE, n).
    integer(c_int) function pw85_contact_derivatives_batch(n, r12, &
        r12_stride, q1, q1_stride, q2, q2_stride, geometry, d, status, &
        threads) bind(C, name='pw85_contact_derivatives_batch')
      import :: c_double, c_int, c_size_t
      integer(c_size_t), value :: n, r12_stride, q1_stride, q2_stride
      real(c_double), intent(in) :: r12(*), q1(*), q2(*)
      real(c_double), intent(inout) :: geometry(*), d(*)
      integer(c_int), intent(inout) :: status(*)
      integer(c_int), value :: threads
    end function

    !> Semi-axes (decreasing) and unit quaternion p = (w, x, y, z), scalar
    !> first (OVITO and SciPy write (x, y, z, w)), of a form.
    integer(c_int) function pw85_principal_axes_quaternion(q, a, p) &
        bind(C, name='pw85_principal_axes_quaternion')
      import :: c_double, c_int, PW85_DIM, PW85_SYM
      real(c_double), intent(in) :: q(PW85_SYM)
      real(c_double), intent(inout) :: a(PW85_DIM), p(4)
    end function

    !> pw85_principal_axes_quaternion for n forms: a(PW85_DIM, n), p(4, n).
    integer(c_int) function pw85_principal_axes_quaternion_batch(n, q, &
        q_stride, a, p, status, threads) &
        bind(C, name='pw85_principal_axes_quaternion_batch')
      import :: c_double, c_int, c_size_t, PW85_SYM
      integer(c_size_t), value :: n, q_stride
      real(c_double), intent(in) :: q(*)
      real(c_double), intent(inout) :: a(*), p(*)
      integer(c_int), intent(inout) :: status(*)
      integer(c_int), value :: threads
    end function

    !> pw85_spheroid for n spheroids: q(PW85_SYM, n).
    integer(c_int) function pw85_spheroid_batch(n, a, a_stride, c, &
        c_stride, axis, axis_stride, q, status, threads) &
        bind(C, name='pw85_spheroid_batch')
      import :: c_double, c_int, c_size_t
      integer(c_size_t), value :: n, a_stride, c_stride, axis_stride
      real(c_double), intent(in) :: a(*), c(*), axis(*)
      real(c_double), intent(inout) :: q(*)
      integer(c_int), intent(inout) :: status(*)
      integer(c_int), value :: threads
    end function

    !> pw85_ellipsoid_rotation for n ellipsoids: q(PW85_SYM, n); each
    !> rotation's 9 entries row by row (a Fortran R(3, 3) holds Rᵀ so).
    integer(c_int) function pw85_ellipsoid_rotation_batch(n, a, a_stride, &
        rot, rot_stride, q, status, threads) &
        bind(C, name='pw85_ellipsoid_rotation_batch')
      import :: c_double, c_int, c_size_t
      integer(c_size_t), value :: n, a_stride, rot_stride
      real(c_double), intent(in) :: a(*), rot(*)
      real(c_double), intent(inout) :: q(*)
      integer(c_int), intent(inout) :: status(*)
      integer(c_int), value :: threads
    end function

    !> pw85_ellipsoid_quaternion for n ellipsoids: q(PW85_SYM, n).
    integer(c_int) function pw85_ellipsoid_quaternion_batch(n, a, a_stride, &
        p, p_stride, q, status, threads) &
        bind(C, name='pw85_ellipsoid_quaternion_batch')
      import :: c_double, c_int, c_size_t
      integer(c_size_t), value :: n, a_stride, p_stride
      real(c_double), intent(in) :: a(*), p(*)
      real(c_double), intent(inout) :: q(*)
      integer(c_int), intent(inout) :: status(*)
      integer(c_int), value :: threads
    end function

    !> pw85_principal_axes for n forms: a(3, n), rot(9, n).
    integer(c_int) function pw85_principal_axes_batch(n, q, q_stride, a, &
        rot, status, threads) bind(C, name='pw85_principal_axes_batch')
      import :: c_double, c_int, c_size_t
      integer(c_size_t), value :: n, q_stride
      real(c_double), intent(in) :: q(*)
      real(c_double), intent(inout) :: a(*), rot(*)
      integer(c_int), intent(inout) :: status(*)
      integer(c_int), value :: threads
    end function

    ! Ellipses (pw85_2d.h, @since 2.5.0; the contracts are there).
    !> −f(λ) for two ellipses; params = r12(2), q1(3), q2(3).
    real(c_double) function pw85_2d_f_neg(lambda, params) &
        bind(C, name='pw85_2d_f_neg')
      import :: c_double, PW85_2D_DIM, PW85_2D_SYM
      real(c_double), value :: lambda
      real(c_double), intent(in) :: params(PW85_2D_DIM + 2 * PW85_2D_SYM)
    end function

    !> μ² and λ of two ellipses: out(1) = μ², out(2) = λ; returns a
    !> status.
    integer(c_int) function pw85_2d_contact_function(r12, q1, q2, out) &
        bind(C, name='pw85_2d_contact_function')
      import :: c_double, c_int, PW85_2D_DIM, PW85_2D_SYM
      real(c_double), intent(in) :: r12(PW85_2D_DIM), q1(PW85_2D_SYM), &
                                    q2(PW85_2D_SYM)
      real(c_double), intent(inout) :: out(2)
    end function

    !> The certified sign of μ² − 1 for two ellipses: result = −1, 0 or
    !> +1; returns a status.
    integer(c_int) function pw85_2d_overlap(r12, q1, q2, result) &
        bind(C, name='pw85_2d_overlap')
      import :: c_double, c_int, PW85_2D_DIM, PW85_2D_SYM
      real(c_double), intent(in) :: r12(PW85_2D_DIM), q1(PW85_2D_SYM), &
                                    q2(PW85_2D_SYM)
      integer(c_int), intent(inout) :: result
    end function

    !> μ², λ, the contact point x − c1 and the normal:
    !> out(PW85_2D_GEOM_SIZE).
    integer(c_int) function pw85_2d_contact_geometry(r12, q1, q2, out) &
        bind(C, name='pw85_2d_contact_geometry')
      import :: c_double, c_int, PW85_2D_DIM, PW85_2D_SYM, PW85_2D_GEOM_SIZE
      real(c_double), intent(in) :: r12(PW85_2D_DIM), q1(PW85_2D_SYM), &
                                    q2(PW85_2D_SYM)
      real(c_double), intent(inout) :: out(PW85_2D_GEOM_SIZE)
    end function

    !> pw85_2d_contact_geometry and the derivatives of μ² (∂μ²/∂r12,
    !> ∂μ²/∂θ1, ∂μ²/∂θ2, ∂μ²/∂q1, ∂μ²/∂q2): d(PW85_2D_DERIV_SIZE).
    integer(c_int) function pw85_2d_contact_derivatives(r12, q1, q2, &
        geometry, d) bind(C, name='pw85_2d_contact_derivatives')
      import :: c_double, c_int, PW85_2D_DIM, PW85_2D_SYM, &
                PW85_2D_GEOM_SIZE, PW85_2D_DERIV_SIZE
      real(c_double), intent(in) :: r12(PW85_2D_DIM), q1(PW85_2D_SYM), &
                                    q2(PW85_2D_SYM)
      real(c_double), intent(inout) :: geometry(PW85_2D_GEOM_SIZE), &
                                       d(PW85_2D_DERIV_SIZE)
    end function

    !> Q = R(θ)·diag(a(1)², a(2)²)·R(θ)ᵀ: a(1) along (cos θ, sin θ).
    integer(c_int) function pw85_2d_ellipse(a, theta, q) &
        bind(C, name='pw85_2d_ellipse')
      import :: c_double, c_int, PW85_2D_DIM, PW85_2D_SYM
      real(c_double), intent(in) :: a(PW85_2D_DIM)
      real(c_double), value :: theta
      real(c_double), intent(inout) :: q(PW85_2D_SYM)
    end function

    !> Semi-axes (decreasing) and the angle θ in (−π/2, π/2] of a(1).
    integer(c_int) function pw85_2d_principal_axes(q, a, theta) &
        bind(C, name='pw85_2d_principal_axes')
      import :: c_double, c_int, PW85_2D_DIM, PW85_2D_SYM
      real(c_double), intent(in) :: q(PW85_2D_SYM)
      real(c_double), intent(inout) :: a(PW85_2D_DIM), theta
    end function

    ! Batches (as those of pw85.h above: contiguous arrays, strides in
    ! doubles, status(n) required here).
    !> pw85_2d_contact_function for n pairs: r12(2, n), q1(3, n), q2(3, n)
    !> (or one each, stride 0), out(2, n).
    integer(c_int) function pw85_2d_contact_function_batch(n, r12, &
        r12_stride, q1, q1_stride, q2, q2_stride, out, status, threads) &
        bind(C, name='pw85_2d_contact_function_batch')
      import :: c_double, c_int, c_size_t
      integer(c_size_t), value :: n, r12_stride, q1_stride, q2_stride
      real(c_double), intent(in) :: r12(*), q1(*), q2(*)
      real(c_double), intent(inout) :: out(*)
      integer(c_int), intent(inout) :: status(*)
      integer(c_int), value :: threads
    end function

    !> pw85_2d_overlap for n pairs: result(n).
    integer(c_int) function pw85_2d_overlap_batch(n, r12, r12_stride, q1, &
        q1_stride, q2, q2_stride, result, status, threads) &
        bind(C, name='pw85_2d_overlap_batch')
      import :: c_double, c_int, c_size_t
      integer(c_size_t), value :: n, r12_stride, q1_stride, q2_stride
      real(c_double), intent(in) :: r12(*), q1(*), q2(*)
      integer(c_int), intent(inout) :: result(*), status(*)
      integer(c_int), value :: threads
    end function

    !> pw85_2d_contact_geometry for n pairs: out(PW85_2D_GEOM_SIZE, n).
    integer(c_int) function pw85_2d_contact_geometry_batch(n, r12, &
        r12_stride, q1, q1_stride, q2, q2_stride, out, status, threads) &
        bind(C, name='pw85_2d_contact_geometry_batch')
      import :: c_double, c_int, c_size_t
      integer(c_size_t), value :: n, r12_stride, q1_stride, q2_stride
      real(c_double), intent(in) :: r12(*), q1(*), q2(*)
      real(c_double), intent(inout) :: out(*)
      integer(c_int), intent(inout) :: status(*)
      integer(c_int), value :: threads
    end function

    !> pw85_2d_contact_derivatives for n pairs:
    !> geometry(PW85_2D_GEOM_SIZE, n), d(PW85_2D_DERIV_SIZE, n).
    integer(c_int) function pw85_2d_contact_derivatives_batch(n, r12, &
        r12_stride, q1, q1_stride, q2, q2_stride, geometry, d, status, &
        threads) bind(C, name='pw85_2d_contact_derivatives_batch')
      import :: c_double, c_int, c_size_t
      integer(c_size_t), value :: n, r12_stride, q1_stride, q2_stride
      real(c_double), intent(in) :: r12(*), q1(*), q2(*)
      real(c_double), intent(inout) :: geometry(*), d(*)
      integer(c_int), intent(inout) :: status(*)
      integer(c_int), value :: threads
    end function

    !> pw85_2d_ellipse for n ellipses: a(2, n), theta(n) (strides 2 and 1,
    !> or 0), q(3, n).
    integer(c_int) function pw85_2d_ellipse_batch(n, a, a_stride, theta, &
        theta_stride, q, status, threads) &
        bind(C, name='pw85_2d_ellipse_batch')
      import :: c_double, c_int, c_size_t
      integer(c_size_t), value :: n, a_stride, theta_stride
      real(c_double), intent(in) :: a(*), theta(*)
      real(c_double), intent(inout) :: q(*)
      integer(c_int), intent(inout) :: status(*)
      integer(c_int), value :: threads
    end function

    !> pw85_2d_principal_axes for n forms: a(2, n), theta(n).
    integer(c_int) function pw85_2d_principal_axes_batch(n, q, q_stride, &
        a, theta, status, threads) &
        bind(C, name='pw85_2d_principal_axes_batch')
      import :: c_double, c_int, c_size_t
      integer(c_size_t), value :: n, q_stride
      real(c_double), intent(in) :: q(*)
      real(c_double), intent(inout) :: a(*), theta(*)
      integer(c_int), intent(inout) :: status(*)
      integer(c_int), value :: threads
    end function
  end interface

contains

  !> The contact function of two ellipsoids: pw85_contact_function with
  !> μ² and λ as scalars. Arrays of any stride are accepted; a wrong size
  !> returns PW85_EINVAL. mu2 and lambda are written on PW85_SUCCESS and
  !> PW85_ERANGE only (μ² = +Inf), as in C.
  integer(c_int) function pw85_contact(r12, q1, q2, mu2, lambda) result(status)
    real(c_double), intent(in) :: r12(:), q1(:), q2(:)
    real(c_double), intent(inout) :: mu2, lambda
    real(c_double) :: out(2)
    if (size(r12) /= PW85_DIM .or. size(q1) /= PW85_SYM .or. &
        size(q2) /= PW85_SYM) then
      status = PW85_EINVAL
      return
    end if
    out = [mu2, lambda]
    status = pw85_contact_function(r12, q1, q2, out)
    mu2 = out(1)
    lambda = out(2)
  end function

  !> The contact function of two ellipses: pw85_2d_contact_function with
  !> μ² and λ as scalars, as pw85_contact (a wrong size: PW85_EINVAL).
  integer(c_int) function pw85_2d_contact(r12, q1, q2, mu2, lambda) &
      result(status)
    real(c_double), intent(in) :: r12(:), q1(:), q2(:)
    real(c_double), intent(inout) :: mu2, lambda
    real(c_double) :: out(2)
    if (size(r12) /= PW85_2D_DIM .or. size(q1) /= PW85_2D_SYM .or. &
        size(q2) /= PW85_2D_SYM) then
      status = PW85_EINVAL
      return
    end if
    out = [mu2, lambda]
    status = pw85_2d_contact_function(r12, q1, q2, out)
    mu2 = out(1)
    lambda = out(2)
  end function

  !> The message of a status code, as a Fortran string.
  function pw85_message(status) result(message)
    integer(c_int), intent(in) :: status
    character(len=:), allocatable :: message
    message = from_c(pw85_strerror(status))
  end function

  !> The version of the library loaded, as a Fortran string.
  function pw85_library_version() result(version)
    character(len=:), allocatable :: version
    version = from_c(pw85_version())
  end function

  !> A Fortran copy of a static NUL-terminated C string ("" for NULL).
  function from_c(p) result(s)
    type(c_ptr), intent(in) :: p
    character(len=:), allocatable :: s
    character(kind=c_char), pointer :: chars(:)
    integer :: n
    if (.not. c_associated(p)) then
      s = ''
      return
    end if
    ! The strings of pw85 are short; 4096 bounds the search, not the
    ! length of any of them.
    call c_f_pointer(p, chars, [4096])
    n = 0
    do while (n < size(chars))
      if (chars(n + 1) == c_null_char) exit
      n = n + 1
    end do
    allocate(character(len=n) :: s)
    s = transfer(chars(1:n), s)
  end function

end module pw85
