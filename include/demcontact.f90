! demcontact for Fortran: `use demcontact`.
!
! Everything of the C API is here through the generated module demcontact_c (include/demcontact_c.f90,
! kept in step with include/demcontact.h by `cargo test --test bindings`):
!   * the C functions themselves, callable directly; they return a status, e.g.
!       stat = dc_alpha_from_e(0.5_c_double, 1.5_c_double, DC_END_FORCE, alpha)
!   * every constant as a named parameter (DC_OK, DC_ERR_*, DC_END_*) and every struct as a
!     bind(c) derived type;
!   * impure elemental wrappers without the dc_ prefix for the scalar functions, which work on
!     arrays and return the status in an optional `stat` (the output is NaN on error):
!       call alpha_from_e(e_array, 1.5_c_double, DC_END_FORCE, alpha_array, stat_array)
! This file adds what needs Fortran idiom by hand: status and version strings.
module demcontact
  use, intrinsic :: iso_c_binding
  use demcontact_c
  implicit none
  public

contains

  !> Normal forces of n = size(overlap) contacts of one pair (dc_normal_force_batch) from
  !> contiguous arrays; every array must have at least size(overlap) elements.
  subroutine normal_force_batch(pair, overlap, vn, r_eff, m_eff, force, stat)
    type(dc_pair), intent(in) :: pair
    real(c_double), intent(in), contiguous :: overlap(:), vn(:), r_eff(:), m_eff(:)
    real(c_double), intent(out), contiguous :: force(:)
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    integer :: n
    n = size(overlap)
    if (size(vn) < n .or. size(r_eff) < n .or. size(m_eff) < n .or. size(force) < n) then
      s = DC_ERR_BUFFER_TOO_SHORT
    else
      s = dc_normal_force_batch(pair, int(n, c_size_t), overlap, vn, r_eff, m_eff, force)
    end if
    if (present(stat)) stat = s
  end subroutine normal_force_batch

  !> Samples one power-law collision at n = size(t) points (dc_contact_trajectory); delta, v and
  !> force must be at least as long as t. stat: DC_OK or the C status.
  subroutine contact_trajectory(p, alpha, v0, omega0, mass, criterion, level, t, delta, v, force, stat)
    real(c_double), intent(in) :: p, alpha, v0, omega0, mass
    integer(c_int32_t), intent(in) :: criterion, level
    real(c_double), intent(out), contiguous :: t(:), delta(:), v(:), force(:)
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    integer :: n
    n = size(t)
    if (size(delta) < n .or. size(v) < n .or. size(force) < n) then
      s = DC_ERR_BUFFER_TOO_SHORT
    else
      s = dc_contact_trajectory(p, alpha, v0, omega0, mass, criterion, level, int(n, c_size_t), &
          t, delta, v, force, int(n, c_size_t))
    end if
    if (present(stat)) stat = s
  end subroutine contact_trajectory

  !> The message of a status code as a Fortran string.
  function dc_status_message(status) result(msg)
    integer(c_int32_t), intent(in) :: status
    character(len=:), allocatable :: msg
    msg = c_string(dc_status_str(status))
  end function dc_status_message

  !> The library version as a Fortran string.
  function dc_version_string() result(v)
    character(len=:), allocatable :: v
    v = c_string(dc_version())
  end function dc_version_string

  !> Copies a static NUL-terminated C string.
  function c_string(p) result(s)
    type(c_ptr), intent(in) :: p
    character(len=:), allocatable :: s
    character(kind=c_char), pointer :: chars(:)
    integer :: n
    interface
      pure function c_strlen(str) bind(c, name='strlen')
        import :: c_ptr, c_size_t
        type(c_ptr), value :: str
        integer(c_size_t) :: c_strlen
      end function c_strlen
    end interface
    if (.not. c_associated(p)) then
      s = ''
      return
    end if
    n = int(c_strlen(p))
    call c_f_pointer(p, chars, [n])
    allocate(character(len=n) :: s)
    s = transfer(chars(1:n), s)
  end function c_string

end module demcontact
