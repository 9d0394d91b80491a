! Fortran bindings of the C interface (iwb_interface.h) through ISO_C_BINDING, and two wrappers
! whose argument lists follow Abaqus' conventions, so that a finite-element code calling FRIC or
! UMAT can call the workbench's interface models (seed chapter 7):
!   iwb_fric  - FRIC's frictional update: slip increments in, shear tractions and their derivatives
!               out (LM, TAU, DDTDDG, DDTDDP, DSLIP, ..., PRESS, DPRESS, ..., STATEV, PROPS)
!   iwb_umat  - UMAT for an interface (cohesive-type) element with NTENS = 3: the normal and two
!               shear components (STRESS, STATEV, DDSDDE, ..., STRAN, DSTRAN, ..., PNEWDT, ...)
! The material is created once by the caller (iwb_material_create) and passed in by handle: the
! library keeps no global state, and neither do these wrappers.
module iwb_interface
  use, intrinsic :: iso_c_binding
  implicit none
  private
  public :: c_ptr, c_null_ptr, iwb_material_create, iwb_material_destroy, iwb_state_size, &
            iwb_initial_state, iwb_update, iwb_umat, iwb_fric, iwb_message_length, c_string

  integer, parameter, public :: IWB_OK = 0, IWB_ERROR_INPUT = 1, IWB_ERROR_DOMAIN = 2, &
                                IWB_ERROR_CONVERGENCE = 3, IWB_ERROR_INTERNAL = 4
  integer, parameter :: iwb_message_length = 1024

  interface
    integer(c_int) function c_material_create(model, parameter_file, kappa_r, integration, out, message, message_size) &
        bind(c, name='iwb_material_create')
      import :: c_int, c_char, c_double, c_ptr, c_size_t
      character(kind=c_char), dimension(*), intent(in) :: model, parameter_file, integration
      real(c_double), value :: kappa_r
      type(c_ptr), intent(out) :: out
      character(kind=c_char), dimension(*), intent(out) :: message
      integer(c_size_t), value :: message_size
    end function
    subroutine iwb_material_destroy(material) bind(c, name='iwb_material_destroy')
      import :: c_ptr
      type(c_ptr), value :: material
    end subroutine
    integer(c_int) function iwb_state_size(material) bind(c, name='iwb_state_size')
      import :: c_int, c_ptr
      type(c_ptr), value :: material
    end function
    integer(c_int) function c_initial_state(material, keys, values, n, state, message, message_size) &
        bind(c, name='iwb_initial_state')
      import :: c_int, c_ptr, c_double, c_char, c_size_t
      type(c_ptr), value :: material
      type(c_ptr), dimension(*), intent(in) :: keys
      real(c_double), dimension(*), intent(in) :: values
      integer(c_int), value :: n
      real(c_double), dimension(*), intent(out) :: state
      character(kind=c_char), dimension(*), intent(out) :: message
      integer(c_size_t), value :: message_size
    end function
    integer(c_int) function c_update(material, state_in, du, thickness, dt, external, state_out, traction, tangent, &
                                     step_factor, message, message_size) bind(c, name='iwb_update')
      import :: c_int, c_ptr, c_double, c_char, c_size_t
      type(c_ptr), value :: material
      real(c_double), dimension(*), intent(in) :: state_in
      real(c_double), dimension(3), intent(in) :: du
      real(c_double), value :: thickness, dt
      type(c_ptr), value :: external
      real(c_double), dimension(*), intent(out) :: state_out
      real(c_double), dimension(3), intent(out) :: traction
      real(c_double), dimension(9), intent(out) :: tangent
      real(c_double), intent(out) :: step_factor
      character(kind=c_char), dimension(*), intent(out) :: message
      integer(c_size_t), value :: message_size
    end function
  end interface

