! A Fortran caller of libiwb_interface through the module iwb_interface (tests/c_api): with MODE
! "umat" the CV element test of cv_hvwe_euler.toml through the UMAT wrapper (separations over a
! unit thickness), with MODE "fric" the CNL test of cnl_hvwe_euler.toml through the FRIC wrapper
! (the pressure held at 100 kPa); one line "gamma,sigma_n,tau" per increment on stdout.
! Usage: fortran_caller PARAMETER_FILE umat|fric
program fortran_caller
  use iwb_interface
  implicit none
  character(len=512) :: parameters, mode
  character(len=1024) :: message
  type(c_ptr) :: material
  double precision :: state(16), stress(3), ddsdde(3, 3), stran(3), dstran(3), sse, spd, scd, rpl, ddsddt(3), drplde(3)
  double precision :: drpldt, time(2), predef(1), dpred(1), props(1), coords(3), drot(3, 3), dfgrd(3, 3), pnewdt
  double precision :: tau(2), ddtddg(2, 2), ddtddp(2), dslip(2)
  character(len=80) :: cmname
  integer :: k, status, lm, n
  call get_command_argument(1, parameters)
  call get_command_argument(2, mode)
  status = iwb_material_create('hvwe', trim(parameters), 1.0d0, 'scheme = "euler"' // new_line('a') // 'substeps = 4', &
                               material, message)
  if (status /= IWB_OK) then
    write (0, '(a)') trim(message)
    stop 1
  end if
  n = iwb_state_size(material)
  status = iwb_initial_state(material, ['sigma_n_kPa', 'e0         '], [100.0d0, 0.7d0], state(1:n), message)
  if (status /= IWB_OK) then
    write (0, '(a)') trim(message)
    stop 1
  end if
  stran = 0.0d0
  stress = 0.0d0
  do k = 1, 100
    pnewdt = 1.0d0
    if (trim(mode) == 'umat') then
      dstran = [0.0d0, 0.05d0 / 100, 0.0d0]
      call iwb_umat(material, stress, state, ddsdde, sse, spd, scd, rpl, ddsddt, drplde, drpldt, stran, dstran, time, &
                    0.0d0, 0.0d0, 0.0d0, predef, dpred, cmname, 1, 2, 3, 16, props, 0, coords, drot, pnewdt, 1.0d0, &
                    dfgrd, dfgrd, 1, 1, 1, 1, 1, k)
      stran = stran + dstran
      write (*, '(es25.17, ",", es25.17, ",", es25.17)') k * 0.05d0 / 100, -stress(1), stress(2)
    else
      dslip = [0.05d0 / 100, 0.0d0]
      call iwb_fric(material, 1.0d0, lm, tau, ddtddg, ddtddp, dslip, state, 100.0d0, 0.0d0, 2, 16, pnewdt)
      write (*, '(es25.17, ",", es25.17, ",", es25.17)') k * 0.05d0 / 100, 100.0d0, tau(1)
    end if
    if (pnewdt < 1.0d0) then
      write (0, '(a, i0)') 'fortran_caller: a cut was asked at increment ', k
      stop 1
    end if
  end do
  call iwb_material_destroy(material)
end program
