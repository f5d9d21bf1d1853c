! Fortran test of `use demcontact`: the bind(c) interfaces and elemental wrappers compute the same
! numbers as the C tests (with --table it prints the common table that ctest compares bit for bit
! with c_tests/common_table.c and the C++ test), bad input is reported through `stat`, and the
! named constants and struct layouts agree with the C header (abi_expect vs abi_probe.c).
program test_fortran
  use, intrinsic :: iso_c_binding
  use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
  use demcontact
  use abi_expect
  implicit none
  real(c_double), parameter :: ps(4) = [1.0_c_double, 1.5_c_double, 2.0_c_double, 3.0_c_double]
  real(c_double), parameter :: es(5) = [0.1_c_double, 0.3_c_double, 0.5_c_double, 0.7_c_double, 0.9_c_double]
  real(c_double), parameter :: pi = 3.14159265358979323846_c_double
  real(c_double) :: a, e, k, dt, want, av(5), ev(5), l
  integer(c_int32_t) :: s, s2, c, stats(5)
  integer :: i, j, passed, failed
  character(len=16) :: arg

  call get_command_argument(1, arg)
  if (trim(arg) == '--table') then
    do c = 0, 1
      do i = 1, 4
        do j = 1, 5
          s = dc_alpha_from_e(es(j), ps(i), c, a)
          s2 = dc_e_from_alpha(a, ps(i), c, e)
          write (*, '(I0,1X,I0,1X,I0,1X,I0,1X,I0)') c, s, s2, transfer(a, 0_c_int64_t), transfer(e, 0_c_int64_t)
        end do
      end do
    end do
    s = dc_hertz_stiffness(63e9_c_double, 0.23_c_double, 1e-3_c_double, 70e9_c_double, 0.3_c_double, 2e-3_c_double, k)
    write (*, '(I0,1X,I0)') s, transfer(k, 0_c_int64_t)
    s = dc_dt_crit(1.5_c_double, 2.0_c_double, 1e4_c_double, dt)
    write (*, '(I0,1X,I0)') s, transfer(dt, 0_c_int64_t)
    write (*, '(I0)') dc_alpha_from_e(1.5_c_double, 1.5_c_double, DC_END_FORCE, a)
    stop
  end if

  passed = 0
  failed = 0
  ! Overlap-end closed form, computed here independently.
  do i = 1, 4
    do j = 1, 5
      l = -log(es(j))
      want = sqrt(2.0_c_double * (ps(i) + 1.0_c_double)) * l / sqrt(pi * pi + l * l)
      s = dc_alpha_from_e(es(j), ps(i), DC_END_OVERLAP, a)
      call check(s == DC_OK .and. abs(a - want) <= 1e-14_c_double * want, 'overlap alpha closed form')
    end do
  end do
  ! Elemental wrapper over an array, both criteria, round trip.
  call alpha_from_e(es, 1.5_c_double, DC_END_FORCE, av, stats)
  call check(all(stats == DC_OK), 'elemental alpha_from_e status')
  call e_from_alpha(av, 1.5_c_double, DC_END_FORCE, ev, stats)
  call check(all(abs(ev - es) <= 1e-14_c_double * es), 'elemental round trip')
  ! Bad input: status through stat, NaN in the output.
  call alpha_from_e(0.0_c_double, 1.5_c_double, DC_END_FORCE, a, s)
  call check(s == DC_ERR_RESTITUTION_RANGE .and. ieee_is_nan(a), 'e = 0 rejected')
  s = dc_alpha_from_e(0.5_c_double, 0.5_c_double, DC_END_FORCE, a)
  call check(s == DC_ERR_EXPONENT_RANGE, 'p < 1 rejected')
  call check(dc_status_message(DC_ERR_EXPONENT_RANGE) == 'force-law exponent p must be >= 1', 'status message')
  call check(len(dc_version_string()) > 0, 'version string')
  ! Hertz helper against the formula.
  s = dc_hertz_stiffness(63e9_c_double, 0.23_c_double, 1e-3_c_double, 63e9_c_double, 0.23_c_double, 1e-3_c_double, k)
  want = 4.0_c_double / 3.0_c_double * 63e9_c_double / (2.0_c_double * (1.0_c_double - 0.23_c_double**2)) * sqrt(0.5e-3_c_double)
  call check(s == DC_OK .and. abs(k - want) <= 1e-14_c_double * want, 'hertz stiffness')
  ! Force kernel: pair constructor, elemental force over an array, batch wrapper, same numbers.
  block
    type(dc_pair) :: pair
    real(c_double) :: d(4), vn(4), r(4), m(4), fe(4), fb(4), fc
    call pair_hertz(63e9_c_double, 0.23_c_double, 63e9_c_double, 0.23_c_double, 0.5_c_double, DC_END_FORCE, pair, s)
    call check(s == DC_OK, 'pair_hertz')
    d = [1e-6_c_double, 2e-6_c_double, 0.0_c_double, -1e-6_c_double]
    vn = [0.1_c_double, -0.2_c_double, 0.1_c_double, 0.1_c_double]
    r = 0.5e-3_c_double
    m = 1e-5_c_double
    fe = normal_force(pair, d, vn, r, m)
    call normal_force_batch(pair, d, vn, r, m, fb, s)
    call check(s == DC_OK .and. all(fe == fb), 'elemental force equals batch')
    call check(fe(3) == 0.0_c_double .and. fe(4) == 0.0_c_double .and. fe(1) > 0.0_c_double, 'force signs')
    s = dc_normal_force_checked(pair, d(1), vn(1), r(1), m(1), fc)
    call check(s == DC_OK .and. fc == fe(1), 'checked force')
    call normal_force_batch(pair, d, vn(1:2), r, m, fb, s)
    call check(s == DC_ERR_BUFFER_TOO_SHORT, 'short batch array')
  end block
  ! Power-law calculus: trajectory into Fortran arrays ends at the duration; energy partition sums to 1.
  block
    real(c_double) :: tt(101), dd(101), vv(101), ff(101), tau, alpha
    type(dc_energy) :: en
    s = dc_alpha_from_e(0.5_c_double, 1.5_c_double, DC_END_FORCE, alpha)
    call contact_trajectory(1.5_c_double, alpha, 1.0_c_double, 100.0_c_double, 1e-3_c_double, DC_END_FORCE, &
        DC_LEVEL_MAX, tt, dd, vv, ff, s)
    call check(s == DC_OK, 'trajectory status')
    s = dc_contact_duration(1.5_c_double, alpha, 1.0_c_double, 100.0_c_double, DC_END_FORCE, tau)
    call check(s == DC_OK .and. abs(tt(101) - tau) <= 1e-13_c_double * tau, 'trajectory ends at tau')
    call check(abs(vv(101) + 0.5_c_double) <= 1e-12_c_double, 'exit speed is e v0')
    call contact_trajectory(1.5_c_double, alpha, 1.0_c_double, 100.0_c_double, 1e-3_c_double, DC_END_FORCE, &
        DC_LEVEL_MAX, tt, dd(1:50), vv, ff, s)
    call check(s == DC_ERR_BUFFER_TOO_SHORT, 'short trajectory buffer')
    call energy_partition(1.5_c_double, alpha, DC_END_FORCE, en, s)
    call check(s == DC_OK, 'energy partition')
  end block
  ! Full contact: spec by field name, model, history owned here, one step onto a rigid wall.
  block
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_positive_inf
    type(dc_contact_spec) :: spec
    type(dc_contact_model) :: model
    type(dc_contact_state) :: st
    type(dc_contact_result) :: res
    real(c_double) :: hist(DC_CONTACT_HISTORY_MAX), inf
    integer(c_size_t) :: hl
    inf = ieee_value(1.0_c_double, ieee_positive_inf)
    call check(dc_contact_spec_init(spec) == DC_OK, 'contact spec init')
    spec%normal = DC_NORMAL_HERTZ
    spec%E1 = 63e9_c_double
    spec%nu1 = 0.23_c_double
    spec%E2 = inf
    spec%nu2 = 0.3_c_double
    spec%tangential = DC_TANGENTIAL_MINDLIN
    spec%mu = 0.3_c_double
    call check(dc_contact_model_init(spec, model) == DC_OK, 'contact model init')
    call check(dc_contact_history_len(model, hl) == DC_OK .and. hl == 6, 'contact history length')
    hist = 0.0_c_double
    st%n = [0.0_c_double, 1.0_c_double, 0.0_c_double]
    st%overlap = 1e-6_c_double
    st%v1 = [0.5_c_double, 0.0_c_double, 0.0_c_double]
    st%v2 = 0.0_c_double
    st%w1 = 0.0_c_double
    st%w2 = 0.0_c_double
    st%r1 = 1e-3_c_double
    st%r2 = inf
    st%m1 = 1e-5_c_double
    st%m2 = inf
    s = dc_contact_force(model, st, 1e-8_c_double, hist, int(DC_CONTACT_HISTORY_MAX, c_size_t), res)
    call check(s == DC_OK .and. res%f_n > 0.0_c_double .and. res%ft(1) < 0.0_c_double, 'contact force')
    call check(res%force(2) == res%f_n .and. hist(4) > 0.0_c_double, 'contact force direction and history')
    st%n(2) = 0.5_c_double
    s = dc_contact_force(model, st, 1e-8_c_double, hist, int(DC_CONTACT_HISTORY_MAX, c_size_t), res)
    call check(s == DC_ERR_NOT_UNIT, 'non-unit normal rejected')
  end block
  ! ABI: constants and struct layouts as the C compiler sees them.
  call check_abi()

  write (*, '(A,I0,A,I0,A)') 'test_fortran: ', passed, ' passed, ', failed, ' failed'
  if (failed /= 0) error stop 1

