!> Cost per column of the C ABI from Fortran (ncat = 5): the batched strength call, the
!> Icepack-style per-cell call, the area-only ridging step batched and per cell, and the
!> complete ridging step (snow, 23 tracers, fluxes, clean-up) per cell and batched over the
!> first 1e5 columns. Workload (the same columns) as benches/strength.rs:
!> deterministic pseudo-random columns, 5-20 % open water, category thicknesses near 0.3, 1,
!> 1.9, 3, 4.5 m. Single thread. Prints nanoseconds per column; no assertions.
!>
!> Usage: bench_strength [NCOL]   (default 1000000)
program bench_strength
  use, intrinsic :: iso_c_binding, only: c_double
  use, intrinsic :: iso_fortran_env, only: int64
  use pressridge
  implicit none
  integer, parameter :: ncat = 5
  real(c_double), parameter :: hmid(ncat) = [0.3_c_double, 1.0_c_double, 1.9_c_double, &
       3.0_c_double, 4.5_c_double]
  integer :: ncol, c, n, rep, nrep
  character(len=32) :: arg
  real(c_double), allocatable :: a(:, :), v(:, :), a0(:), p(:), aw(:, :), vw(:, :), a0w(:), &
       conv(:), shear(:)
  real(c_double) :: r, w(ncat), s, t
  ! CICE's default category bounds for ncat = 5 (kcatbound = 1), m.
  real(c_double), parameter :: hin(0:ncat) = [0.0_c_double, 0.6_c_double, 1.4_c_double, &
       2.4_c_double, 3.6_c_double, 5.0_c_double]
  integer(int64) :: t0, t1, rate

  ncol = 1000000
  if (command_argument_count() > 0) then
     call get_command_argument(1, arg)
     read (arg, *) ncol
  end if
  allocate(a(ncat, ncol), v(ncat, ncol), a0(ncol), p(ncol), aw(ncat, ncol), vw(ncat, ncol), &
       a0w(ncol), conv(ncol), shear(ncol))
  r = 0.5_c_double
  do c = 1, ncol
     r = lcg(r)
     a0(c) = 0.05_c_double + 0.15_c_double * r
     do n = 1, ncat
        r = lcg(r)
        w(n) = 0.2_c_double + r
     end do
     s = sum(w)
     do n = 1, ncat
        a(n, c) = (1.0_c_double - a0(c)) * w(n) / s
        r = lcg(r)
        v(n, c) = a(n, c) * hmid(n) * (0.8_c_double + 0.4_c_double * r)
     end do
     a0(c) = 1.0_c_double - sum(a(:, c))
  end do
  conv = 2.0e-6_c_double
  shear = 4.0e-6_c_double
  call system_clock(count_rate=rate)
  print '(a, i0, a)', 'pressridge '//pressridge_version()//', ncat = 5, ', ncol, ' columns'

  ! Batched strength (CICE defaults: exponential/exponential, Rothrock, C_f = 17).
  call pressridge_strength(a, v, p, aice0=a0) ! warm-up
  nrep = 5
  call system_clock(t0)
  do rep = 1, nrep
     call pressridge_strength(a, v, p, aice0=a0)
  end do
  call system_clock(t1)
  t = real(t1 - t0, c_double) / rate / nrep
  print '(a, f8.1, a)', 'batched strength, one call for all columns:  ', 1e9 * t / ncol, ' ns/column'

  ! Per cell, as CICE calls icepack_ice_strength.
  call system_clock(t0)
  do c = 1, ncol
     p(c) = 0
     call pressridge_ice_strength(0.0_c_double, 0.0_c_double, a0(c), a(:, c), v(:, c), p(c))
  end do
  call system_clock(t1)
  t = real(t1 - t0, c_double) / rate
  print '(a, f8.1, a)', 'pressridge_ice_strength, one call per cell:  ', 1e9 * t / ncol, ' ns/column'

  ! Batched ridging step (on a fresh copy each repetition).
  nrep = 2
  t = 0
  do rep = 1, nrep
     aw = a
     vw = v
     a0w = a0
     call system_clock(t0)
     call pressridge_ridge_step(aw, vw, a0w, conv, shear, 3600.0_c_double)
     call system_clock(t1)
     t = t + real(t1 - t0, c_double) / rate
  end do
  t = t / nrep
  print '(a, f8.1, a)', 'batched ridging step, one call for all:      ', 1e9 * t / ncol, ' ns/column'

  ! Per cell, as an Icepack-style host would call ridge_ice.
  aw = a
  vw = v
  a0w = a0
  call system_clock(t0)
  do c = 1, ncol
     call pressridge_ridge_ice(3600.0_c_double, hin, conv(c), shear(c), aw(:, c), vw(:, c), &
          a0w(c))
  end do
  call system_clock(t1)
  t = real(t1 - t0, c_double) / rate
  print '(a, f8.1, a)', 'pressridge_ridge_ice, one call per cell:     ', 1e9 * t / ncol, ' ns/column'

  call bench_full_step(min(ncol, 100000))