contains

  ! A Fortran string as a NUL-terminated C string.
  function c_string(text) result(c)
    character(len=*), intent(in) :: text
    character(kind=c_char), dimension(len_trim(text) + 1) :: c
    integer :: i
    do i = 1, len_trim(text)
      c(i) = text(i:i)
    end do
    c(len_trim(text) + 1) = c_null_char
  end function

  subroutine from_c(c, text)
    character(kind=c_char), dimension(*), intent(in) :: c
    character(len=*), intent(out) :: text
    integer :: i
    text = ' '
    do i = 1, len(text)
      if (c(i) == c_null_char) exit
      text(i:i) = c(i)
    end do
  end subroutine

  ! integration: the TOML text of an [integration] table ('' for the default, adaptive rk32)
  integer function iwb_material_create(model, parameter_file, kappa_r, integration, material, message) result(status)
    character(len=*), intent(in) :: model, parameter_file, integration
    double precision, intent(in) :: kappa_r
    type(c_ptr), intent(out) :: material
    character(len=*), intent(out) :: message
    character(kind=c_char), dimension(iwb_message_length) :: buffer
    status = c_material_create(c_string(model), c_string(parameter_file), real(kappa_r, c_double), c_string(integration), &
                               material, buffer, int(iwb_message_length, c_size_t))
    call from_c(buffer, message)
  end function

  ! The initial state from (key, value) pairs, keys as a test file's [initial] names them.
  integer function iwb_initial_state(material, keys, values, state, message) result(status)
    type(c_ptr), intent(in) :: material
    character(len=*), dimension(:), intent(in) :: keys
    double precision, dimension(:), intent(in) :: values
    double precision, dimension(:), intent(out) :: state
    character(len=*), intent(out) :: message
    character(kind=c_char), dimension(64, size(keys)), target :: key_text
    type(c_ptr), dimension(size(keys)) :: key_pointers
    character(kind=c_char), dimension(iwb_message_length) :: buffer
    integer :: i, j
    do i = 1, size(keys)
      key_text(:, i) = c_null_char
      do j = 1, min(len_trim(keys(i)), 63)
        key_text(j, i) = keys(i)(j:j)
      end do
      key_pointers(i) = c_loc(key_text(1, i))
    end do
    status = c_initial_state(material, key_pointers, values, int(size(keys), c_int), state, buffer, &
                             int(iwb_message_length, c_size_t))
    call from_c(buffer, message)
  end function

  integer function iwb_update(material, state_in, du, thickness, state_out, traction, tangent, step_factor, message) &
      result(status)
    type(c_ptr), intent(in) :: material
    double precision, dimension(:), intent(in) :: state_in
    double precision, dimension(3), intent(in) :: du
    double precision, intent(in) :: thickness
    double precision, dimension(:), intent(out) :: state_out
    double precision, dimension(3), intent(out) :: traction
    double precision, dimension(3, 3), intent(out) :: tangent  ! tangent(i, j) = d traction_i / d du_j
    double precision, intent(out) :: step_factor
    character(len=*), intent(out) :: message
    character(kind=c_char), dimension(iwb_message_length) :: buffer
    double precision, dimension(9) :: row_major
    status = c_update(material, state_in, du, real(thickness, c_double), 0.0_c_double, c_null_ptr, state_out, traction, &
                      row_major, step_factor, buffer, int(iwb_message_length, c_size_t))
    tangent = transpose(reshape(row_major, [3, 3]))
    call from_c(buffer, message)
  end function

  ! UMAT for an interface element, NTENS = 3 (normal, shear 1, shear 2), Abaqus' sign: tension
  ! positive STRESS, opening positive STRAN; the interface's strains are the element's separations
  ! over its (virtual) thickness, which the element already divides by: thickness 1 here. STATEV
  ! holds the model's state (NSTATV >= iwb_state_size); on the first increment (KINC = 1, KSTEP =
  ! 1) STATEV must hold the initial state from iwb_initial_state. PNEWDT < 1 asks for a cut.
  subroutine iwb_umat(material, stress, statev, ddsdde, sse, spd, scd, rpl, ddsddt, drplde, drpldt, stran, dstran, &
                      time, dtime, temp, dtemp, predef, dpred, cmname, ndi, nshr, ntens, nstatv, props, nprops, &
                      coords, drot, pnewdt, celent, dfgrd0, dfgrd1, noel, npt, layer, kspt, kstep, kinc)
    type(c_ptr), intent(in) :: material
    integer, intent(in) :: ndi, nshr, ntens, nstatv, nprops, noel, npt, layer, kspt, kstep, kinc
    double precision, intent(inout) :: stress(ntens), statev(nstatv), sse, spd, scd, pnewdt
    double precision, intent(out) :: ddsdde(ntens, ntens), rpl, ddsddt(ntens), drplde(ntens), drpldt
    double precision, intent(in) :: stran(ntens), dstran(ntens), time(2), dtime, temp, dtemp, predef(1), dpred(1), &
                                    props(nprops), coords(3), drot(3, 3), celent, dfgrd0(3, 3), dfgrd1(3, 3)
    character(len=80), intent(in) :: cmname
    double precision :: state_out(nstatv), traction(3), tangent(3, 3), factor
    character(len=iwb_message_length) :: message
    integer :: status, n
    n = iwb_state_size(material)
    if (ntens /= 3 .or. nstatv < n) then
      pnewdt = 0.25d0  ! a mis-declared element: the caller sees a cut it cannot satisfy and stops
      return
    end if
    status = iwb_update(material, statev(1:n), dstran(1:3), 1.0d0, state_out(1:n), traction, tangent, factor, message)
    if (status /= IWB_OK) then
      pnewdt = min(pnewdt, factor)
      return
    end if
    statev(1:n) = state_out(1:n)
    ! traction is (sigma_n compression positive, tau_x, tau_y): Abaqus' STRESS is tension positive
    stress(1) = -traction(1)
    stress(2:3) = traction(2:3)
    ddsdde(1, :) = -tangent(1, :)
    ddsdde(2:3, :) = tangent(2:3, :)
    rpl = 0.0d0
    ddsddt = 0.0d0
    drplde = 0.0d0
    drpldt = 0.0d0
  end subroutine

  ! FRIC's frictional update, the seed's usage (7.1): the slip increments DSLIP(1:2) and the
  ! contact pressure's increment over the virtual thickness d_s^v give the interface's shear
  ! strains; the model returns the shear tractions TAU(1:2) and DDTDDG(i,j) = d tau_i / d slip_j,
  ! DDTDDP(i) = d tau_i / d p. The normal behaviour stays the contact algorithm's (pressure
  ! given): the normal strain increment is DPRESS over the model's own normal tangent, solved by
  ! a Newton iteration on du_n with the consistent tangent. LM = 0: sticking or slipping is the
  ! model's business (no Coulomb switch).
  subroutine iwb_fric(material, thickness, lm, tau, ddtddg, ddtddp, dslip, statev, press, dpress, nfdir, nstatv, pnewdt)
    type(c_ptr), intent(in) :: material
    double precision, intent(in) :: thickness, dslip(nfdir), press, dpress
    integer, intent(in) :: nfdir, nstatv
    integer, intent(out) :: lm
    double precision, intent(out) :: tau(nfdir), ddtddg(nfdir, nfdir), ddtddp(nfdir)
    double precision, intent(inout) :: statev(nstatv), pnewdt
    double precision :: du(3), state_out(nstatv), traction(3), tangent(3, 3), factor, residual
    character(len=iwb_message_length) :: message
    integer :: status, n, it
    n = iwb_state_size(material)
    lm = 0
    du = 0.0d0
    du(2:1 + nfdir) = dslip(1:nfdir)
    do it = 1, 30
      status = iwb_update(material, statev(1:n), du, thickness, state_out(1:n), traction, tangent, factor, message)
      if (status /= IWB_OK) then
        pnewdt = min(pnewdt, factor)
        return
      end if
      residual = traction(1) - (press + dpress)
      if (abs(residual) <= 1d-10 * max(1.0d0, abs(press + dpress))) exit
      du(1) = du(1) - residual / tangent(1, 1)
    end do
    statev(1:n) = state_out(1:n)
    tau(1:nfdir) = traction(2:1 + nfdir)
    ! at fixed pressure: d tau / d slip = T_ss - T_sn T_ns / T_nn, d tau / d p = T_sn / T_nn
    ddtddg(1:nfdir, 1:nfdir) = tangent(2:1 + nfdir, 2:1 + nfdir) - &
        matmul(reshape(tangent(2:1 + nfdir, 1), [nfdir, 1]), reshape(tangent(1, 2:1 + nfdir), [1, nfdir])) / tangent(1, 1)
    ddtddp(1:nfdir) = tangent(2:1 + nfdir, 1) / tangent(1, 1)
  end subroutine

end module iwb_interface
