! Drives the LS-DYNA shim sketch like a host would: a bonded point opened quasi-statically
! through shim_tiebreak (three history values) and through shim_friction_node (full history),
! with the probe example's constants. Checks the closed form: peak tension sigma_max at
! g_c = sigma_max / C_N, and that both routes agree. Exit status 0 when they do.
program shim_demo
  use, intrinsic :: iso_c_binding, only: c_double, c_int32_t
  use plyform_law, only: plyform_law_history, PLYFORM_LAW_OK
  use plyform_lsdyna_shim
  implicit none

  real(c_double), parameter :: cn = 30.0_c_double, smax = 0.3_c_double, gc = smax / cn
  real(c_double), parameter :: v = 1.0e-2_c_double  ! opening rate [mm/s]
  integer, parameter :: n = 10000
  ! MODEL CN SMAX_LO SMAX_HI T_LO T_HI ETA ZETA_LO ZETA_HI BETA0 BOND_TOL; zeros as LS-DYNA
  ! passes blank fields (SMAX_HI, T_HI, ZETA_HI, BETA0 take their defaults).
  real(c_double) :: uc(11) = [1.0_c_double, cn, smax, 0.0_c_double, 0.0_c_double, &
                              0.0_c_double, 3.0e-5_c_double, 0.0_c_double, 0.0_c_double, &
                              0.0_c_double, 1.0e-6_c_double]
  real(c_double) :: hist3(3), p, g, dt, peak, g_peak, f_add, f_t(2)
  type(plyform_law_history) :: hist
  integer(c_int32_t) :: status
  character(len=512) :: message
  integer :: i
  logical :: ok

  call shim_create(uc, status, message)
  if (status /= PLYFORM_LAW_OK) then
    print '(a,i0,2a)', 'shim_create failed, status ', status, ': ', trim(message)
    stop 1
  end if

  ! Route 1: user tiebreak, history (state, beta, gap) zeroed as LS-DYNA hands it over.
  hist3 = 0.0_c_double
  dt = 40.0_c_double * gc / real(n, c_double) / v
  peak = 0.0_c_double
  g_peak = 0.0_c_double
  call shim_tiebreak(0.0_c_double, dt, 20.0_c_double, cn, hist3, p, status)
  do i = 1, n
    g = 40.0_c_double * gc * real(i, c_double) / real(n, c_double)
    call shim_tiebreak(g, dt, 20.0_c_double, cn, hist3, p, status)
    if (status /= PLYFORM_LAW_OK) stop 2
    if (-p > peak) then
      peak = -p
      g_peak = g
    end if
  end do
  print '(a,f8.5,a,f8.5,a)', 'tiebreak route: peak tension ', peak, ' MPa at g = ', g_peak, ' mm'
  ok = abs(peak / smax - 1.0_c_double) < 0.01_c_double .and. abs(g_peak / gc - 1.0_c_double) < 0.02_c_double
  ok = ok .and. .not. abs(hist3(2)) > 0.0_c_double  ! fully debonded: beta = 0

  ! Route 2: full history per node (SMP usrfrc), unit area, no host penalty in the band.
  call shim_initial_history(0.0_c_double, hist, status)
  if (status /= PLYFORM_LAW_OK) stop 3
  peak = 0.0_c_double
  do i = 1, n
    g = 40.0_c_double * gc * real(i, c_double) / real(n, c_double)
    call shim_friction_node(g, [0.0_c_double, 0.0_c_double], dt, 20.0_c_double, cn, &
                            1.0_c_double, 0.0_c_double, hist, f_add, f_t, status)
    if (status /= PLYFORM_LAW_OK) stop 3
    peak = max(peak, -f_add)
  end do
  print '(a,f8.5,a)', 'friction route: peak tension ', peak, ' MPa'
  ok = ok .and. abs(peak / smax - 1.0_c_double) < 0.01_c_double

  call shim_destroy()
  if (.not. ok) then
    print '(a)', 'shim_demo: FAILED (expected peak sigma_max = 0.3 MPa at g_c = 0.01 mm)'
    stop 1
  end if
  print '(a)', 'shim_demo: OK'

end program shim_demo
