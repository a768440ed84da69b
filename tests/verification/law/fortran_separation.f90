! Drives a quasi-static separation of an initially bonded point through the Fortran module
! plyform_law and checks (1) every step against the same path run through the C++ class, bit
! for bit, and (2) the closed form: peak tension sigma_max at g_c = sigma_max / C_N.
program fortran_separation
  use, intrinsic :: iso_c_binding
  use plyform_law
  implicit none

  interface
    function cpp_reference_separation(uc, n_uc, n_steps, dt, temperature, k_normal, gaps, &
                                      pressure, beta) result(status) &
        bind(C, name="cpp_reference_separation")
      import :: c_double, c_int
      real(c_double), intent(in) :: uc(*)
      integer(c_int), value :: n_uc, n_steps
      real(c_double), value :: dt, temperature, k_normal
      real(c_double), intent(in) :: gaps(*)
      real(c_double), intent(out) :: pressure(*), beta(*)
      integer(c_int) :: status
    end function
  end interface

  integer, parameter :: n = 20001
  real(c_double), parameter :: cn = 30.0_c_double, smax = 0.3_c_double
  real(c_double), parameter :: dt = 1.0e-5_c_double, temperature = 300.0_c_double
  real(c_double), parameter :: k_normal = 1000.0_c_double
  real(c_double) :: uc(11), gaps(n), p_f(n), b_f(n), p_c(n), b_c(n), peak, g_peak, gc
  type(c_ptr) :: law
  type(plyform_law_history) :: hist
  type(plyform_law_increment) :: inc
  type(plyform_law_response) :: resp
  type(plyform_law_curve) :: no_curves(1)
  character(kind=c_char) :: message(512)
  integer(c_int32_t) :: status
  integer :: i, failures

  failures = 0
  ! MODEL CN SMAX_LO SMAX_HI T_LO T_HI ETA ZETA_LO ZETA_HI BETA0 BOND_TOL
  uc = [1.0_c_double, cn, smax, smax, 300.0_c_double, 500.0_c_double, 1.0e-14_c_double, &
        0.0_c_double, 0.0_c_double, 1.0_c_double, 1.0e-6_c_double]
  gc = smax / cn
  do i = 1, n
    gaps(i) = 40.0_c_double * gc * real(i - 1, c_double) / real(n - 1, c_double)
  end do

  status = plyform_law_create(uc, size(uc, kind=c_int32_t), no_curves, 0_c_int32_t, law, &
                              message, int(size(message), c_size_t))
  if (status /= PLYFORM_LAW_OK) then
    print *, 'plyform_law_create failed with status ', status
    stop 1
  end if
  status = plyform_law_initial_history(law, gaps(1), hist)
  if (status /= PLYFORM_LAW_OK .or. hist%state /= PLYFORM_LAW_CONTACT) then
    print *, 'initial history: status ', status, ' state ', hist%state
    stop 1
  end if

  inc%dt = dt
  inc%temperature = temperature
  inc%k_normal = k_normal
  inc%k_tangent = k_normal
  inc%area = 1.0_c_double
  p_f(1) = 0.0_c_double
  b_f(1) = 1.0_c_double
  do i = 2, n
    inc%gap = gaps(i)
    status = plyform_law_update_node(law, inc, hist, resp)
    if (status /= PLYFORM_LAW_OK) then
      print *, 'update failed at step ', i
      stop 1
    end if
    p_f(i) = resp%pressure
    b_f(i) = hist%beta
  end do
  call plyform_law_destroy(law)

  status = cpp_reference_separation(uc, size(uc, kind=c_int), n, dt, temperature, k_normal, &
                                    gaps, p_c, b_c)
  if (status /= 0) then
    print *, 'C++ reference failed with status ', status
    stop 1
  end if

  do i = 2, n
    if (p_f(i) /= p_c(i) .or. b_f(i) /= b_c(i)) then
      failures = failures + 1
      if (failures < 5) print *, 'step ', i, ' Fortran ', p_f(i), b_f(i), ' C++ ', p_c(i), b_c(i)
    end if
  end do
  if (failures == 0) then
    print *, 'Fortran module equals C++ on all ', n - 1, ' steps'
  end if

  peak = maxval(-p_f)
  g_peak = gaps(maxloc(-p_f, dim=1))
  if (abs(peak - smax) > 0.005_c_double * smax .or. abs(g_peak - gc) > 0.01_c_double * gc) then
    print *, 'closed form missed: peak ', peak, ' at ', g_peak, ' expected ', smax, ' at ', gc
    failures = failures + 1
  else
    print *, 'peak tension ', peak, ' at gap ', g_peak, ' (closed form ', smax, ' at ', gc, ')'
  end if
  if (hist%state /= PLYFORM_LAW_DETACHED) then
    print *, 'expected a fully debonded node at 40 g_c, state ', hist%state
    failures = failures + 1
  end if

  if (failures /= 0) stop 1
end program fortran_separation