contains

  subroutine check(cond, what)
    logical, intent(in) :: cond
    character(len=*), intent(in) :: what
    if (cond) then
      passed = passed + 1
    else
      failed = failed + 1
      write (*, '(A,A)') 'check failed: ', what
    end if
  end subroutine check

  subroutine check_abi()
    interface
      function dc_probe_n_consts() bind(c)
        import :: c_int32_t
        integer(c_int32_t) :: dc_probe_n_consts
      end function
      function dc_probe_const(i) bind(c)
        import :: c_int32_t, c_int64_t
        integer(c_int32_t), value :: i
        integer(c_int64_t) :: dc_probe_const
      end function
      function dc_probe_n_layout() bind(c)
        import :: c_int32_t
        integer(c_int32_t) :: dc_probe_n_layout
      end function
      function dc_probe_layout(i) bind(c)
        import :: c_int32_t, c_int64_t
        integer(c_int32_t), value :: i
        integer(c_int64_t) :: dc_probe_layout
      end function
    end interface
    integer(c_int64_t) :: v(4096)
    integer :: n, m
    call expected_consts(v, n)
    call check(n == dc_probe_n_consts(), 'number of constants')
    do m = 1, n
      call check(v(m) == dc_probe_const(int(m, c_int32_t)), 'constant value')
    end do
    call expected_layout(v, n)
    call check(n == dc_probe_n_layout(), 'number of layout entries')
    do m = 1, n
      call check(v(m) == dc_probe_layout(int(m, c_int32_t)), 'struct size/offset')
    end do
  end subroutine check_abi

end program test_fortran
