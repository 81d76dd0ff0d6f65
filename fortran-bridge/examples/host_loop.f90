!> An example host model loop: read a 2-D grid of thickness distributions (data/sample_itd.nc),
!> then, cell by cell as CICE does, compute the ice strength with pressridge_ice_strength (the
!> drop-in for icepack_ice_strength) and take one ridging step of an hour with
!> pressridge_ridge_ice. With a reference file from `pressridge strength` (and optionally one
!> from `pressridge ridge-step --dt 3600`), check that the answers are the same.
!>
!> Usage: host_loop SAMPLE.nc [STRENGTH_REF.nc [RIDGED_REF.nc]]
program host_loop
  use, intrinsic :: iso_c_binding, only: c_double
  use pressridge, only: pressridge_ice_strength, pressridge_ridge_ice, pressridge_init_parameters, &
       pressridge_version
  use sample_io
  implicit none

  character(len=1024) :: sample, ref, ridged
  integer :: ni, nj, ncat, i, j, n
  real(c_double), allocatable :: aicen(:, :, :), vicen(:, :, :), aice0(:, :), divu(:, :), &
       shear(:, :), hin_max(:), strength(:, :), pref(:, :), ra(:, :, :), rv(:, :, :), ra0(:, :), &
       closing(:, :)
  real(c_double), parameter :: dt = 3600.0_c_double
  real(c_double) :: dmax, vol0, vol1
  logical :: ok

  call get_command_argument(1, sample)
  call get_command_argument(2, ref)
  call get_command_argument(3, ridged)
  if (len_trim(sample) == 0) then
     print '(a)', 'usage: host_loop SAMPLE.nc [STRENGTH_REF.nc [RIDGED_REF.nc]]'
     error stop 2
  end if

  call read_grid(trim(sample), ni, nj, ncat)
  allocate(aicen(ni, nj, ncat), vicen(ni, nj, ncat), aice0(ni, nj), divu(ni, nj), shear(ni, nj), &
       hin_max(0:ncat), strength(ni, nj), closing(ni, nj))
  call read_3d(trim(sample), 'aicen', aicen)
  call read_3d(trim(sample), 'vicen', vicen)
  call read_2d(trim(sample), 'aice0', aice0)
  call read_2d(trim(sample), 'divu', divu)
  call read_2d(trim(sample), 'shear', shear)
  call read_1d(trim(sample), 'hin_max', hin_max)
  print '(a, i0, a, i0, a, i0, a)', 'pressridge '//pressridge_version()//': ', ni, ' x ', nj, &
       ' cells, ', ncat, ' categories'

  ! CICE's defaults (kstrength = 1, krdg_partic = 1, krdg_redist = 1, Cf = 17), spelled out.
  call pressridge_init_parameters(kstrength=1, krdg_partic=1, krdg_redist=1, Cf=17.0_c_double)

  ! --- the dynamics step: ice strength, one call per cell, Icepack's argument list
  !$omp parallel do private(i)
  do j = 1, nj
     do i = 1, ni
        strength(i, j) = 0.0_c_double
        call pressridge_ice_strength(aice=sum(aicen(i, j, :)), vice=sum(vicen(i, j, :)), &
             aice0=aice0(i, j), aicen=aicen(i, j, :), vicen=vicen(i, j, :), &
             strength=strength(i, j))
     end do
  end do
  !$omp end parallel do
  print '(a, f8.2, a, f8.2, a)', 'strength: mean ', sum(strength) / (ni * nj) / 1e3, &
       ' kN/m, max ', maxval(strength) / 1e3, ' kN/m'

  ok = .true.
  if (len_trim(ref) > 0) then
     allocate(pref(ni, nj))
     call read_2d(trim(ref), 'strength', pref)
     dmax = maxval(abs(strength - pref))
     print '(a, es10.3, a)', 'strength vs pressridge strength: max |difference| = ', dmax, ' N/m'
     ok = ok .and. dmax <= 1e-13_c_double * maxval(abs(pref))
  end if

  ! --- the ridging step, one call per cell: convergence = max(-div u, 0)
  vol0 = sum(vicen)
  !$omp parallel do private(i)
  do j = 1, nj
     do i = 1, ni
        call pressridge_ridge_ice(dt, hin_max, max(-divu(i, j), 0.0_c_double), shear(i, j), &
             aicen(i, j, :), vicen(i, j, :), aice0(i, j), closing=closing(i, j))
     end do
  end do
  !$omp end parallel do
  vol1 = sum(vicen)
  print '(a, es10.3, a, es10.3)', 'ridging step: mean closing rate ', sum(closing) / (ni * nj), &
       ' 1/s; relative change of ice volume ', (vol1 - vol0) / vol0
  ok = ok .and. abs(vol1 - vol0) <= 1e-12_c_double * vol0
  n = count(abs(aice0 + sum(aicen, dim=3) - 1.0_c_double) > 1e-10_c_double)
  print '(a, i0)', 'cells whose area is not 1 after ridging: ', n
  ok = ok .and. n == 0

  if (len_trim(ridged) > 0) then
     allocate(ra(ni, nj, ncat), rv(ni, nj, ncat), ra0(ni, nj))
     call read_3d(trim(ridged), 'aicen', ra)
     call read_3d(trim(ridged), 'vicen', rv)
     call read_2d(trim(ridged), 'aice0', ra0)
     dmax = max(maxval(abs(aicen - ra)), maxval(abs(vicen - rv)), maxval(abs(aice0 - ra0)))
     print '(a, es10.3)', 'ridged state vs pressridge ridge-step: max |difference| = ', dmax
     ok = ok .and. dmax <= 1e-13_c_double
  end if

  deallocate(aicen, vicen, aice0, divu, shear, hin_max, strength, closing)
  if (allocated(pref)) deallocate(pref)
  if (allocated(ra)) deallocate(ra, rv, ra0)
  if (.not. ok) then
     print '(a)', 'host_loop: MISMATCH'
     error stop 1
  end if
  print '(a)', 'host_loop: same answers as the pressridge command line'
end program host_loop
