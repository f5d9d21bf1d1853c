program minimal
  use demcontact
  implicit none
  real(c_double) :: alpha(3)
  integer(c_int32_t) :: stat(3)
  ! Elemental over an array of restitutions; the status comes back per element.
  call alpha_from_e([0.3_c_double, 0.5_c_double, 0.0_c_double], 1.5_c_double, DC_END_FORCE, alpha, stat)
  print '(2F18.15)', alpha(1:2)
  if (stat(3) /= DC_ERR_RESTITUTION_RANGE) error stop 1
  print '(A)', dc_status_message(stat(3))
end program minimal