contains

  !> The complete ridging step on the first n columns, with 10 % snow and the 23 CICE
  !> tracers of benches/strength.rs: per cell (as CICE calls icepack_step_ridge) and in one
  !> call.
  subroutine bench_full_step(n)
    integer, intent(in) :: n
    type(pressridge_ridger) :: rg
    integer :: ntrcr, i, k
    real(c_double), allocatable :: aw(:, :), vw(:, :), sw(:, :), tw(:, :, :), a0w(:), &
         aicew(:), fresh(:), fsalt(:), fhocn(:), fpond(:), op(:)
    real(c_double) :: hb(0:ncat), d1, d2, d3, t
    call pressridge_ridger_init(rg, ncat, 7, 1, .true., .true., .true., .true., ntrcr=ntrcr)
    allocate(aw(ncat, n), vw(ncat, n), sw(ncat, n), tw(ntrcr, ncat, n), a0w(n), aicew(n), &
         fresh(n), fsalt(n), fhocn(n), fpond(n), op(n))
    hb = hin
    do rep = 1, 2
       aw = a(:, 1:n)
       vw = v(:, 1:n)
       sw = 0.1_c_double * v(:, 1:n)
       a0w = a0(1:n)
       aicew = 0
       fresh = 0
       fsalt = 0
       fhocn = 0
       fpond = 0
       tw(1, :, :) = -20.0_c_double
       do k = 1, 7
          tw(1 + k, :, :) = -3.0e8_c_double - 1.0e6_c_double * k
          tw(9 + k, :, :) = 4.0_c_double + 0.2_c_double * k
       end do
       tw(9, :, :) = -1.15e8_c_double
       tw(17, :, :) = 2.0e7_c_double
       tw(18, :, :) = 0.4_c_double
       tw(19, :, :) = 0.8_c_double
       tw(20, :, :) = 0.8_c_double
       tw(21, :, :) = 0.2_c_double
       tw(22, :, :) = 0.1_c_double
       tw(23, :, :) = 0.01_c_double
       call system_clock(t0)
       if (rep == 1) then
          do i = 1, n
             call pressridge_step_ridge(rg, 3600.0_c_double, 1, hb, conv(i), shear(i), &
                  aw(:, i), tw(:, :, i), vw(:, i), sw(:, i), a0w(i), d1, d2, d3, op(i), &
                  fpond(i), fresh(i), fhocn(i), aice=aicew(i), fsalt=fsalt(i), &
                  Tf=-1.8_c_double)
          end do
       else
          call pressridge_step_ridge_cells(rg, 3600.0_c_double, 1, hb, conv(1:n), &
               shear(1:n), aw, tw, vw, sw, a0w, aicew, fresh=fresh, fsalt=fsalt, fhocn=fhocn, &
               fpond=fpond)
       end if
       call system_clock(t1)
       t = real(t1 - t0, c_double) / rate
       if (rep == 1) then
          print '(a, f8.1, a)', 'complete step (23 tracers), one call per cell: ', 1e9 * t / n, &
               ' ns/cell'
       else
          print '(a, f8.1, a)', 'complete step (23 tracers), one call for all:  ', 1e9 * t / n, &
               ' ns/cell'
       end if
    end do
    call pressridge_ridger_free(rg)
  end subroutine bench_full_step

  !> A deterministic pseudo-random number in [0, 1).
  real(c_double) function lcg(x)
    real(c_double), intent(in) :: x
    lcg = modulo(x * 9301.0_c_double + 0.49297_c_double, 1.0_c_double)
  end function lcg

end program bench_strength
