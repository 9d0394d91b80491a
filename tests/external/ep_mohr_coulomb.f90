! A user's interface model as a user would write it (issue 22 item 6): Coulomb friction with a
! dilatancy angle, linear elastic normal and shear stiffness, in Fortran behind the UMAT-style entry
! point of src/models/external/README.md. Written here from the equations alone, independently of
! src/models/mc, which implements the same law: the tests hold the two against each other.
!   PROPS: 1 constrained modulus E_oed (kPa), 2 shear modulus G (kPa), 3 phi (deg), 4 psi (deg),
!          5 cohesion c (kPa).  NSTATV = 2: plastic opening, plastic shear strain.
!   STRESS: normal (tension positive), tau_x, tau_y. STRAN, DSTRAN: eps_n (opening positive), gamma_x, gamma_y.
subroutine ep_mohr_coulomb(stress, statev, ddsdde, stran, dstran, nstatv, props, nprops, pnewdt) &
    bind(c, name='ep_mohr_coulomb')
  use, intrinsic :: iso_c_binding, only: c_double, c_int
  implicit none
  integer(c_int), intent(in) :: nstatv, nprops
  real(c_double), intent(inout) :: stress(3), statev(*), pnewdt
  real(c_double), intent(out) :: ddsdde(3, 3)
  real(c_double), intent(in) :: stran(3), dstran(3), props(nprops)
  real(c_double), parameter :: deg = acos(-1.0d0) / 180.0d0
  real(c_double) :: e_oed, g, tan_phi, tan_psi, c, sigma_tr, tau_tr(2), t_tr, f, h, dl, t, n(2)
  integer :: i, j
  e_oed = props(1); g = props(2); tan_phi = tan(props(3) * deg); tan_psi = tan(props(4) * deg); c = props(5)
  ! the trial: sigma_n (compression positive) unloads on opening, tau loads with gamma
  sigma_tr = -stress(1) - e_oed * dstran(1)
  tau_tr = stress(2:3) + g * dstran(2:3)
  t_tr = sqrt(tau_tr(1)**2 + tau_tr(2)**2)
  if (sigma_tr <= 0.0d0) then  ! contact lost: ask for a smaller increment
    pnewdt = 0.5d0
    return
  end if
  f = t_tr - sigma_tr * tan_phi - c
  ddsdde = 0.0d0
  ddsdde(1, 1) = e_oed
  ddsdde(2, 2) = g
  ddsdde(3, 3) = g
  if (f <= 0.0d0) then  ! elastic
    stress(1) = -sigma_tr
    stress(2:3) = tau_tr
    return
  end if
  ! plastic: the multiplier moves |tau| back by g dl and opens the interface by dl tan(psi), which
  ! loads sigma_n by e_oed dl tan(psi): f = f_tr - dl (g + e_oed tan_phi tan_psi) = 0
  h = g + e_oed * tan_phi * tan_psi
  dl = f / h
  t = t_tr - g * dl
  n = tau_tr / t_tr
  stress(1) = -(sigma_tr + e_oed * tan_psi * dl)
  stress(2:3) = t * n
  if (nstatv >= 2) then
    statev(1) = statev(1) + dl * tan_psi
    statev(2) = statev(2) + dl
  end if
  ! consistent tangent, tension-positive normal row: d(-sigma_n)/d eps_n, d(-sigma_n)/d gamma_j
  ddsdde(1, 1) = e_oed - e_oed * tan_psi * e_oed * tan_phi / h
  do j = 1, 2
    ddsdde(1, 1 + j) = -e_oed * tan_psi * g * n(j) / h
  end do
  ! d tau_i / d eps_n = n_i d|tau| / d eps_n, with d dl / d eps_n = e_oed tan_phi / h
  do i = 1, 2
    ddsdde(1 + i, 1) = -n(i) * g * e_oed * tan_phi / h
    do j = 1, 2
      ddsdde(1 + i, 1 + j) = n(i) * (g * n(j) - g * g * n(j) / h) + t * g * (merge(1.0d0, 0.0d0, i == j) - n(i) * n(j)) / t_tr
    end do
  end do
end subroutine
