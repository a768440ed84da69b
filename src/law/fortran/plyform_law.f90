! Fortran bindings of the plyform interlayer contact law (iso_c_binding over plyform_law.h).
!
! A host such as an LS-DYNA user friction or user tiebreak routine creates one law per
! interface with plyform_law_create, keeps a plyform_law_history per slave node and calls
! plyform_law_update_node every cycle. See docs/host-integration.md.
module plyform_law
  use, intrinsic :: iso_c_binding, only: c_int32_t, c_int64_t, c_double, c_ptr, c_size_t, &
                                         c_char, c_null_ptr
  implicit none
  private

  integer(c_int32_t), parameter, public :: PLYFORM_LAW_OK = 0
  integer(c_int32_t), parameter, public :: PLYFORM_LAW_INVALID_ARGUMENT = 1
  integer(c_int32_t), parameter, public :: PLYFORM_LAW_INVALID_PARAMETER = 2
  integer(c_int32_t), parameter, public :: PLYFORM_LAW_OUT_OF_MEMORY = 3
  integer(c_int32_t), parameter, public :: PLYFORM_LAW_INTERNAL_ERROR = 4

  integer(c_int32_t), parameter, public :: PLYFORM_LAW_APPROACHING = 0
  integer(c_int32_t), parameter, public :: PLYFORM_LAW_CONTACT = 1
  integer(c_int32_t), parameter, public :: PLYFORM_LAW_SEPARATING = 2
  integer(c_int32_t), parameter, public :: PLYFORM_LAW_DETACHED = 3
  integer, parameter, public :: PLYFORM_LAW_MAX_CONSTANTS = 24

  !> A load curve for the -N slots (value against temperature).
  type, bind(C), public :: plyform_law_curve
    integer(c_int32_t) :: id = 0
    integer(c_int32_t) :: n_points = 0
    type(c_ptr) :: x = c_null_ptr
    type(c_ptr) :: y = c_null_ptr
  end type

  !> History of one slave node (layout of plyform_law_history in plyform_law.h).
  type, bind(C), public :: plyform_law_history
    integer(c_int32_t) :: state = 0
    integer(c_int32_t) :: reserved = 0
    real(c_double) :: beta = 1.0_c_double
    real(c_double) :: gap = 0.0_c_double
    real(c_double) :: slip(2) = 0.0_c_double
    real(c_double) :: opening(2) = 0.0_c_double
    real(c_double) :: e_damage = 0.0_c_double
    real(c_double) :: e_viscous = 0.0_c_double
    real(c_double) :: e_friction = 0.0_c_double
    real(c_double) :: e_damping = 0.0_c_double
    real(c_double) :: e_healing = 0.0_c_double
    real(c_double) :: damping = 0.0_c_double
  end type

  type, bind(C), public :: plyform_law_increment
    real(c_double) :: gap = 0.0_c_double
    real(c_double) :: slip(2) = 0.0_c_double
    real(c_double) :: dt = 0.0_c_double
    real(c_double) :: temperature = 0.0_c_double
    real(c_double) :: k_normal = 0.0_c_double
    real(c_double) :: k_tangent = 0.0_c_double
    real(c_double) :: area = 1.0_c_double
    real(c_double) :: mass = 0.0_c_double
  end type

  type, bind(C), public :: plyform_law_response
    real(c_double) :: pressure = 0.0_c_double
    real(c_double) :: tau(2) = 0.0_c_double
    real(c_double) :: stored = 0.0_c_double
  end type

  type, bind(C), public :: plyform_law_batch
    integer(c_int64_t) :: n = 0
    real(c_double) :: dt = 0.0_c_double
    type(c_ptr) :: gap = c_null_ptr, slip_x = c_null_ptr, slip_y = c_null_ptr
    type(c_ptr) :: temperature = c_null_ptr, k_normal = c_null_ptr, k_tangent = c_null_ptr
    type(c_ptr) :: area = c_null_ptr, mass = c_null_ptr
    type(c_ptr) :: state = c_null_ptr
    type(c_ptr) :: beta = c_null_ptr, hist_gap = c_null_ptr, hist_slip_x = c_null_ptr
    type(c_ptr) :: hist_slip_y = c_null_ptr, opening_x = c_null_ptr, opening_y = c_null_ptr
    type(c_ptr) :: e_damage = c_null_ptr, e_viscous = c_null_ptr, e_friction = c_null_ptr
    type(c_ptr) :: e_damping = c_null_ptr, e_healing = c_null_ptr
    type(c_ptr) :: pressure = c_null_ptr, tau_x = c_null_ptr, tau_y = c_null_ptr
    type(c_ptr) :: stored = c_null_ptr
    type(c_ptr) :: damping = c_null_ptr
  end type

  public :: plyform_law_create, plyform_law_destroy, plyform_law_initial_history
  public :: plyform_law_update_node, plyform_law_update_batch, plyform_law_update_mode1

  interface
    !> constants: UC1..UCn (NaN = blank); curves may be an empty array with n_curves = 0.
    !> message: a character(kind=c_char) buffer of message_size characters.
    function plyform_law_create(constants, n_constants, curves, n_curves, law, message, &
                                message_size) result(status) bind(C, name="plyform_law_create")
      import :: c_double, c_int32_t, c_ptr, c_char, c_size_t, plyform_law_curve
      real(c_double), intent(in) :: constants(*)
      integer(c_int32_t), value :: n_constants
      type(plyform_law_curve), intent(in) :: curves(*)
      integer(c_int32_t), value :: n_curves
      type(c_ptr), intent(out) :: law
      character(kind=c_char), intent(out) :: message(*)
      integer(c_size_t), value :: message_size
      integer(c_int32_t) :: status
    end function

    subroutine plyform_law_destroy(law) bind(C, name="plyform_law_destroy")
      import :: c_ptr
      type(c_ptr), value :: law
    end subroutine

    function plyform_law_initial_history(law, gap, history) result(status) &
        bind(C, name="plyform_law_initial_history")
      import :: c_ptr, c_double, c_int32_t, plyform_law_history
      type(c_ptr), value :: law
      real(c_double), value :: gap
      type(plyform_law_history), intent(out) :: history
      integer(c_int32_t) :: status
    end function

    function plyform_law_update_node(law, increment, history, response) result(status) &
        bind(C, name="plyform_law_update_node")
      import :: c_ptr, c_int32_t, plyform_law_increment, plyform_law_history, &
                plyform_law_response
      type(c_ptr), value :: law
      type(plyform_law_increment), intent(in) :: increment
      type(plyform_law_history), intent(inout) :: history
      type(plyform_law_response), intent(out) :: response
      integer(c_int32_t) :: status
    end function

    function plyform_law_update_batch(law, batch) result(status) &
        bind(C, name="plyform_law_update_batch")
      import :: c_ptr, c_int32_t, plyform_law_batch
      type(c_ptr), value :: law
      type(plyform_law_batch), intent(in) :: batch
      integer(c_int32_t) :: status
    end function

    !> Mode I with a three-value history (state, beta, gap), e.g. for a user tiebreak.
    function plyform_law_update_mode1(law, gap, dt, temperature, k_normal, hist, pressure) &
        result(status) bind(C, name="plyform_law_update_mode1")
      import :: c_ptr, c_double, c_int32_t
      type(c_ptr), value :: law
      real(c_double), value :: gap, dt, temperature, k_normal
      real(c_double), intent(inout) :: hist(3)
      real(c_double), intent(out) :: pressure
      integer(c_int32_t) :: status
    end function
  end interface
end module plyform_law
