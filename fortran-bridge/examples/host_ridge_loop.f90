!> A host model's ridging loop with the complete step (issue 15): a 4 x 3 grid, 5 thickness
!> categories, 7 ice layers, 1 snow layer and every CICE tracer (23), 400 steps of one hour
!> with deformation that converges and diverges. Each step a toy "advection" brings ice in
!> (convergence) or takes it out (divergence), then ridging restores the cell: on even steps
!> cell by cell as CICE calls icepack_step_ridge (pressridge_step_ridge), on odd steps the
!> whole grid in one call (pressridge_step_ridge_cells). After every ridging step the program
!> checks, per cell, that the total area is 1, nothing is negative, and water mass and enthalpy
!> are conserved with the fluxes to the ocean (1e-12 relative). Stops with an error otherwise.
program host_ridge_loop
  use, intrinsic :: iso_c_binding, only: c_double, c_int32_t
  use pressridge
  implicit none
  integer, parameter :: nx = 4, ny = 3, ncol = nx * ny, ncat = 5, nilyr = 7, nslyr = 1
  integer, parameter :: nsteps = 400
  real(c_double), parameter :: dt = 3600.0_c_double, rhoi = 917.0_c_double, &
       rhos = 330.0_c_double, tf = -1.8_c_double
  real(c_double), parameter :: hmid(ncat) = [0.3_c_double, 1.0_c_double, 1.9_c_double, &
       3.0_c_double, 4.5_c_double]
  type(pressridge_ridger) :: ridger
  integer :: ntrcr, step, c, n, k, nzap, ierr
  integer :: trcr_depend(64), n_trcr_strata(64), nt_strata(64, 2)
  real(c_double) :: trcr_base(64, 3)
  real(c_double), allocatable :: aicen(:, :), vicen(:, :), vsnon(:, :), trcrn(:, :, :)
  real(c_double) :: aice0(ncol), aice(ncol), conv(ncol), shear(ncol), divu, delta, sh
  real(c_double) :: fresh(ncol), fsalt(ncol), fhocn(ncol), fpond(ncol), opening(ncol)
  real(c_double) :: hin_max(0:ncat), mass0(ncol), heat0(ncol), mass1, heat1, f, total
  logical :: first_ice(ncat)
  real(c_double) :: d1, d2, d3, dp

  call pressridge_ridger_init(ridger, ncat, nilyr, nslyr, .true., .true., .true., .true., &
       ntrcr=ntrcr, trcr_depend=trcr_depend, trcr_base=trcr_base, &
       n_trcr_strata=n_trcr_strata, nt_strata=nt_strata)
  if (ntrcr /= 23 .or. trcr_depend(22) /= 2 + 21 .or. nt_strata(22, 2) /= 21) &
       error stop 'host_ridge_loop: unexpected tracer layout'
  allocate(aicen(ncat, ncol), vicen(ncat, ncol), vsnon(ncat, ncol), trcrn(ntrcr, ncat, ncol))
  hin_max = [0.0_c_double, 0.6_c_double, 1.4_c_double, 2.4_c_double, 3.6_c_double, 1.0e8_c_double]

  ! Initial state: 90-98 % ice, snow, ponds and every tracer.
  do c = 1, ncol
     do n = 1, ncat
        aicen(n, c) = (0.90_c_double + 0.08_c_double * mod(c, 3) / 2) * (0.1_c_double + 0.05_c_double * n) &
             / 0.95_c_double
        vicen(n, c) = aicen(n, c) * hmid(n)
        vsnon(n, c) = 0.1_c_double * vicen(n, c)
        trcrn(1, n, c) = -15.0_c_double
        do k = 1, nilyr
           trcrn(1 + k, n, c) = -3.0e8_c_double - 1.0e6_c_double * k
           trcrn(9 + k, n, c) = 4.0_c_double + 0.2_c_double * k
        end do
        trcrn(9, n, c) = -1.15e8_c_double
        trcrn(17, n, c) = 2.0e7_c_double
        trcrn(18:23, n, c) = [0.4_c_double, 0.8_c_double, 0.8_c_double, 0.2_c_double, &
             0.1_c_double, 0.01_c_double]
     end do
     aice0(c) = max(0.0_c_double, 1.0_c_double - sum(aicen(:, c)))
     aice(c) = sum(aicen(:, c))
  end do

  nzap = 0
  do step = 1, nsteps
     ! Host deformation (1/s): divergence and shear strain rates, then Icepack's terms.
     do c = 1, ncol
        divu = 4.0e-6_c_double * sin(0.05_c_double * step + 0.7_c_double * c)
        sh = 6.0e-6_c_double * (1.0_c_double + cos(0.03_c_double * step + c))
        delta = sqrt(divu**2 + 0.25_c_double * sh**2)
        conv(c) = -min(divu, 0.0_c_double)
        shear(c) = 0.5_c_double * (delta - abs(divu))
        ! Toy advection: the cell gains (convergence) or loses (divergence) ice.
        f = 1.0_c_double - divu * dt
        aicen(:, c) = aicen(:, c) * f
        vicen(:, c) = vicen(:, c) * f
        vsnon(:, c) = vsnon(:, c) * f
        if (f < 1.0_c_double) aice0(c) = aice0(c) * f
        mass0(c) = water_mass(c)
        heat0(c) = enthalpy(c)
     end do
     fresh = 0
     fsalt = 0
     fhocn = 0
     fpond = 0
     if (mod(step, 2) == 0) then
        do c = 1, ncol
           first_ice = .false.
           call pressridge_step_ridge(ridger, dt, 1, hin_max, conv(c), shear(c), aicen(:, c), &
                trcrn(:, :, c), vicen(:, c), vsnon(:, c), aice0(c), d1, d2, d3, opening(c), &
                fpond(c), fresh(c), fhocn(c), aice=aice(c), fsalt=fsalt(c), &
                first_ice=first_ice, Tf=tf, dpnd_ridge=dp, ierr=ierr)
           if (ierr /= PRESSRIDGE_OK) then
              print '(a, i0, a, i0, 2a)', 'step ', step, ' cell ', c, ': ', &
                   pressridge_last_error_message()
              error stop 'host_ridge_loop: ridging failed'
           end if
           nzap = nzap + count(first_ice)
        end do
     else
        call pressridge_step_ridge_cells(ridger, dt, 1, hin_max, conv, shear, aicen, trcrn, &
             vicen, vsnon, aice0, aice, fresh=fresh, fsalt=fsalt, fhocn=fhocn, fpond=fpond, &
             opening=opening, ierr=ierr)
        if (ierr /= PRESSRIDGE_OK) then
           print '(a, i0, 2a)', 'step ', step, ': ', pressridge_last_error_message()
           error stop 'host_ridge_loop: ridging failed'
        end if
     end if
     do c = 1, ncol
        total = aice0(c) + sum(aicen(:, c))
        mass1 = water_mass(c) + fresh(c) * dt
        heat1 = enthalpy(c) + fhocn(c) * dt
        if (abs(total - 1.0_c_double) > 1.0e-12_c_double .or. &
             any(aicen(:, c) < 0) .or. any(vicen(:, c) < 0) .or. any(vsnon(:, c) < 0) .or. &
             abs(mass1 - mass0(c)) > 1.0e-12_c_double * mass0(c) .or. &
             abs(heat1 - heat0(c)) > 1.0e-12_c_double * abs(heat0(c))) then
           print '(a, i0, a, i0, 3es24.15)', 'step ', step, ' cell ', c, total, mass1 - mass0(c), &
                heat1 - heat0(c)
           error stop 'host_ridge_loop: not conserved'
        end if
     end do
  end do
  print '(a, i0, a, i0, a)', 'host_ridge_loop: ', nsteps, ' steps of ', ncol, &
       ' cells ridged with snow and 23 tracers; area 1, water mass and enthalpy conserved'
  print '(a, f8.4, a, f8.4, a)', '  mean ice area ', sum(1.0_c_double - aice0) / ncol, &
       ', mean ice volume ', sum(vicen) / ncol, ' m'
  call pressridge_ridger_free(ridger)

contains

  real(c_double) function water_mass(c)
    integer, intent(in) :: c
    water_mass = rhoi * sum(vicen(:, c)) + rhos * sum(vsnon(:, c))
  end function water_mass

  real(c_double) function enthalpy(c)
    integer, intent(in) :: c
    integer :: n, k
    enthalpy = 0
    do n = 1, ncat
       do k = 1, nilyr
          enthalpy = enthalpy + trcrn(1 + k, n, c) * vicen(n, c) / nilyr
       end do
       enthalpy = enthalpy + trcrn(9, n, c) * vsnon(n, c) / nslyr
    end do
  end function enthalpy
end program host_ridge_loop
