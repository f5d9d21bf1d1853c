! Generated from include/demcontact.h by xtask (xtask/src/fortran.rs): do not edit by hand.
! Regenerate: cargo run -p xtask -- bindings
!
! bind(c) interfaces to every demcontact function, the constants as named parameters, the
! structs as bind(c) derived types, and impure elemental wrappers (status in `stat`) for
! the scalar functions. Use module `demcontact` (include/demcontact.f90), which re-exports it.
module demcontact_c
  use, intrinsic :: iso_c_binding
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
  implicit none
  private :: ieee_value, ieee_quiet_nan

  integer(c_int32_t), parameter :: DC_BUILTIN_LIGGGHTS_HOOKE = 1
  integer(c_int32_t), parameter :: DC_BUILTIN_LIGGGHTS_HERTZ = 2
  integer(c_int32_t), parameter :: DC_BUILTIN_LAMMPS_COEFF_RESTITUTION = 3
  integer(c_int32_t), parameter :: DC_BUILTIN_LAMMPS_TSUJI_HERTZ = 4
  integer(c_int32_t), parameter :: DC_BUILTIN_LAMMPS_TSUJI_HOOKE = 5
  integer(c_int32_t), parameter :: DC_BUILTIN_YADE_VISCEL_EN = 6
  integer(c_int32_t), parameter :: DC_BUILTIN_YADE_MINDLIN_EN = 7
  integer(c_int32_t), parameter :: DC_BUILTIN_YADE_MINDLIN_BETAN = 8
  integer(c_int32_t), parameter :: DC_BUILTIN_LAMMPS_TSUJI_HERTZ_SQRT2 = 9
  integer(c_int32_t), parameter :: DC_BUILTIN_LAMMPS_TSUJI_HOOKE_SQRT2 = 10
  integer(c_int32_t), parameter :: DC_MODEL_POWERLAW = 1
  integer(c_int32_t), parameter :: DC_MODEL_HERTZ = 2
  integer(c_int32_t), parameter :: DC_MODEL_VISCOELASTIC = 3
  integer(c_int32_t), parameter :: DC_MODEL_DMT = 4
  integer(c_int32_t), parameter :: DC_MODEL_ELASTIC_PLASTIC = 5
  integer(c_int32_t), parameter :: DC_MODEL_JKR = 6
  integer(c_int32_t), parameter :: DC_NORMAL_HERTZ = 1
  integer(c_int32_t), parameter :: DC_NORMAL_POWERLAW = 2
  integer(c_int32_t), parameter :: DC_NORMAL_LINEAR = 3
  integer(c_int32_t), parameter :: DC_NORMAL_VISCOELASTIC = 4
  integer(c_int32_t), parameter :: DC_NORMAL_DMT = 5
  integer(c_int32_t), parameter :: DC_NORMAL_ELASTIC_PLASTIC = 6
  integer(c_int32_t), parameter :: DC_NORMAL_JKR = 7
  integer(c_int32_t), parameter :: DC_DAMPING_NONE = 0
  integer(c_int32_t), parameter :: DC_DAMPING_RESTITUTION = 1
  integer(c_int32_t), parameter :: DC_TANGENTIAL_NONE = 0
  integer(c_int32_t), parameter :: DC_TANGENTIAL_LINEAR = 1
  integer(c_int32_t), parameter :: DC_TANGENTIAL_MINDLIN = 2
  integer(c_int32_t), parameter :: DC_TANGENTIAL_MINDLIN_RESCALE = 3
  integer(c_int32_t), parameter :: DC_ROLLING_NONE = 0
  integer(c_int32_t), parameter :: DC_ROLLING_CONSTANT = 1
  integer(c_int32_t), parameter :: DC_ROLLING_EPSD = 2
  integer(c_int32_t), parameter :: DC_TWISTING_NONE = 0
  integer(c_int32_t), parameter :: DC_TWISTING_SDS = 1
  integer(c_int32_t), parameter :: DC_CARRY_ROTATE = 0
  integer(c_int32_t), parameter :: DC_CARRY_PROJECT = 1
  integer(c_int32_t), parameter :: DC_CONTACT_SPEC_VERSION = 1
  integer(c_int32_t), parameter :: DC_CONTACT_HISTORY_MAX = 12
  integer(c_int32_t), parameter :: DC_FIT_MODEL_CONSTANT = 0
  integer(c_int32_t), parameter :: DC_FIT_MODEL_VISCOELASTIC = 1
  integer(c_int32_t), parameter :: DC_PLAN_INPUT_VERSION = 1
  integer(c_int32_t), parameter :: DC_PLAN_FIELD_NONE = 0
  integer(c_int32_t), parameter :: DC_PLAN_FIELD_YOUNGS = 1
  integer(c_int32_t), parameter :: DC_PLAN_FIELD_POISSON = 2
  integer(c_int32_t), parameter :: DC_PLAN_FIELD_DENSITY = 3
  integer(c_int32_t), parameter :: DC_PLAN_FIELD_RESTITUTION = 4
  integer(c_int32_t), parameter :: DC_PLAN_FIELD_RADIUS_MIN = 5
  integer(c_int32_t), parameter :: DC_PLAN_FIELD_RADIUS_MAX = 6
  integer(c_int32_t), parameter :: DC_PLAN_FIELD_V_MAX = 7
  integer(c_int32_t), parameter :: DC_PLAN_FIELD_DEPTH = 8
  integer(c_int32_t), parameter :: DC_PLAN_FIELD_GRAVITY = 9
  integer(c_int32_t), parameter :: DC_PLAN_FIELD_PRESSURE = 10
  integer(c_int32_t), parameter :: DC_PLAN_FIELD_SOLID_FRACTION = 11
  integer(c_int32_t), parameter :: DC_PLAN_FIELD_COORDINATION = 12
  integer(c_int32_t), parameter :: DC_PLAN_FIELD_LOAD_FACTOR = 13
  integer(c_int32_t), parameter :: DC_PLAN_FIELD_FRICTION = 14
  integer(c_int32_t), parameter :: DC_PLAN_FIELD_ROLLING_FRICTION = 15
  integer(c_int32_t), parameter :: DC_PLAN_FIELD_OVERLAP_TOL = 16
  integer(c_int32_t), parameter :: DC_PLAN_FIELD_E_TOL = 17
  integer(c_int32_t), parameter :: DC_PLAN_FIELD_STATIC_TOL = 18
  integer(c_int32_t), parameter :: DC_PLAN_FIELD_DURATION_TOL = 19
  integer(c_int32_t), parameter :: DC_PLAN_FIELD_CRITERION = 20
  integer(c_int32_t), parameter :: DC_PLAN_FIELD_STABILITY_FRACTION = 21
  integer(c_int32_t), parameter :: DC_PLAN_FIELD_CONVENTIONAL_DIVISOR = 22
  integer(c_int32_t), parameter :: DC_PLAN_FIELD_WALLS = 23
  integer(c_int32_t), parameter :: DC_PLAN_BINDING_OVERLAP = 0
  integer(c_int32_t), parameter :: DC_PLAN_BINDING_STATIC = 1
  integer(c_int32_t), parameter :: DC_PLAN_BINDING_DURATION = 2
  integer(c_int32_t), parameter :: DC_PLAN_STEP_RESTITUTION = 0
  integer(c_int32_t), parameter :: DC_PLAN_STEP_STABILITY = 1
  integer(c_int32_t), parameter :: DC_PLAN_PAIR_MIN_MIN = 0
  integer(c_int32_t), parameter :: DC_PLAN_PAIR_MIN_MAX = 1
  integer(c_int32_t), parameter :: DC_PLAN_PAIR_MAX_MAX = 2
  integer(c_int32_t), parameter :: DC_PLAN_PAIR_MIN_WALL = 3
  integer(c_int32_t), parameter :: DC_PLAN_PAIR_MAX_WALL = 4
  integer(c_int32_t), parameter :: DC_PLAN_PAIR_MIN_PEAK = 5
  integer(c_int32_t), parameter :: DC_LEVEL_MIN = 0
  integer(c_int32_t), parameter :: DC_LEVEL_MAX = 4
  integer(c_int32_t), parameter :: DC_END_OVERLAP = 0
  integer(c_int32_t), parameter :: DC_END_FORCE = 1
  integer(c_int32_t), parameter :: DC_INTEGRATOR_VELOCITY_VERLET = 0
  integer(c_int32_t), parameter :: DC_INTEGRATOR_SYMPLECTIC_EULER = 1
  integer(c_int32_t), parameter :: DC_DISPATCH_BASELINE = 0
  integer(c_int32_t), parameter :: DC_DISPATCH_AVX2 = 1
  integer(c_int32_t), parameter :: DC_DISPATCH_AVX512 = 2
  integer(c_int32_t), parameter :: DC_OK = 0
  integer(c_int32_t), parameter :: DC_ERR_NULL_POINTER = 6101
  integer(c_int32_t), parameter :: DC_ERR_NOT_FINITE = 6102
  integer(c_int32_t), parameter :: DC_ERR_RESTITUTION_RANGE = 6103
  integer(c_int32_t), parameter :: DC_ERR_EXPONENT_RANGE = 6104
  integer(c_int32_t), parameter :: DC_ERR_NOT_POSITIVE = 6105
  integer(c_int32_t), parameter :: DC_ERR_NEGATIVE = 6106
  integer(c_int32_t), parameter :: DC_ERR_CRITERION = 6107
  integer(c_int32_t), parameter :: DC_ERR_RESULT_RANGE = 6108
  integer(c_int32_t), parameter :: DC_ERR_NO_CONVERGENCE = 6109
  integer(c_int32_t), parameter :: DC_ERR_BUFFER_TOO_SHORT = 6110
  integer(c_int32_t), parameter :: DC_ERR_NO_EVENT = 6111
  integer(c_int32_t), parameter :: DC_ERR_LEVEL = 6112
  integer(c_int32_t), parameter :: DC_ERR_PLAN = 6113
  integer(c_int32_t), parameter :: DC_ERR_POISSON_RANGE = 6114
  integer(c_int32_t), parameter :: DC_ERR_PAIR_INVALID = 6120
  integer(c_int32_t), parameter :: DC_ERR_BUFFER_LAYOUT = 6121
  integer(c_int32_t), parameter :: DC_ERR_SPEC_VERSION = 6122
  integer(c_int32_t), parameter :: DC_ERR_SPEC_MODEL = 6123
  integer(c_int32_t), parameter :: DC_ERR_SPEC_UNSET = 6124
  integer(c_int32_t), parameter :: DC_ERR_CONTACT_MODEL_INVALID = 6125
  integer(c_int32_t), parameter :: DC_ERR_NOT_UNIT = 6126
  integer(c_int32_t), parameter :: DC_ERR_BUILTIN_MODEL = 6130
  integer(c_int32_t), parameter :: DC_ERR_BUILTIN_UNREACHABLE = 6131
  integer(c_int32_t), parameter :: DC_ERR_FIT_TOO_FEW = 6132
  integer(c_int32_t), parameter :: DC_ERR_FIT_DEGENERATE = 6133
  integer(c_int32_t), parameter :: DC_ERR_BUILTIN_VERSION = 6134
  integer(c_int32_t), parameter :: DC_ERR_INTEGRATOR = 6135
  integer(c_int32_t), parameter :: DC_ERR_STEP_UNSUPPORTED = 6136
  integer(c_int32_t), parameter :: DC_ERR_STEP_UNREACHABLE = 6137
  integer(c_int32_t), parameter :: DC_ERR_PLAN_RANGE = 6140
  integer(c_int32_t), parameter :: DC_ERR_PLAN_INFEASIBLE = 6141
  integer(c_int32_t), parameter :: DC_ERR_INTERNAL = 6199

  type, bind(c) :: dc_contact_spec
    integer(c_int32_t) :: version
    integer(c_int32_t) :: size
    integer(c_int32_t) :: normal
    integer(c_int32_t) :: damping
    integer(c_int32_t) :: criterion
    integer(c_int32_t) :: tangential
    integer(c_int32_t) :: rolling
    integer(c_int32_t) :: twisting
    real(c_double) :: E1
    real(c_double) :: nu1
    real(c_double) :: E2
    real(c_double) :: nu2
    real(c_double) :: p
    real(c_double) :: k_n
    real(c_double) :: e_n
    real(c_double) :: visco_A
    real(c_double) :: mu
    real(c_double) :: k_t
    real(c_double) :: e_t
    real(c_double) :: mu_r
    real(c_double) :: k_r
    real(c_double) :: eta_r
    real(c_double) :: mu_tw
    real(c_double) :: k_tw
    real(c_double) :: eta_tw
    real(c_double) :: inertia_factor
    real(c_double) :: work_of_adhesion
    real(c_double) :: yield_pressure
  end type dc_contact_spec

  type, bind(c) :: dc_pair
    integer(c_int32_t) :: model
    integer(c_int32_t) :: kernel
    integer(c_int32_t) :: criterion
    integer(c_int32_t) :: clamp
    real(c_double) :: p
    real(c_double) :: stiffness
    real(c_double) :: alpha
    real(c_double) :: damping_a
    real(c_double) :: e
    real(c_double) :: k
    real(c_double) :: c
    real(c_double) :: h
  end type dc_pair

  type, bind(c) :: dc_contact_model
    integer(c_int32_t) :: magic
    integer(c_int32_t) :: history_len
    integer(c_int32_t) :: tangential
    integer(c_int32_t) :: rolling
    integer(c_int32_t) :: twisting
    integer(c_int32_t) :: carry
    type(dc_pair) :: normal
    real(c_double) :: mu
    real(c_double) :: kt
    real(c_double) :: zeta_t
    real(c_double) :: kappa
    real(c_double) :: mu_r
    real(c_double) :: k_r
    real(c_double) :: eta_r
    real(c_double) :: mu_tw
    real(c_double) :: k_tw
    real(c_double) :: eta_tw
    real(c_double) :: reserved(6)
  end type dc_contact_model

  type, bind(c) :: dc_contact_state
    real(c_double) :: n(3)
    real(c_double) :: overlap
    real(c_double) :: v1(3)
    real(c_double) :: v2(3)
    real(c_double) :: w1(3)
    real(c_double) :: w2(3)
    real(c_double) :: r1
    real(c_double) :: r2
    real(c_double) :: m1
    real(c_double) :: m2
  end type dc_contact_state

  type, bind(c) :: dc_contact_result
    real(c_double) :: force(3)
    real(c_double) :: torque1(3)
    real(c_double) :: torque2(3)
    real(c_double) :: f_n
    real(c_double) :: ft(3)
    integer(c_int32_t) :: sliding
    integer(c_int32_t) :: rolling_sliding
  end type dc_contact_result

  type, bind(c) :: dc_contact_energy
    real(c_double) :: dissipated
    real(c_double) :: normal_damping
    real(c_double) :: tangential_damping
    real(c_double) :: tangential_slip
    real(c_double) :: tangential_elastic
    real(c_double) :: rolling_damping
    real(c_double) :: rolling_slip
    real(c_double) :: rolling_elastic
    real(c_double) :: twisting_damping
    real(c_double) :: twisting_slip
    real(c_double) :: twisting_elastic
  end type dc_contact_energy

  type, bind(c) :: dc_contact_batch
    integer(c_size_t) :: n
    integer(c_size_t) :: history_stride
    type(c_ptr) :: normal
    type(c_ptr) :: overlap
    type(c_ptr) :: v1
    type(c_ptr) :: v2
    type(c_ptr) :: w1
    type(c_ptr) :: w2
    type(c_ptr) :: r1
    type(c_ptr) :: r2
    type(c_ptr) :: m1
    type(c_ptr) :: m2
    type(c_ptr) :: history
    type(c_ptr) :: f_n
    type(c_ptr) :: force
    type(c_ptr) :: torque1
    type(c_ptr) :: torque2
  end type dc_contact_batch

  type, bind(c) :: dc_fit_result
    real(c_double) :: beta
    real(c_double) :: beta_se
    real(c_double) :: e_const
    real(c_double) :: e_const_se
    real(c_double) :: chi2_viscoelastic
    real(c_double) :: chi2_constant
    real(c_double) :: max_residual_viscoelastic
    real(c_double) :: max_residual_constant
    real(c_double) :: v_min
    real(c_double) :: v_max
    real(c_double) :: e_viscoelastic_at_v_min
    real(c_double) :: e_viscoelastic_at_v_max
    real(c_double) :: max_model_deviation
    integer(c_int32_t) :: model
    integer(c_int32_t) :: se_from_scatter
    integer(c_int32_t) :: iterations
    integer(c_int32_t) :: robust
  end type dc_fit_result

  type, bind(c) :: dc_plan_input
    integer(c_int32_t) :: version
    integer(c_int32_t) :: size
    real(c_double) :: youngs
    real(c_double) :: poisson
    real(c_double) :: density
    real(c_double) :: restitution
    real(c_double) :: radius_min
    real(c_double) :: radius_max
    real(c_double) :: v_max
    real(c_double) :: depth
    real(c_double) :: gravity
    real(c_double) :: pressure
    real(c_double) :: solid_fraction
    real(c_double) :: coordination
    real(c_double) :: load_factor
    real(c_double) :: friction
    real(c_double) :: rolling_friction
    real(c_double) :: overlap_tol
    real(c_double) :: e_tol
    real(c_double) :: static_tol
    real(c_double) :: duration_tol
    integer(c_int32_t) :: criterion
    integer(c_int32_t) :: walls
    real(c_double) :: stability_fraction
    real(c_double) :: conventional_divisor
  end type dc_plan_input

  type, bind(c) :: dc_plan_result
    real(c_double) :: youngs_soft
    real(c_double) :: softening
    integer(c_int32_t) :: binding
    integer(c_int32_t) :: binding_dt
    real(c_double) :: dt
    real(c_double) :: dt_restitution
    real(c_double) :: dt_stability
    real(c_double) :: dt_conventional
    real(c_double) :: speedup
    real(c_double) :: alpha
    real(c_double) :: max_overlap_ratio
    real(c_double) :: max_overlap_ratio_real
    real(c_double) :: static_overlap_ratio
    real(c_double) :: static_overlap_ratio_real
    integer(c_int32_t) :: max_overlap_pair
    integer(c_int32_t) :: static_pair
    real(c_double) :: stress
    real(c_double) :: static_force
    real(c_double) :: duration
    real(c_double) :: duration_real
    real(c_double) :: duration_change
    real(c_double) :: t_hertz
    real(c_double) :: dt_over_t_hertz
    real(c_double) :: steps_per_contact
    real(c_double) :: e_plain_at_dt
    real(c_double) :: e_plain_min
    real(c_double) :: e_plain_max
    real(c_double) :: e_plain_mean
  end type dc_plan_result

  type, bind(c) :: dc_duration_plan
    integer(c_int64_t) :: tag
    real(c_double) :: p
    real(c_double) :: q
    real(c_double) :: amp
    real(c_double) :: lgamma_q
    real(c_double) :: ln_aq
    integer(c_int32_t) :: level
    integer(c_int32_t) :: n
    real(c_double) :: nodes(16)
    real(c_double) :: weights(16)
  end type dc_duration_plan

  type, bind(c) :: dc_energy
    real(c_double) :: e
    real(c_double) :: loading
    real(c_double) :: unloading
    real(c_double) :: returned
    real(c_double) :: clamped
  end type dc_energy

  interface
    function dc_builtin_value_for_e(model, clamp, e, value_out) bind(c, &
        name='dc_builtin_value_for_e')
      import
      integer(c_int32_t), value, intent(in) :: model
      integer(c_int32_t), value, intent(in) :: clamp
      real(c_double), value, intent(in) :: e
      real(c_double), intent(out) :: value_out
      integer(c_int32_t) :: dc_builtin_value_for_e
    end function dc_builtin_value_for_e
    function dc_builtin_realised_e(model, clamp, value, e_out) bind(c, name='dc_builtin_realised_e')
      import
      integer(c_int32_t), value, intent(in) :: model
      integer(c_int32_t), value, intent(in) :: clamp
      real(c_double), value, intent(in) :: value
      real(c_double), intent(out) :: e_out
      integer(c_int32_t) :: dc_builtin_realised_e
    end function dc_builtin_realised_e
    function dc_builtin_value_for_e_wall(model, clamp, wall, e, value_out) bind(c, &
        name='dc_builtin_value_for_e_wall')
      import
      integer(c_int32_t), value, intent(in) :: model
      integer(c_int32_t), value, intent(in) :: clamp
      integer(c_int32_t), value, intent(in) :: wall
      real(c_double), value, intent(in) :: e
      real(c_double), intent(out) :: value_out
      integer(c_int32_t) :: dc_builtin_value_for_e_wall
    end function dc_builtin_value_for_e_wall
    function dc_builtin_realised_e_wall(model, clamp, wall, value, e_out) bind(c, &
        name='dc_builtin_realised_e_wall')
      import
      integer(c_int32_t), value, intent(in) :: model
      integer(c_int32_t), value, intent(in) :: clamp
      integer(c_int32_t), value, intent(in) :: wall
      real(c_double), value, intent(in) :: value
      real(c_double), intent(out) :: e_out
      integer(c_int32_t) :: dc_builtin_realised_e_wall
    end function dc_builtin_realised_e_wall
    function dc_builtin_yade_viscel_cn(e, kn, m_reduced, cn_out) bind(c, &
        name='dc_builtin_yade_viscel_cn')
      import
      real(c_double), value, intent(in) :: e
      real(c_double), value, intent(in) :: kn
      real(c_double), value, intent(in) :: m_reduced
      real(c_double), intent(out) :: cn_out
      integer(c_int32_t) :: dc_builtin_yade_viscel_cn
    end function dc_builtin_yade_viscel_cn
    function dc_builtin_for_lammps_release(model, yyyymmdd, model_out) bind(c, &
        name='dc_builtin_for_lammps_release')
      import
      integer(c_int32_t), value, intent(in) :: model
      integer(c_int32_t), value, intent(in) :: yyyymmdd
      integer(c_int32_t), intent(out) :: model_out
      integer(c_int32_t) :: dc_builtin_for_lammps_release
    end function dc_builtin_for_lammps_release
    function dc_alpha_from_e(e, p, criterion, alpha_out) bind(c, name='dc_alpha_from_e')
      import
      real(c_double), value, intent(in) :: e
      real(c_double), value, intent(in) :: p
      integer(c_int32_t), value, intent(in) :: criterion
      real(c_double), intent(out) :: alpha_out
      integer(c_int32_t) :: dc_alpha_from_e
    end function dc_alpha_from_e
    function dc_e_from_alpha(alpha, p, criterion, e_out) bind(c, name='dc_e_from_alpha')
      import
      real(c_double), value, intent(in) :: alpha
      real(c_double), value, intent(in) :: p
      integer(c_int32_t), value, intent(in) :: criterion
      real(c_double), intent(out) :: e_out
      integer(c_int32_t) :: dc_e_from_alpha
    end function dc_e_from_alpha
    function dc_elastic_plastic_restitution(x, e_out) bind(c, name='dc_elastic_plastic_restitution')
      import
      real(c_double), value, intent(in) :: x
      real(c_double), intent(out) :: e_out
      integer(c_int32_t) :: dc_elastic_plastic_restitution
    end function dc_elastic_plastic_restitution
    function dc_elastic_plastic_yield_speed(e_star, r_eff, m_eff, p_y, v_out) bind(c, &
        name='dc_elastic_plastic_yield_speed')
      import
      real(c_double), value, intent(in) :: e_star
      real(c_double), value, intent(in) :: r_eff
      real(c_double), value, intent(in) :: m_eff
      real(c_double), value, intent(in) :: p_y
      real(c_double), intent(out) :: v_out
      integer(c_int32_t) :: dc_elastic_plastic_yield_speed
    end function dc_elastic_plastic_yield_speed
    function dc_contact_spec_init(spec) bind(c, name='dc_contact_spec_init')
      import
      type(dc_contact_spec), intent(inout) :: spec
      integer(c_int32_t) :: dc_contact_spec_init
    end function dc_contact_spec_init
    function dc_contact_model_init(spec, out) bind(c, name='dc_contact_model_init')
      import
      type(dc_contact_spec), intent(in) :: spec
      type(dc_contact_model), intent(out) :: out
      integer(c_int32_t) :: dc_contact_model_init
    end function dc_contact_model_init
    function dc_contact_model_set_carry(model, carry) bind(c, name='dc_contact_model_set_carry')
      import
      type(dc_contact_model), intent(inout) :: model
      integer(c_int32_t), value, intent(in) :: carry
      integer(c_int32_t) :: dc_contact_model_set_carry
    end function dc_contact_model_set_carry
    function dc_contact_model_set_step(model, dt, integrator) bind(c, &
        name='dc_contact_model_set_step')
      import
      type(dc_contact_model), intent(inout) :: model
      real(c_double), value, intent(in) :: dt
      integer(c_int32_t), value, intent(in) :: integrator
      integer(c_int32_t) :: dc_contact_model_set_step
    end function dc_contact_model_set_step
    function dc_contact_history_len(model, len_out) bind(c, name='dc_contact_history_len')
      import
      type(dc_contact_model), intent(in) :: model
      integer(c_size_t), intent(out) :: len_out
      integer(c_int32_t) :: dc_contact_history_len
    end function dc_contact_history_len
    function dc_contact_model_reach(model, r_eff, reach_out) bind(c, name='dc_contact_model_reach')
      import
      type(dc_contact_model), intent(in) :: model
      real(c_double), value, intent(in) :: r_eff
      real(c_double), intent(out) :: reach_out
      integer(c_int32_t) :: dc_contact_model_reach
    end function dc_contact_model_reach
    function dc_contact_force(model, state, dt, history, history_len, out) bind(c, &
        name='dc_contact_force')
      import
      type(dc_contact_model), intent(in) :: model
      type(dc_contact_state), intent(in) :: state
      real(c_double), value, intent(in) :: dt
      real(c_double), intent(inout) :: history(*)
      integer(c_size_t), value, intent(in) :: history_len
      type(dc_contact_result), intent(out) :: out
      integer(c_int32_t) :: dc_contact_force
    end function dc_contact_force
    function dc_contact_force_energy(model, state, dt, history, history_len, out, energy) bind(c, &
        name='dc_contact_force_energy')
      import
      type(dc_contact_model), intent(in) :: model
      type(dc_contact_state), intent(in) :: state
      real(c_double), value, intent(in) :: dt
      real(c_double), intent(inout) :: history(*)
      integer(c_size_t), value, intent(in) :: history_len
      type(dc_contact_result), intent(out) :: out
      type(dc_contact_energy), intent(inout) :: energy
      integer(c_int32_t) :: dc_contact_force_energy
    end function dc_contact_force_energy
    function dc_contact_force_spheres(model, x1, x2, state, dt, history, history_len, out) bind(c, &
        name='dc_contact_force_spheres')
      import
      type(dc_contact_model), intent(in) :: model
      real(c_double), intent(in) :: x1(*)
      real(c_double), intent(in) :: x2(*)
      type(dc_contact_state), intent(in) :: state
      real(c_double), value, intent(in) :: dt
      real(c_double), intent(inout) :: history(*)
      integer(c_size_t), value, intent(in) :: history_len
      type(dc_contact_result), intent(out) :: out
      integer(c_int32_t) :: dc_contact_force_spheres
    end function dc_contact_force_spheres
    pure function dc_contact_force_batch(model, batch, dt) bind(c, name='dc_contact_force_batch')
      import
      type(dc_contact_model), intent(in) :: model
      type(dc_contact_batch), intent(in) :: batch
      real(c_double), value, intent(in) :: dt
      integer(c_int32_t) :: dc_contact_force_batch
    end function dc_contact_force_batch
    function dc_contact_force_batch_fused(model, batch, dt, first_bad) bind(c, &
        name='dc_contact_force_batch_fused')
      import
      type(dc_contact_model), intent(in) :: model
      type(dc_contact_batch), intent(in) :: batch
      real(c_double), value, intent(in) :: dt
      integer(c_size_t), intent(inout) :: first_bad(*)
      integer(c_int32_t) :: dc_contact_force_batch_fused
    end function dc_contact_force_batch_fused
    function dc_fit_restitution(n, v, e, sigma, criterion, tol, robust, resid_viscoelastic, &
        resid_constant, out) bind(c, name='dc_fit_restitution')
      import
      integer(c_size_t), value, intent(in) :: n
      real(c_double), intent(in) :: v(*)
      real(c_double), intent(in) :: e(*)
      real(c_double), intent(in) :: sigma(*)
      integer(c_int32_t), value, intent(in) :: criterion
      real(c_double), value, intent(in) :: tol
      integer(c_int32_t), value, intent(in) :: robust
      real(c_double), intent(inout) :: resid_viscoelastic(*)
      real(c_double), intent(inout) :: resid_constant(*)
      type(dc_fit_result), intent(out) :: out
      integer(c_int32_t) :: dc_fit_restitution
    end function dc_fit_restitution
    function dc_fit_quantile95(n, se_from_scatter, q_out) bind(c, name='dc_fit_quantile95')
      import
      integer(c_size_t), value, intent(in) :: n
      integer(c_int32_t), value, intent(in) :: se_from_scatter
      real(c_double), intent(out) :: q_out(*)
      integer(c_int32_t) :: dc_fit_quantile95
    end function dc_fit_quantile95
    function dc_pair_powerlaw(p, k, e, criterion, out) bind(c, name='dc_pair_powerlaw')
      import
      real(c_double), value, intent(in) :: p
      real(c_double), value, intent(in) :: k
      real(c_double), value, intent(in) :: e
      integer(c_int32_t), value, intent(in) :: criterion
      type(dc_pair), intent(out) :: out
      integer(c_int32_t) :: dc_pair_powerlaw
    end function dc_pair_powerlaw
    function dc_pair_powerlaw_alpha(p, k, alpha, criterion, out) bind(c, &
        name='dc_pair_powerlaw_alpha')
      import
      real(c_double), value, intent(in) :: p
      real(c_double), value, intent(in) :: k
      real(c_double), value, intent(in) :: alpha
      integer(c_int32_t), value, intent(in) :: criterion
      type(dc_pair), intent(out) :: out
      integer(c_int32_t) :: dc_pair_powerlaw_alpha
    end function dc_pair_powerlaw_alpha
    function dc_pair_linear(k, e, criterion, out) bind(c, name='dc_pair_linear')
      import
      real(c_double), value, intent(in) :: k
      real(c_double), value, intent(in) :: e
      integer(c_int32_t), value, intent(in) :: criterion
      type(dc_pair), intent(out) :: out
      integer(c_int32_t) :: dc_pair_linear
    end function dc_pair_linear
    function dc_pair_hertz(E1, nu1, E2, nu2, e, criterion, out) bind(c, name='dc_pair_hertz')
      import
      real(c_double), value, intent(in) :: E1
      real(c_double), value, intent(in) :: nu1
      real(c_double), value, intent(in) :: E2
      real(c_double), value, intent(in) :: nu2
      real(c_double), value, intent(in) :: e
      integer(c_int32_t), value, intent(in) :: criterion
      type(dc_pair), intent(out) :: out
      integer(c_int32_t) :: dc_pair_hertz
    end function dc_pair_hertz
    function dc_pair_viscoelastic(E1, nu1, E2, nu2, A, criterion, out) bind(c, &
        name='dc_pair_viscoelastic')
      import
      real(c_double), value, intent(in) :: E1
      real(c_double), value, intent(in) :: nu1
      real(c_double), value, intent(in) :: E2
      real(c_double), value, intent(in) :: nu2
      real(c_double), value, intent(in) :: A
      integer(c_int32_t), value, intent(in) :: criterion
      type(dc_pair), intent(out) :: out
      integer(c_int32_t) :: dc_pair_viscoelastic
    end function dc_pair_viscoelastic
    pure function dc_normal_force(pair, overlap, vn, r_eff, m_eff) bind(c, name='dc_normal_force')
      import
      type(dc_pair), intent(in) :: pair
      real(c_double), value, intent(in) :: overlap
      real(c_double), value, intent(in) :: vn
      real(c_double), value, intent(in) :: r_eff
      real(c_double), value, intent(in) :: m_eff
      real(c_double) :: dc_normal_force
    end function dc_normal_force
    function dc_normal_force_checked(pair, overlap, vn, r_eff, m_eff, force_out) bind(c, &
        name='dc_normal_force_checked')
      import
      type(dc_pair), intent(in) :: pair
      real(c_double), value, intent(in) :: overlap
      real(c_double), value, intent(in) :: vn
      real(c_double), value, intent(in) :: r_eff
      real(c_double), value, intent(in) :: m_eff
      real(c_double), intent(out) :: force_out
      integer(c_int32_t) :: dc_normal_force_checked
    end function dc_normal_force_checked
    function dc_normal_force_batch(pair, n, overlap, vn, r_eff, m_eff, force_out) bind(c, &
        name='dc_normal_force_batch')
      import
      type(dc_pair), intent(in) :: pair
      integer(c_size_t), value, intent(in) :: n
      real(c_double), intent(in) :: overlap(*)
      real(c_double), intent(in) :: vn(*)
      real(c_double), intent(in) :: r_eff(*)
      real(c_double), intent(in) :: m_eff(*)
      real(c_double), intent(out) :: force_out(*)
      integer(c_int32_t) :: dc_normal_force_batch
    end function dc_normal_force_batch
    function dc_normal_force_batch_fast(pair, n, overlap, vn, r_eff, m_eff, force_out) bind(c, &
        name='dc_normal_force_batch_fast')
      import
      type(dc_pair), intent(in) :: pair
      integer(c_size_t), value, intent(in) :: n
      real(c_double), intent(in) :: overlap(*)
      real(c_double), intent(in) :: vn(*)
      real(c_double), intent(in) :: r_eff(*)
      real(c_double), intent(in) :: m_eff(*)
      real(c_double), intent(out) :: force_out(*)
      integer(c_int32_t) :: dc_normal_force_batch_fast
    end function dc_normal_force_batch_fast
    function dc_normal_force_3d(pair, x1, v1, R1, m1, x2, v2, R2, m2, force_out) bind(c, &
        name='dc_normal_force_3d')
      import
      type(dc_pair), intent(in) :: pair
      real(c_double), intent(in) :: x1(*)
      real(c_double), intent(in) :: v1(*)
      real(c_double), value, intent(in) :: R1
      real(c_double), value, intent(in) :: m1
      real(c_double), intent(in) :: x2(*)
      real(c_double), intent(in) :: v2(*)
      real(c_double), value, intent(in) :: R2
      real(c_double), value, intent(in) :: m2
      real(c_double), intent(out) :: force_out(*)
      integer(c_int32_t) :: dc_normal_force_3d
    end function dc_normal_force_3d
    function dc_hertz_stiffness(E1, nu1, R1, E2, nu2, R2, k_out) bind(c, name='dc_hertz_stiffness')
      import
      real(c_double), value, intent(in) :: E1
      real(c_double), value, intent(in) :: nu1
      real(c_double), value, intent(in) :: R1
      real(c_double), value, intent(in) :: E2
      real(c_double), value, intent(in) :: nu2
      real(c_double), value, intent(in) :: R2
      real(c_double), intent(out) :: k_out
      integer(c_int32_t) :: dc_hertz_stiffness
    end function dc_hertz_stiffness
    function dc_effective_modulus(E1, nu1, E2, nu2, E_star_out) bind(c, name='dc_effective_modulus')
      import
      real(c_double), value, intent(in) :: E1
      real(c_double), value, intent(in) :: nu1
      real(c_double), value, intent(in) :: E2
      real(c_double), value, intent(in) :: nu2
      real(c_double), intent(out) :: E_star_out
      integer(c_int32_t) :: dc_effective_modulus
    end function dc_effective_modulus
    function dc_plan_input_init(input) bind(c, name='dc_plan_input_init')
      import
      type(dc_plan_input), intent(inout) :: input
      integer(c_int32_t) :: dc_plan_input_init
    end function dc_plan_input_init
    function dc_plan(input, out, field_out) bind(c, name='dc_plan')
      import
      type(dc_plan_input), intent(in) :: input
      type(dc_plan_result), intent(out) :: out
      integer(c_int32_t), intent(out) :: field_out
      integer(c_int32_t) :: dc_plan
    end function dc_plan
    function dc_max_overlap(p, alpha, v0, omega0, delta_max_out) bind(c, name='dc_max_overlap')
      import
      real(c_double), value, intent(in) :: p
      real(c_double), value, intent(in) :: alpha
      real(c_double), value, intent(in) :: v0
      real(c_double), value, intent(in) :: omega0
      real(c_double), intent(out) :: delta_max_out
      integer(c_int32_t) :: dc_max_overlap
    end function dc_max_overlap
    function dc_time_of_max_overlap(p, alpha, v0, omega0, t_out) bind(c, &
        name='dc_time_of_max_overlap')
      import
      real(c_double), value, intent(in) :: p
      real(c_double), value, intent(in) :: alpha
      real(c_double), value, intent(in) :: v0
      real(c_double), value, intent(in) :: omega0
      real(c_double), intent(out) :: t_out
      integer(c_int32_t) :: dc_time_of_max_overlap
    end function dc_time_of_max_overlap
    function dc_contact_duration(p, alpha, v0, omega0, criterion, tau_out) bind(c, &
        name='dc_contact_duration')
      import
      real(c_double), value, intent(in) :: p
      real(c_double), value, intent(in) :: alpha
      real(c_double), value, intent(in) :: v0
      real(c_double), value, intent(in) :: omega0
      integer(c_int32_t), value, intent(in) :: criterion
      real(c_double), intent(out) :: tau_out
      integer(c_int32_t) :: dc_contact_duration
    end function dc_contact_duration
    function dc_contact_duration_level(p, alpha, v0, omega0, criterion, level, tau_out) bind(c, &
        name='dc_contact_duration_level')
      import
      real(c_double), value, intent(in) :: p
      real(c_double), value, intent(in) :: alpha
      real(c_double), value, intent(in) :: v0
      real(c_double), value, intent(in) :: omega0
      integer(c_int32_t), value, intent(in) :: criterion
      integer(c_int32_t), value, intent(in) :: level
      real(c_double), intent(out) :: tau_out
      integer(c_int32_t) :: dc_contact_duration_level
    end function dc_contact_duration_level
    function dc_duration_plan_init(p, level, plan_out) bind(c, name='dc_duration_plan_init')
      import
      real(c_double), value, intent(in) :: p
      integer(c_int32_t), value, intent(in) :: level
      type(dc_duration_plan), intent(out) :: plan_out
      integer(c_int32_t) :: dc_duration_plan_init
    end function dc_duration_plan_init
    function dc_contact_duration_planned(plan, alpha, v0, omega0, criterion, tau_out) bind(c, &
        name='dc_contact_duration_planned')
      import
      type(dc_duration_plan), intent(in) :: plan
      real(c_double), value, intent(in) :: alpha
      real(c_double), value, intent(in) :: v0
      real(c_double), value, intent(in) :: omega0
      integer(c_int32_t), value, intent(in) :: criterion
      real(c_double), intent(out) :: tau_out
      integer(c_int32_t) :: dc_contact_duration_planned
    end function dc_contact_duration_planned
    function dc_energy_partition(p, alpha, criterion, energy_out) bind(c, name='dc_energy_partition')
      import
      real(c_double), value, intent(in) :: p
      real(c_double), value, intent(in) :: alpha
      integer(c_int32_t), value, intent(in) :: criterion
      type(dc_energy), intent(out) :: energy_out
      integer(c_int32_t) :: dc_energy_partition
    end function dc_energy_partition
    function dc_contact_trajectory(p, alpha, v0, omega0, mass, criterion, level, n, t_out, delta_out, &
        v_out, force_out, buf_len) bind(c, name='dc_contact_trajectory')
      import
      real(c_double), value, intent(in) :: p
      real(c_double), value, intent(in) :: alpha
      real(c_double), value, intent(in) :: v0
      real(c_double), value, intent(in) :: omega0
      real(c_double), value, intent(in) :: mass
      integer(c_int32_t), value, intent(in) :: criterion
      integer(c_int32_t), value, intent(in) :: level
      integer(c_size_t), value, intent(in) :: n
      real(c_double), intent(out) :: t_out(*)
      real(c_double), intent(out) :: delta_out(*)
      real(c_double), intent(out) :: v_out(*)
      real(c_double), intent(out) :: force_out(*)
      integer(c_size_t), value, intent(in) :: buf_len
      integer(c_int32_t) :: dc_contact_trajectory
    end function dc_contact_trajectory
    function dc_omega0(k, m, omega0_out) bind(c, name='dc_omega0')
      import
      real(c_double), value, intent(in) :: k
      real(c_double), value, intent(in) :: m
      real(c_double), intent(out) :: omega0_out
      integer(c_int32_t) :: dc_omega0
    end function dc_omega0
    function dc_status_str(status) bind(c, name='dc_status_str')
      import
      integer(c_int32_t), value, intent(in) :: status
      type(c_ptr) :: dc_status_str
    end function dc_status_str
    pure function dc_status_known(status) bind(c, name='dc_status_known')
      import
      integer(c_int32_t), value, intent(in) :: status
      integer(c_int32_t) :: dc_status_known
    end function dc_status_known
    function dc_dt_for_accuracy(p, e, criterion, v0, omega0, tol, dt_out) bind(c, &
        name='dc_dt_for_accuracy')
      import
      real(c_double), value, intent(in) :: p
      real(c_double), value, intent(in) :: e
      integer(c_int32_t), value, intent(in) :: criterion
      real(c_double), value, intent(in) :: v0
      real(c_double), value, intent(in) :: omega0
      real(c_double), value, intent(in) :: tol
      real(c_double), intent(out) :: dt_out
      integer(c_int32_t) :: dc_dt_for_accuracy
    end function dc_dt_for_accuracy
    function dc_dt_for_accuracy_step_aware(p, e, criterion, v0, omega0, tol, dt_out) bind(c, &
        name='dc_dt_for_accuracy_step_aware')
      import
      real(c_double), value, intent(in) :: p
      real(c_double), value, intent(in) :: e
      integer(c_int32_t), value, intent(in) :: criterion
      real(c_double), value, intent(in) :: v0
      real(c_double), value, intent(in) :: omega0
      real(c_double), value, intent(in) :: tol
      real(c_double), intent(out) :: dt_out
      integer(c_int32_t) :: dc_dt_for_accuracy_step_aware
    end function dc_dt_for_accuracy_step_aware
    function dc_dt_crit(p, v0, omega0, dt_out) bind(c, name='dc_dt_crit')
      import
      real(c_double), value, intent(in) :: p
      real(c_double), value, intent(in) :: v0
      real(c_double), value, intent(in) :: omega0
      real(c_double), intent(out) :: dt_out
      integer(c_int32_t) :: dc_dt_crit
    end function dc_dt_crit
    function dc_dt_linearised(p, v0, omega0, dt_out) bind(c, name='dc_dt_linearised')
      import
      real(c_double), value, intent(in) :: p
      real(c_double), value, intent(in) :: v0
      real(c_double), value, intent(in) :: omega0
      real(c_double), intent(out) :: dt_out
      integer(c_int32_t) :: dc_dt_linearised
    end function dc_dt_linearised
    function dc_dt_static(p, alpha, omega0, accel, dt_out) bind(c, name='dc_dt_static')
      import
      real(c_double), value, intent(in) :: p
      real(c_double), value, intent(in) :: alpha
      real(c_double), value, intent(in) :: omega0
      real(c_double), value, intent(in) :: accel
      real(c_double), intent(out) :: dt_out
      integer(c_int32_t) :: dc_dt_static
    end function dc_dt_static
    function dc_version() bind(c, name='dc_version')
      import
      type(c_ptr) :: dc_version
    end function dc_version
    pure function dc_dispatch_level() bind(c, name='dc_dispatch_level')
      import
      integer(c_int32_t) :: dc_dispatch_level
    end function dc_dispatch_level
    function dc_viscoelastic_e(b, criterion, e_out) bind(c, name='dc_viscoelastic_e')
      import
      real(c_double), value, intent(in) :: b
      integer(c_int32_t), value, intent(in) :: criterion
      real(c_double), intent(out) :: e_out
      integer(c_int32_t) :: dc_viscoelastic_e
    end function dc_viscoelastic_e
    function dc_viscoelastic_e_series(b, criterion, e_out) bind(c, name='dc_viscoelastic_e_series')
      import
      real(c_double), value, intent(in) :: b
      integer(c_int32_t), value, intent(in) :: criterion
      real(c_double), intent(out) :: e_out
      integer(c_int32_t) :: dc_viscoelastic_e_series
    end function dc_viscoelastic_e_series
    function dc_viscoelastic_e_reference(b, criterion, e_out) bind(c, &
        name='dc_viscoelastic_e_reference')
      import
      real(c_double), value, intent(in) :: b
      integer(c_int32_t), value, intent(in) :: criterion
      real(c_double), intent(out) :: e_out
      integer(c_int32_t) :: dc_viscoelastic_e_reference
    end function dc_viscoelastic_e_reference
    function dc_viscoelastic_b(k, gamma, v, b_out) bind(c, name='dc_viscoelastic_b')
      import
      real(c_double), value, intent(in) :: k
      real(c_double), value, intent(in) :: gamma
      real(c_double), value, intent(in) :: v
      real(c_double), intent(out) :: b_out
      integer(c_int32_t) :: dc_viscoelastic_b
    end function dc_viscoelastic_b
    function dc_viscoelastic_e_of_speed(k, gamma, v, criterion, e_out) bind(c, &
        name='dc_viscoelastic_e_of_speed')
      import
      real(c_double), value, intent(in) :: k
      real(c_double), value, intent(in) :: gamma
      real(c_double), value, intent(in) :: v
      integer(c_int32_t), value, intent(in) :: criterion
      real(c_double), intent(out) :: e_out
      integer(c_int32_t) :: dc_viscoelastic_e_of_speed
    end function dc_viscoelastic_e_of_speed
    function dc_viscoelastic_k_gamma(rho, a, m_eff, k_out, gamma_out) bind(c, &
        name='dc_viscoelastic_k_gamma')
      import
      real(c_double), value, intent(in) :: rho
      real(c_double), value, intent(in) :: a
      real(c_double), value, intent(in) :: m_eff
      real(c_double), intent(out) :: k_out
      real(c_double), intent(out) :: gamma_out
      integer(c_int32_t) :: dc_viscoelastic_k_gamma
    end function dc_viscoelastic_k_gamma
    function dc_viscoelastic_b_from_e(e, criterion, b_out) bind(c, name='dc_viscoelastic_b_from_e')
      import
      real(c_double), value, intent(in) :: e
      integer(c_int32_t), value, intent(in) :: criterion
      real(c_double), intent(out) :: b_out
      integer(c_int32_t) :: dc_viscoelastic_b_from_e
    end function dc_viscoelastic_b_from_e
    function dc_viscoelastic_beta_from_e(e, v_ref, criterion, beta_out) bind(c, &
        name='dc_viscoelastic_beta_from_e')
      import
      real(c_double), value, intent(in) :: e
      real(c_double), value, intent(in) :: v_ref
      integer(c_int32_t), value, intent(in) :: criterion
      real(c_double), intent(out) :: beta_out
      integer(c_int32_t) :: dc_viscoelastic_beta_from_e
    end function dc_viscoelastic_beta_from_e
    function dc_viscoelastic_a_from_e(e, v_ref, rho, m_eff, criterion, a_out) bind(c, &
        name='dc_viscoelastic_a_from_e')
      import
      real(c_double), value, intent(in) :: e
      real(c_double), value, intent(in) :: v_ref
      real(c_double), value, intent(in) :: rho
      real(c_double), value, intent(in) :: m_eff
      integer(c_int32_t), value, intent(in) :: criterion
      real(c_double), intent(out) :: a_out
      integer(c_int32_t) :: dc_viscoelastic_a_from_e
    end function dc_viscoelastic_a_from_e
    function dc_viscoelastic_speed_for_e(e, beta, criterion, v_out) bind(c, &
        name='dc_viscoelastic_speed_for_e')
      import
      real(c_double), value, intent(in) :: e
      real(c_double), value, intent(in) :: beta
      integer(c_int32_t), value, intent(in) :: criterion
      real(c_double), intent(out) :: v_out
      integer(c_int32_t) :: dc_viscoelastic_speed_for_e
    end function dc_viscoelastic_speed_for_e
  end interface

