! Sketch of an LS-DYNA host shim for the plyform contact law (docs/host-integration.md).
!
! Not LS-DYNA code: these subroutines take the quantities a user tiebreak routine
! (utb101..utb105) or an SMP user friction routine (usrfrc) has at hand, already mapped to the
! law's meaning (surface gap, slip increment, dt, temperature, penalty per area, area), and
! forward them to the module plyform_law. The LS-DYNA routine itself (its argument list comes
! from the dyn21 template of your LS-DYNA version) only unpacks its arguments and calls these.
!
! Reals are double precision here; a single-precision LS-DYNA passes real*4, convert on entry.
module plyform_lsdyna_shim
  use, intrinsic :: iso_c_binding, only: c_double, c_int32_t, c_ptr, c_null_ptr, c_char, &
                                         c_size_t, c_associated
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
  use plyform_law
  implicit none
  private

  public :: shim_create, shim_destroy, shim_ready, shim_initial_history, shim_tiebreak
  public :: shim_friction_node

  !> One law per interface, created once, then only read: safe to share between threads.
  type(c_ptr), save :: law = c_null_ptr

  !> Slots whose blank value means "take the default", not 0: LS-DYNA hands a blank field to
  !> the user routine as 0, so these are passed on as NaN (blank) when they are 0.
  !> SMAX_HI(4) T_HI(6) ZETA_HI(9) BETA0(10) MU_HI(14) VISC_HI(16) BETA_MIN(19) FD_RATIO(23)
  integer, parameter :: blank_if_zero(8) = [4, 6, 9, 10, 14, 16, 19, 23]

contains

  !> Creates the law from the constants as LS-DYNA holds them (UP1..UPn of the tiebreak card,
  !> or the UC of *USER_INTERFACE_FRICTION). status: a PLYFORM_LAW_* code; on an invalid
  !> constant the law's message names it.
  subroutine shim_create(constants, status, message)
    real(c_double), intent(in) :: constants(:)
    integer(c_int32_t), intent(out) :: status
    character(len=*), intent(out) :: message
    real(c_double) :: uc(PLYFORM_LAW_MAX_CONSTANTS)
    type(plyform_law_curve) :: no_curves(1)
    character(kind=c_char) :: buffer(1024)
    integer :: n, i

    n = min(size(constants), PLYFORM_LAW_MAX_CONSTANTS)
    uc(1:n) = constants(1:n)
    do i = 1, size(blank_if_zero)
      if (blank_if_zero(i) <= n) then
        if (.not. abs(uc(blank_if_zero(i))) > 0.0_c_double) then
          uc(blank_if_zero(i)) = ieee_value(uc(1), ieee_quiet_nan)
        end if
      end if
    end do
    call shim_destroy()
    buffer = c_char_''
    status = plyform_law_create(uc, int(n, c_int32_t), no_curves, 0_c_int32_t, law, buffer, &
                                int(size(buffer), c_size_t))
    message = ''
    do i = 1, min(len(message), size(buffer))
      if (buffer(i) == achar(0)) exit
      message(i:i) = buffer(i)
    end do
  end subroutine

  subroutine shim_destroy()
    if (c_associated(law)) call plyform_law_destroy(law)
    law = c_null_ptr
  end subroutine

  logical function shim_ready()
    shim_ready = c_associated(law)
  end function

  !> History of a slave node at t = 0 (bonded when |gap| <= BOND_TOL), for shim_friction_node.
  subroutine shim_initial_history(gap, hist, status)
    real(c_double), intent(in) :: gap
    type(plyform_law_history), intent(out) :: hist
    integer(c_int32_t), intent(out) :: status
    status = plyform_law_initial_history(law, gap, hist)
  end subroutine

  !> User tiebreak (mode I, three history variables): hist = (state, beta, gap), as LS-DYNA keeps
  !> them per slave node (NHV = 3). LS-DYNA zeroes them before the first call; all-zero is taken
  !> as "not initialised yet" and filled from the current gap (bonded within BOND_TOL).
  !> traction: normal traction, positive in compression (tension < 0).
  subroutine shim_tiebreak(gap, dt, temperature, k_normal, hist, traction, status)
    real(c_double), intent(in) :: gap, dt, temperature, k_normal
    real(c_double), intent(inout) :: hist(3)
    real(c_double), intent(out) :: traction
    integer(c_int32_t), intent(out) :: status
    type(plyform_law_history) :: h0

    traction = 0.0_c_double
    if (.not. any(abs(hist) > 0.0_c_double)) then
      status = plyform_law_initial_history(law, gap, h0)
      if (status /= PLYFORM_LAW_OK) return
      hist = [real(h0%state, c_double), h0%beta, h0%gap]
    end if
    status = plyform_law_update_mode1(law, gap, dt, temperature, k_normal, hist, traction)
  end subroutine

  !> SMP user friction, one slave node: the full law with its own history record. With the
  !> paper's thickness scaling, LS-DYNA applies its own penalty force f_host (normal, positive
  !> in compression) inside the enlarged band; the shim returns the normal force to ADD so that
  !> the total is the law's, and the tangential force of the law.
  subroutine shim_friction_node(gap, slip_increment, dt, temperature, k_normal, area, f_host, &
                                hist, f_normal_add, f_tangent, status)
    real(c_double), intent(in) :: gap, slip_increment(2), dt, temperature, k_normal, area, f_host
    type(plyform_law_history), intent(inout) :: hist
    real(c_double), intent(out) :: f_normal_add, f_tangent(2)
    integer(c_int32_t), intent(out) :: status
    type(plyform_law_increment) :: inc
    type(plyform_law_response) :: resp

    inc%gap = gap
    inc%slip = slip_increment
    inc%dt = dt
    inc%temperature = temperature
    inc%k_normal = k_normal
    inc%k_tangent = k_normal
    inc%area = area
    inc%mass = 0.0_c_double
    status = plyform_law_update_node(law, inc, hist, resp)
    if (status /= PLYFORM_LAW_OK) then
      f_normal_add = 0.0_c_double
      f_tangent = 0.0_c_double
      return
    end if
    f_normal_add = resp%pressure * area - f_host
    f_tangent = resp%tau * area
  end subroutine

end module plyform_lsdyna_shim