contains

  !> Elemental form of dc_builtin_value_for_e: on error `value_out` is NaN (numeric) and `stat` the status.
  impure elemental subroutine builtin_value_for_e(model, clamp, e, value_out, stat)
    integer(c_int32_t), intent(in) :: model
    integer(c_int32_t), intent(in) :: clamp
    real(c_double), intent(in) :: e
    real(c_double), intent(out) :: value_out
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    s = dc_builtin_value_for_e(model, clamp, e, value_out)
    if (present(stat)) stat = s
    if (s /= DC_OK) value_out = ieee_value(value_out, ieee_quiet_nan)
  end subroutine builtin_value_for_e

  !> Elemental form of dc_builtin_realised_e: on error `e_out` is NaN (numeric) and `stat` the status.
  impure elemental subroutine builtin_realised_e(model, clamp, value, e_out, stat)
    integer(c_int32_t), intent(in) :: model
    integer(c_int32_t), intent(in) :: clamp
    real(c_double), intent(in) :: value
    real(c_double), intent(out) :: e_out
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    s = dc_builtin_realised_e(model, clamp, value, e_out)
    if (present(stat)) stat = s
    if (s /= DC_OK) e_out = ieee_value(e_out, ieee_quiet_nan)
  end subroutine builtin_realised_e

  !> Elemental form of dc_builtin_value_for_e_wall: on error `value_out` is NaN (numeric) and `stat` the status.
  impure elemental subroutine builtin_value_for_e_wall(model, clamp, wall, e, value_out, stat)
    integer(c_int32_t), intent(in) :: model
    integer(c_int32_t), intent(in) :: clamp
    integer(c_int32_t), intent(in) :: wall
    real(c_double), intent(in) :: e
    real(c_double), intent(out) :: value_out
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    s = dc_builtin_value_for_e_wall(model, clamp, wall, e, value_out)
    if (present(stat)) stat = s
    if (s /= DC_OK) value_out = ieee_value(value_out, ieee_quiet_nan)
  end subroutine builtin_value_for_e_wall

  !> Elemental form of dc_builtin_realised_e_wall: on error `e_out` is NaN (numeric) and `stat` the status.
  impure elemental subroutine builtin_realised_e_wall(model, clamp, wall, value, e_out, stat)
    integer(c_int32_t), intent(in) :: model
    integer(c_int32_t), intent(in) :: clamp
    integer(c_int32_t), intent(in) :: wall
    real(c_double), intent(in) :: value
    real(c_double), intent(out) :: e_out
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    s = dc_builtin_realised_e_wall(model, clamp, wall, value, e_out)
    if (present(stat)) stat = s
    if (s /= DC_OK) e_out = ieee_value(e_out, ieee_quiet_nan)
  end subroutine builtin_realised_e_wall

  !> Elemental form of dc_builtin_yade_viscel_cn: on error `cn_out` is NaN (numeric) and `stat` the status.
  impure elemental subroutine builtin_yade_viscel_cn(e, kn, m_reduced, cn_out, stat)
    real(c_double), intent(in) :: e
    real(c_double), intent(in) :: kn
    real(c_double), intent(in) :: m_reduced
    real(c_double), intent(out) :: cn_out
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    s = dc_builtin_yade_viscel_cn(e, kn, m_reduced, cn_out)
    if (present(stat)) stat = s
    if (s /= DC_OK) cn_out = ieee_value(cn_out, ieee_quiet_nan)
  end subroutine builtin_yade_viscel_cn

  !> Elemental form of dc_builtin_for_lammps_release: on error `model_out` is NaN (numeric) and `stat` the status.
  impure elemental subroutine builtin_for_lammps_release(model, yyyymmdd, model_out, stat)
    integer(c_int32_t), intent(in) :: model
    integer(c_int32_t), intent(in) :: yyyymmdd
    integer(c_int32_t), intent(out) :: model_out
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    s = dc_builtin_for_lammps_release(model, yyyymmdd, model_out)
    if (present(stat)) stat = s
  end subroutine builtin_for_lammps_release

  !> Elemental form of dc_alpha_from_e: on error `alpha_out` is NaN (numeric) and `stat` the status.
  impure elemental subroutine alpha_from_e(e, p, criterion, alpha_out, stat)
    real(c_double), intent(in) :: e
    real(c_double), intent(in) :: p
    integer(c_int32_t), intent(in) :: criterion
    real(c_double), intent(out) :: alpha_out
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    s = dc_alpha_from_e(e, p, criterion, alpha_out)
    if (present(stat)) stat = s
    if (s /= DC_OK) alpha_out = ieee_value(alpha_out, ieee_quiet_nan)
  end subroutine alpha_from_e

  !> Elemental form of dc_e_from_alpha: on error `e_out` is NaN (numeric) and `stat` the status.
  impure elemental subroutine e_from_alpha(alpha, p, criterion, e_out, stat)
    real(c_double), intent(in) :: alpha
    real(c_double), intent(in) :: p
    integer(c_int32_t), intent(in) :: criterion
    real(c_double), intent(out) :: e_out
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    s = dc_e_from_alpha(alpha, p, criterion, e_out)
    if (present(stat)) stat = s
    if (s /= DC_OK) e_out = ieee_value(e_out, ieee_quiet_nan)
  end subroutine e_from_alpha

  !> Elemental form of dc_elastic_plastic_restitution: on error `e_out` is NaN (numeric) and `stat` the status.
  impure elemental subroutine elastic_plastic_restitution(x, e_out, stat)
    real(c_double), intent(in) :: x
    real(c_double), intent(out) :: e_out
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    s = dc_elastic_plastic_restitution(x, e_out)
    if (present(stat)) stat = s
    if (s /= DC_OK) e_out = ieee_value(e_out, ieee_quiet_nan)
  end subroutine elastic_plastic_restitution

  !> Elemental form of dc_elastic_plastic_yield_speed: on error `v_out` is NaN (numeric) and `stat` the status.
  impure elemental subroutine elastic_plastic_yield_speed(e_star, r_eff, m_eff, p_y, v_out, stat)
    real(c_double), intent(in) :: e_star
    real(c_double), intent(in) :: r_eff
    real(c_double), intent(in) :: m_eff
    real(c_double), intent(in) :: p_y
    real(c_double), intent(out) :: v_out
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    s = dc_elastic_plastic_yield_speed(e_star, r_eff, m_eff, p_y, v_out)
    if (present(stat)) stat = s
    if (s /= DC_OK) v_out = ieee_value(v_out, ieee_quiet_nan)
  end subroutine elastic_plastic_yield_speed

  !> Elemental form of dc_contact_model_init: on error `out` is NaN (numeric) and `stat` the status.
  impure elemental subroutine contact_model_init(spec, out, stat)
    type(dc_contact_spec), intent(in) :: spec
    type(dc_contact_model), intent(out) :: out
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    s = dc_contact_model_init(spec, out)
    if (present(stat)) stat = s
  end subroutine contact_model_init

  !> Elemental form of dc_contact_model_reach: on error `reach_out` is NaN (numeric) and `stat` the status.
  impure elemental subroutine contact_model_reach(model, r_eff, reach_out, stat)
    type(dc_contact_model), intent(in) :: model
    real(c_double), intent(in) :: r_eff
    real(c_double), intent(out) :: reach_out
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    s = dc_contact_model_reach(model, r_eff, reach_out)
    if (present(stat)) stat = s
    if (s /= DC_OK) reach_out = ieee_value(reach_out, ieee_quiet_nan)
  end subroutine contact_model_reach

  !> Elemental form of dc_pair_powerlaw: on error `out` is NaN (numeric) and `stat` the status.
  impure elemental subroutine pair_powerlaw(p, k, e, criterion, out, stat)
    real(c_double), intent(in) :: p
    real(c_double), intent(in) :: k
    real(c_double), intent(in) :: e
    integer(c_int32_t), intent(in) :: criterion
    type(dc_pair), intent(out) :: out
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    s = dc_pair_powerlaw(p, k, e, criterion, out)
    if (present(stat)) stat = s
  end subroutine pair_powerlaw

  !> Elemental form of dc_pair_powerlaw_alpha: on error `out` is NaN (numeric) and `stat` the status.
  impure elemental subroutine pair_powerlaw_alpha(p, k, alpha, criterion, out, stat)
    real(c_double), intent(in) :: p
    real(c_double), intent(in) :: k
    real(c_double), intent(in) :: alpha
    integer(c_int32_t), intent(in) :: criterion
    type(dc_pair), intent(out) :: out
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    s = dc_pair_powerlaw_alpha(p, k, alpha, criterion, out)
    if (present(stat)) stat = s
  end subroutine pair_powerlaw_alpha

  !> Elemental form of dc_pair_linear: on error `out` is NaN (numeric) and `stat` the status.
  impure elemental subroutine pair_linear(k, e, criterion, out, stat)
    real(c_double), intent(in) :: k
    real(c_double), intent(in) :: e
    integer(c_int32_t), intent(in) :: criterion
    type(dc_pair), intent(out) :: out
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    s = dc_pair_linear(k, e, criterion, out)
    if (present(stat)) stat = s
  end subroutine pair_linear

  !> Elemental form of dc_pair_hertz: on error `out` is NaN (numeric) and `stat` the status.
  impure elemental subroutine pair_hertz(E1, nu1, E2, nu2, e, criterion, out, stat)
    real(c_double), intent(in) :: E1
    real(c_double), intent(in) :: nu1
    real(c_double), intent(in) :: E2
    real(c_double), intent(in) :: nu2
    real(c_double), intent(in) :: e
    integer(c_int32_t), intent(in) :: criterion
    type(dc_pair), intent(out) :: out
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    s = dc_pair_hertz(E1, nu1, E2, nu2, e, criterion, out)
    if (present(stat)) stat = s
  end subroutine pair_hertz

  !> Elemental form of dc_pair_viscoelastic: on error `out` is NaN (numeric) and `stat` the status.
  impure elemental subroutine pair_viscoelastic(E1, nu1, E2, nu2, A, criterion, out, stat)
    real(c_double), intent(in) :: E1
    real(c_double), intent(in) :: nu1
    real(c_double), intent(in) :: E2
    real(c_double), intent(in) :: nu2
    real(c_double), intent(in) :: A
    integer(c_int32_t), intent(in) :: criterion
    type(dc_pair), intent(out) :: out
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    s = dc_pair_viscoelastic(E1, nu1, E2, nu2, A, criterion, out)
    if (present(stat)) stat = s
  end subroutine pair_viscoelastic

  !> Elemental form of dc_normal_force_checked: on error `force_out` is NaN (numeric) and `stat` the status.
  impure elemental subroutine normal_force_checked(pair, overlap, vn, r_eff, m_eff, force_out, stat)
    type(dc_pair), intent(in) :: pair
    real(c_double), intent(in) :: overlap
    real(c_double), intent(in) :: vn
    real(c_double), intent(in) :: r_eff
    real(c_double), intent(in) :: m_eff
    real(c_double), intent(out) :: force_out
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    s = dc_normal_force_checked(pair, overlap, vn, r_eff, m_eff, force_out)
    if (present(stat)) stat = s
    if (s /= DC_OK) force_out = ieee_value(force_out, ieee_quiet_nan)
  end subroutine normal_force_checked

  !> Elemental form of dc_hertz_stiffness: on error `k_out` is NaN (numeric) and `stat` the status.
  impure elemental subroutine hertz_stiffness(E1, nu1, R1, E2, nu2, R2, k_out, stat)
    real(c_double), intent(in) :: E1
    real(c_double), intent(in) :: nu1
    real(c_double), intent(in) :: R1
    real(c_double), intent(in) :: E2
    real(c_double), intent(in) :: nu2
    real(c_double), intent(in) :: R2
    real(c_double), intent(out) :: k_out
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    s = dc_hertz_stiffness(E1, nu1, R1, E2, nu2, R2, k_out)
    if (present(stat)) stat = s
    if (s /= DC_OK) k_out = ieee_value(k_out, ieee_quiet_nan)
  end subroutine hertz_stiffness

  !> Elemental form of dc_effective_modulus: on error `E_star_out` is NaN (numeric) and `stat` the status.
  impure elemental subroutine effective_modulus(E1, nu1, E2, nu2, E_star_out, stat)
    real(c_double), intent(in) :: E1
    real(c_double), intent(in) :: nu1
    real(c_double), intent(in) :: E2
    real(c_double), intent(in) :: nu2
    real(c_double), intent(out) :: E_star_out
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    s = dc_effective_modulus(E1, nu1, E2, nu2, E_star_out)
    if (present(stat)) stat = s
    if (s /= DC_OK) E_star_out = ieee_value(E_star_out, ieee_quiet_nan)
  end subroutine effective_modulus

  !> Elemental form of dc_max_overlap: on error `delta_max_out` is NaN (numeric) and `stat` the status.
  impure elemental subroutine max_overlap(p, alpha, v0, omega0, delta_max_out, stat)
    real(c_double), intent(in) :: p
    real(c_double), intent(in) :: alpha
    real(c_double), intent(in) :: v0
    real(c_double), intent(in) :: omega0
    real(c_double), intent(out) :: delta_max_out
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    s = dc_max_overlap(p, alpha, v0, omega0, delta_max_out)
    if (present(stat)) stat = s
    if (s /= DC_OK) delta_max_out = ieee_value(delta_max_out, ieee_quiet_nan)
  end subroutine max_overlap

  !> Elemental form of dc_time_of_max_overlap: on error `t_out` is NaN (numeric) and `stat` the status.
  impure elemental subroutine time_of_max_overlap(p, alpha, v0, omega0, t_out, stat)
    real(c_double), intent(in) :: p
    real(c_double), intent(in) :: alpha
    real(c_double), intent(in) :: v0
    real(c_double), intent(in) :: omega0
    real(c_double), intent(out) :: t_out
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    s = dc_time_of_max_overlap(p, alpha, v0, omega0, t_out)
    if (present(stat)) stat = s
    if (s /= DC_OK) t_out = ieee_value(t_out, ieee_quiet_nan)
  end subroutine time_of_max_overlap

  !> Elemental form of dc_contact_duration: on error `tau_out` is NaN (numeric) and `stat` the status.
  impure elemental subroutine contact_duration(p, alpha, v0, omega0, criterion, tau_out, stat)
    real(c_double), intent(in) :: p
    real(c_double), intent(in) :: alpha
    real(c_double), intent(in) :: v0
    real(c_double), intent(in) :: omega0
    integer(c_int32_t), intent(in) :: criterion
    real(c_double), intent(out) :: tau_out
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    s = dc_contact_duration(p, alpha, v0, omega0, criterion, tau_out)
    if (present(stat)) stat = s
    if (s /= DC_OK) tau_out = ieee_value(tau_out, ieee_quiet_nan)
  end subroutine contact_duration

  !> Elemental form of dc_contact_duration_level: on error `tau_out` is NaN (numeric) and `stat` the status.
  impure elemental subroutine contact_duration_level(p, alpha, v0, omega0, criterion, level, tau_out, &
      stat)
    real(c_double), intent(in) :: p
    real(c_double), intent(in) :: alpha
    real(c_double), intent(in) :: v0
    real(c_double), intent(in) :: omega0
    integer(c_int32_t), intent(in) :: criterion
    integer(c_int32_t), intent(in) :: level
    real(c_double), intent(out) :: tau_out
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    s = dc_contact_duration_level(p, alpha, v0, omega0, criterion, level, tau_out)
    if (present(stat)) stat = s
    if (s /= DC_OK) tau_out = ieee_value(tau_out, ieee_quiet_nan)
  end subroutine contact_duration_level

  !> Elemental form of dc_duration_plan_init: on error `plan_out` is NaN (numeric) and `stat` the status.
  impure elemental subroutine duration_plan_init(p, level, plan_out, stat)
    real(c_double), intent(in) :: p
    integer(c_int32_t), intent(in) :: level
    type(dc_duration_plan), intent(out) :: plan_out
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    s = dc_duration_plan_init(p, level, plan_out)
    if (present(stat)) stat = s
  end subroutine duration_plan_init

  !> Elemental form of dc_contact_duration_planned: on error `tau_out` is NaN (numeric) and `stat` the status.
  impure elemental subroutine contact_duration_planned(plan, alpha, v0, omega0, criterion, tau_out, &
      stat)
    type(dc_duration_plan), intent(in) :: plan
    real(c_double), intent(in) :: alpha
    real(c_double), intent(in) :: v0
    real(c_double), intent(in) :: omega0
    integer(c_int32_t), intent(in) :: criterion
    real(c_double), intent(out) :: tau_out
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    s = dc_contact_duration_planned(plan, alpha, v0, omega0, criterion, tau_out)
    if (present(stat)) stat = s
    if (s /= DC_OK) tau_out = ieee_value(tau_out, ieee_quiet_nan)
  end subroutine contact_duration_planned

  !> Elemental form of dc_energy_partition: on error `energy_out` is NaN (numeric) and `stat` the status.
  impure elemental subroutine energy_partition(p, alpha, criterion, energy_out, stat)
    real(c_double), intent(in) :: p
    real(c_double), intent(in) :: alpha
    integer(c_int32_t), intent(in) :: criterion
    type(dc_energy), intent(out) :: energy_out
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    s = dc_energy_partition(p, alpha, criterion, energy_out)
    if (present(stat)) stat = s
  end subroutine energy_partition

  !> Elemental form of dc_omega0: on error `omega0_out` is NaN (numeric) and `stat` the status.
  impure elemental subroutine omega0(k, m, omega0_out, stat)
    real(c_double), intent(in) :: k
    real(c_double), intent(in) :: m
    real(c_double), intent(out) :: omega0_out
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    s = dc_omega0(k, m, omega0_out)
    if (present(stat)) stat = s
    if (s /= DC_OK) omega0_out = ieee_value(omega0_out, ieee_quiet_nan)
  end subroutine omega0

  !> Elemental form of dc_dt_for_accuracy: on error `dt_out` is NaN (numeric) and `stat` the status.
  impure elemental subroutine dt_for_accuracy(p, e, criterion, v0, omega0, tol, dt_out, stat)
    real(c_double), intent(in) :: p
    real(c_double), intent(in) :: e
    integer(c_int32_t), intent(in) :: criterion
    real(c_double), intent(in) :: v0
    real(c_double), intent(in) :: omega0
    real(c_double), intent(in) :: tol
    real(c_double), intent(out) :: dt_out
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    s = dc_dt_for_accuracy(p, e, criterion, v0, omega0, tol, dt_out)
    if (present(stat)) stat = s
    if (s /= DC_OK) dt_out = ieee_value(dt_out, ieee_quiet_nan)
  end subroutine dt_for_accuracy

  !> Elemental form of dc_dt_for_accuracy_step_aware: on error `dt_out` is NaN (numeric) and `stat` the status.
  impure elemental subroutine dt_for_accuracy_step_aware(p, e, criterion, v0, omega0, tol, dt_out, &
      stat)
    real(c_double), intent(in) :: p
    real(c_double), intent(in) :: e
    integer(c_int32_t), intent(in) :: criterion
    real(c_double), intent(in) :: v0
    real(c_double), intent(in) :: omega0
    real(c_double), intent(in) :: tol
    real(c_double), intent(out) :: dt_out
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    s = dc_dt_for_accuracy_step_aware(p, e, criterion, v0, omega0, tol, dt_out)
    if (present(stat)) stat = s
    if (s /= DC_OK) dt_out = ieee_value(dt_out, ieee_quiet_nan)
  end subroutine dt_for_accuracy_step_aware

  !> Elemental form of dc_dt_crit: on error `dt_out` is NaN (numeric) and `stat` the status.
  impure elemental subroutine dt_crit(p, v0, omega0, dt_out, stat)
    real(c_double), intent(in) :: p
    real(c_double), intent(in) :: v0
    real(c_double), intent(in) :: omega0
    real(c_double), intent(out) :: dt_out
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    s = dc_dt_crit(p, v0, omega0, dt_out)
    if (present(stat)) stat = s
    if (s /= DC_OK) dt_out = ieee_value(dt_out, ieee_quiet_nan)
  end subroutine dt_crit

  !> Elemental form of dc_dt_linearised: on error `dt_out` is NaN (numeric) and `stat` the status.
  impure elemental subroutine dt_linearised(p, v0, omega0, dt_out, stat)
    real(c_double), intent(in) :: p
    real(c_double), intent(in) :: v0
    real(c_double), intent(in) :: omega0
    real(c_double), intent(out) :: dt_out
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    s = dc_dt_linearised(p, v0, omega0, dt_out)
    if (present(stat)) stat = s
    if (s /= DC_OK) dt_out = ieee_value(dt_out, ieee_quiet_nan)
  end subroutine dt_linearised

  !> Elemental form of dc_dt_static: on error `dt_out` is NaN (numeric) and `stat` the status.
  impure elemental subroutine dt_static(p, alpha, omega0, accel, dt_out, stat)
    real(c_double), intent(in) :: p
    real(c_double), intent(in) :: alpha
    real(c_double), intent(in) :: omega0
    real(c_double), intent(in) :: accel
    real(c_double), intent(out) :: dt_out
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    s = dc_dt_static(p, alpha, omega0, accel, dt_out)
    if (present(stat)) stat = s
    if (s /= DC_OK) dt_out = ieee_value(dt_out, ieee_quiet_nan)
  end subroutine dt_static

  !> Elemental form of dc_viscoelastic_e: on error `e_out` is NaN (numeric) and `stat` the status.
  impure elemental subroutine viscoelastic_e(b, criterion, e_out, stat)
    real(c_double), intent(in) :: b
    integer(c_int32_t), intent(in) :: criterion
    real(c_double), intent(out) :: e_out
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    s = dc_viscoelastic_e(b, criterion, e_out)
    if (present(stat)) stat = s
    if (s /= DC_OK) e_out = ieee_value(e_out, ieee_quiet_nan)
  end subroutine viscoelastic_e

  !> Elemental form of dc_viscoelastic_e_series: on error `e_out` is NaN (numeric) and `stat` the status.
  impure elemental subroutine viscoelastic_e_series(b, criterion, e_out, stat)
    real(c_double), intent(in) :: b
    integer(c_int32_t), intent(in) :: criterion
    real(c_double), intent(out) :: e_out
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    s = dc_viscoelastic_e_series(b, criterion, e_out)
    if (present(stat)) stat = s
    if (s /= DC_OK) e_out = ieee_value(e_out, ieee_quiet_nan)
  end subroutine viscoelastic_e_series

  !> Elemental form of dc_viscoelastic_e_reference: on error `e_out` is NaN (numeric) and `stat` the status.
  impure elemental subroutine viscoelastic_e_reference(b, criterion, e_out, stat)
    real(c_double), intent(in) :: b
    integer(c_int32_t), intent(in) :: criterion
    real(c_double), intent(out) :: e_out
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    s = dc_viscoelastic_e_reference(b, criterion, e_out)
    if (present(stat)) stat = s
    if (s /= DC_OK) e_out = ieee_value(e_out, ieee_quiet_nan)
  end subroutine viscoelastic_e_reference

  !> Elemental form of dc_viscoelastic_b: on error `b_out` is NaN (numeric) and `stat` the status.
  impure elemental subroutine viscoelastic_b(k, gamma, v, b_out, stat)
    real(c_double), intent(in) :: k
    real(c_double), intent(in) :: gamma
    real(c_double), intent(in) :: v
    real(c_double), intent(out) :: b_out
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    s = dc_viscoelastic_b(k, gamma, v, b_out)
    if (present(stat)) stat = s
    if (s /= DC_OK) b_out = ieee_value(b_out, ieee_quiet_nan)
  end subroutine viscoelastic_b

  !> Elemental form of dc_viscoelastic_e_of_speed: on error `e_out` is NaN (numeric) and `stat` the status.
  impure elemental subroutine viscoelastic_e_of_speed(k, gamma, v, criterion, e_out, stat)
    real(c_double), intent(in) :: k
    real(c_double), intent(in) :: gamma
    real(c_double), intent(in) :: v
    integer(c_int32_t), intent(in) :: criterion
    real(c_double), intent(out) :: e_out
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    s = dc_viscoelastic_e_of_speed(k, gamma, v, criterion, e_out)
    if (present(stat)) stat = s
    if (s /= DC_OK) e_out = ieee_value(e_out, ieee_quiet_nan)
  end subroutine viscoelastic_e_of_speed

  !> Elemental form of dc_viscoelastic_b_from_e: on error `b_out` is NaN (numeric) and `stat` the status.
  impure elemental subroutine viscoelastic_b_from_e(e, criterion, b_out, stat)
    real(c_double), intent(in) :: e
    integer(c_int32_t), intent(in) :: criterion
    real(c_double), intent(out) :: b_out
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    s = dc_viscoelastic_b_from_e(e, criterion, b_out)
    if (present(stat)) stat = s
    if (s /= DC_OK) b_out = ieee_value(b_out, ieee_quiet_nan)
  end subroutine viscoelastic_b_from_e

  !> Elemental form of dc_viscoelastic_beta_from_e: on error `beta_out` is NaN (numeric) and `stat` the status.
  impure elemental subroutine viscoelastic_beta_from_e(e, v_ref, criterion, beta_out, stat)
    real(c_double), intent(in) :: e
    real(c_double), intent(in) :: v_ref
    integer(c_int32_t), intent(in) :: criterion
    real(c_double), intent(out) :: beta_out
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    s = dc_viscoelastic_beta_from_e(e, v_ref, criterion, beta_out)
    if (present(stat)) stat = s
    if (s /= DC_OK) beta_out = ieee_value(beta_out, ieee_quiet_nan)
  end subroutine viscoelastic_beta_from_e

  !> Elemental form of dc_viscoelastic_a_from_e: on error `a_out` is NaN (numeric) and `stat` the status.
  impure elemental subroutine viscoelastic_a_from_e(e, v_ref, rho, m_eff, criterion, a_out, stat)
    real(c_double), intent(in) :: e
    real(c_double), intent(in) :: v_ref
    real(c_double), intent(in) :: rho
    real(c_double), intent(in) :: m_eff
    integer(c_int32_t), intent(in) :: criterion
    real(c_double), intent(out) :: a_out
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    s = dc_viscoelastic_a_from_e(e, v_ref, rho, m_eff, criterion, a_out)
    if (present(stat)) stat = s
    if (s /= DC_OK) a_out = ieee_value(a_out, ieee_quiet_nan)
  end subroutine viscoelastic_a_from_e

  !> Elemental form of dc_viscoelastic_speed_for_e: on error `v_out` is NaN (numeric) and `stat` the status.
  impure elemental subroutine viscoelastic_speed_for_e(e, beta, criterion, v_out, stat)
    real(c_double), intent(in) :: e
    real(c_double), intent(in) :: beta
    integer(c_int32_t), intent(in) :: criterion
    real(c_double), intent(out) :: v_out
    integer(c_int32_t), intent(out), optional :: stat
    integer(c_int32_t) :: s
    s = dc_viscoelastic_speed_for_e(e, beta, criterion, v_out)
    if (present(stat)) stat = s
    if (s /= DC_OK) v_out = ieee_value(v_out, ieee_quiet_nan)
  end subroutine viscoelastic_speed_for_e

  !> Elemental form of dc_normal_force (pure: arrays of contacts in one call).
  elemental function normal_force(pair, overlap, vn, r_eff, m_eff) result(r)
    type(dc_pair), intent(in) :: pair
    real(c_double), intent(in) :: overlap
    real(c_double), intent(in) :: vn
    real(c_double), intent(in) :: r_eff
    real(c_double), intent(in) :: m_eff
    real(c_double) :: r
    r = dc_normal_force(pair, overlap, vn, r_eff, m_eff)
  end function normal_force
end module demcontact_c
