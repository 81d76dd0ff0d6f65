!> Side-by-side timing of the complete ridging step and of the ice strength: Icepack's
!> icepack_step_ridge and icepack_ice_strength (built from
!> the user's Icepack checkout by run.sh; no Icepack code is in this repository) and
!> pressridge's C ABI, per cell and batched, on the same columns in the same run. Workload
!> as benches/strength.rs and bench_strength.f90: ncat = 5 (bounds 0, 0.6, 1.4, 2.4, 3.6 m),
!> 5-20 % open water, 10 % snow, 7 ice layers, 1 snow layer, 23 tracers, CICE defaults,
!> rdg_conv 2e-6 + rdg_shear 4e-6 1/s, dt 3600 s. Also reports the largest relative
!> difference between the two answers.
!>
!> Usage (via run.sh): bench_icepack_ridge [NCOL]   (default 100000)
program bench_icepack_ridge
  use, intrinsic :: iso_c_binding, only: c_double
  use, intrinsic :: iso_fortran_env, only: int64
  use icepack_intfc, only: icepack_step_ridge, icepack_ice_strength, icepack_init_tracer_sizes, &
       icepack_init_tracer_flags, icepack_init_tracer_indices, icepack_init_parameters, &
       icepack_warnings_flush, icepack_warnings_aborted
  use pressridge
  use pressridge_icepack, only: pressridge_icepack_step_ridge, pressridge_icepack_ice_strength
  implicit none
  integer, parameter :: ncat = 5, nilyr = 7, nslyr = 1, ntrcr = 23
  real(c_double), parameter :: hmid(ncat) = [0.3d0, 1.0d0, 1.9d0, 3.0d0, 4.5d0]
  real(c_double), parameter :: hin0(0:ncat) = [0.0d0, 0.6d0, 1.4d0, 2.4d0, 3.6d0, 5.0d0]
  real(c_double), parameter :: dt = 3600.0d0, conv = 2.0d-6, shear = 4.0d-6, tf = -1.8d0
  integer :: ncol, c, n, k, rep
  character(len=32) :: arg
  real(c_double), allocatable :: a(:, :), v(:, :), s(:, :), tr(:, :, :), a0(:)
  real(c_double), allocatable :: ia(:, :), iv(:, :), is(:, :), it(:, :, :), ia0(:), iaice(:)
  real(c_double), allocatable :: pa(:, :), pv(:, :), ps(:, :), pt(:, :, :), pa0(:), paice(:)
  real(c_double), allocatable :: fr(:), fs(:), fh(:), fp(:), cv(:), sh(:)
  real(c_double), allocatable :: sic(:), spc(:), spb(:), sdi(:), ai(:), vi(:)
  real(c_double) :: r, w(ncat), sw, hin(0:ncat), t, tic, tpc, tpb, tdi, diff, ddi
  real(c_double) :: d1, d2, d3, op, fpond, fresh, fhocn, fsalt, aice, faero(1), fbio(1)
  real(c_double) :: aparticn(ncat), krdgn(ncat), aredistn(ncat), vredistn(ncat), &
       dardg1ndt(ncat), dardg2ndt(ncat), dvirdgndt(ncat), araftn(ncat), vraftn(ncat)
  integer :: trcr_depend(ntrcr), n_trcr_strata(ntrcr), nt_strata(ntrcr, 2)
  real(c_double) :: trcr_base(ntrcr, 3)
  logical :: first_ice(ncat)
  type(pressridge_ridger) :: rg
  integer(int64) :: t0, t1, rate

  ncol = 100000
  if (command_argument_count() > 0) then
     call get_command_argument(1, arg)
     read (arg, *) ncol
  end if
  allocate(a(ncat, ncol), v(ncat, ncol), s(ncat, ncol), tr(ntrcr, ncat, ncol), a0(ncol))
  r = 0.5d0
  do c = 1, ncol
     r = lcg(r)
     a0(c) = 0.05d0 + 0.15d0 * r
     do n = 1, ncat
        r = lcg(r)
        w(n) = 0.2d0 + r
     end do
     sw = sum(w)
     do n = 1, ncat
        a(n, c) = (1.0d0 - a0(c)) * w(n) / sw
        r = lcg(r)
        v(n, c) = a(n, c) * hmid(n) * (0.8d0 + 0.4d0 * r)
     end do
     a0(c) = 1.0d0 - sum(a(:, c))
  end do
  s = 0.1d0 * v
  tr(1, :, :) = -20.0d0
  do k = 1, nilyr
     tr(1 + k, :, :) = -3.0d8 - 1.0d6 * k
     tr(9 + k, :, :) = 4.0d0 + 0.2d0 * k
  end do
  tr(9, :, :) = -1.15d8
  tr(17:23, :, :) = 0
  tr(17, :, :) = 2.0d7
  tr(18, :, :) = 0.4d0
  tr(19, :, :) = 0.8d0
  tr(20, :, :) = 0.8d0
  tr(21, :, :) = 0.2d0
  tr(22, :, :) = 0.1d0
  tr(23, :, :) = 0.01d0

  ! Icepack set-up: the tracer layout of the reference data, default parameters.
  call icepack_init_parameters()
  call icepack_init_tracer_flags(tr_iage_in=.true., tr_FY_in=.true., tr_lvl_in=.true., &
       tr_pond_in=.true., tr_pond_lvl_in=.true.)
  call icepack_init_tracer_sizes(ncat_in=ncat, nilyr_in=nilyr, nslyr_in=nslyr, nblyr_in=1, &
       ntrcr_in=ntrcr, nbtrcr_in=0, n_aero_in=0, n_iso_in=0)
  call icepack_init_tracer_indices(nt_Tsfc_in=1, nt_qice_in=2, nt_qsno_in=9, nt_sice_in=10, &
       nt_iage_in=17, nt_FY_in=18, nt_alvl_in=19, nt_vlvl_in=20, nt_apnd_in=21, &
       nt_hpnd_in=22, nt_ipnd_in=23)
  call icepack_warnings_flush(6)
  if (icepack_warnings_aborted()) error stop 'Icepack set-up failed'
  ! pressridge set-up; it returns Icepack's tracer tables.
  call pressridge_ridger_init(rg, ncat, nilyr, nslyr, .true., .true., .true., .true., &
       trcr_depend=trcr_depend, trcr_base=trcr_base, n_trcr_strata=n_trcr_strata, &
       nt_strata=nt_strata)

  call system_clock(count_rate=rate)
  allocate(ia, source=a)
  allocate(iv, source=v)
  allocate(is, source=s)
  allocate(it, source=tr)
  allocate(ia0, source=a0)
  allocate(iaice(ncol))
  allocate(pa, source=a)
  allocate(pv, source=v)
  allocate(ps, source=s)
  allocate(pt, source=tr)
  allocate(pa0, source=a0)
  allocate(paice(ncol), fr(ncol), fs(ncol), fh(ncol), fp(ncol), cv(ncol), sh(ncol))
  cv = conv
  sh = shear
  tic = huge(1.0d0)
  tpc = huge(1.0d0)
  tpb = huge(1.0d0)
  tdi = huge(1.0d0)
  do rep = 1, 3
     ! Icepack, per cell (as CICE's step_dyn_ridge).
     ia = a
     iv = v
     is = s
     it = tr
     ia0 = a0
     call system_clock(t0)
     do c = 1, ncol
        hin = hin0
        fpond = 0
        fresh = 0
        fhocn = 0
        fsalt = 0
        first_ice = .false.
        call icepack_step_ridge(dt=dt, ndtd=1, hin_max=hin, rdg_conv=cv(c), rdg_shear=sh(c), &
             aicen=ia(:, c), trcrn=it(:, :, c), vicen=iv(:, c), vsnon=is(:, c), aice0=ia0(c), &
             trcr_depend=trcr_depend, trcr_base=trcr_base, n_trcr_strata=n_trcr_strata, &
             nt_strata=nt_strata, dardg1dt=d1, dardg2dt=d2, dvirdgdt=d3, opening=op, &
             fpond=fpond, fresh=fresh, fhocn=fhocn, faero_ocn=faero, aparticn=aparticn, &
             krdgn=krdgn, aredistn=aredistn, vredistn=vredistn, dardg1ndt=dardg1ndt, &
             dardg2ndt=dardg2ndt, dvirdgndt=dvirdgndt, araftn=araftn, vraftn=vraftn, &
             aice=iaice(c), fsalt=fsalt, first_ice=first_ice, flux_bio=fbio, Tf=tf)
     end do
     call system_clock(t1)
     tic = min(tic, real(t1 - t0, c_double) / rate)
     if (icepack_warnings_aborted()) error stop 'Icepack aborted'
     ! pressridge, per cell through the C ABI, the same arguments.
     pa = a
     pv = v
     ps = s
     pt = tr
     pa0 = a0
     call system_clock(t0)
     do c = 1, ncol
        hin = hin0
        fpond = 0
        fresh = 0
        fhocn = 0
        fsalt = 0
        first_ice = .false.
        call pressridge_step_ridge(rg, dt, 1, hin, conv, shear, pa(:, c), pt(:, :, c), &
             pv(:, c), ps(:, c), pa0(c), d1, d2, d3, op, fpond, fresh, fhocn, &
             aparticn=aparticn, krdgn=krdgn, aredistn=aredistn, vredistn=vredistn, &
             dardg1ndt=dardg1ndt, dardg2ndt=dardg2ndt, dvirdgndt=dvirdgndt, araftn=araftn, &
             vraftn=vraftn, aice=paice(c), fsalt=fsalt, first_ice=first_ice, Tf=tf)
     end do
     call system_clock(t1)
     tpc = min(tpc, real(t1 - t0, c_double) / rate)
     diff = max(maxval(abs(pa - ia)), maxval(abs(pv - iv)), maxval(abs(ps - is)), &
          maxval(abs(pt - it) / max(1.0d0, abs(it))))
     ! The drop-in, Icepack's arguments (set-up read through Icepack's queries each call).
     pa = a
     pv = v
     ps = s
     pt = tr
     pa0 = a0
     call system_clock(t0)
     do c = 1, ncol
        hin = hin0
        fpond = 0
        fresh = 0
        fhocn = 0
        fsalt = 0
        first_ice = .false.
        call pressridge_icepack_step_ridge(dt=dt, ndtd=1, hin_max=hin, rdg_conv=cv(c), &
             rdg_shear=sh(c), aicen=pa(:, c), trcrn=pt(:, :, c), vicen=pv(:, c), &
             vsnon=ps(:, c), aice0=pa0(c), trcr_depend=trcr_depend, trcr_base=trcr_base, &
             n_trcr_strata=n_trcr_strata, nt_strata=nt_strata, dardg1dt=d1, dardg2dt=d2, &
             dvirdgdt=d3, opening=op, fpond=fpond, fresh=fresh, fhocn=fhocn, faero_ocn=faero, &
             aparticn=aparticn, krdgn=krdgn, aredistn=aredistn, vredistn=vredistn, &
             dardg1ndt=dardg1ndt, dardg2ndt=dardg2ndt, dvirdgndt=dvirdgndt, araftn=araftn, &
             vraftn=vraftn, aice=paice(c), fsalt=fsalt, first_ice=first_ice, flux_bio=fbio, &
             Tf=tf)
     end do
     call system_clock(t1)
     tdi = min(tdi, real(t1 - t0, c_double) / rate)
     if (icepack_warnings_aborted()) error stop 'the drop-in aborted'
     ddi = max(maxval(abs(pa - ia)), maxval(abs(pv - iv)), maxval(abs(ps - is)), &
          maxval(abs(pt - it) / max(1.0d0, abs(it))))
     ! pressridge, all cells in one call.
     pa = a
     pv = v
     ps = s
     pt = tr
     pa0 = a0
     fr = 0
     fs = 0
     fh = 0
     fp = 0
     call system_clock(t0)
     call pressridge_step_ridge_cells(rg, dt, 1, hin0, cv, sh, pa, pt, pv, ps, pa0, paice, &
          fresh=fr, fsalt=fs, fhocn=fh, fpond=fp)
     call system_clock(t1)
     tpb = min(tpb, real(t1 - t0, c_double) / rate)
  end do
  print '(a, i0, a)', 'complete ridging step, ncat = 5, 23 tracers, ', ncol, &
       ' cells, best of 3 (ns per cell):'
  print '(a, f9.1)', '  Icepack icepack_step_ridge, per cell:        ', 1d9 * tic / ncol
  print '(a, f9.1)', '  pressridge_step_ridge (C ABI), per cell:     ', 1d9 * tpc / ncol
  print '(a, f9.1)', '  pressridge_icepack_step_ridge (drop-in):     ', 1d9 * tdi / ncol
  print '(a, f9.1)', '  pressridge_step_ridge_cells, one call:       ', 1d9 * tpb / ncol
  print '(a, es10.2)', '  largest difference from Icepack (state, tracers relative): ', diff
  print '(a, es10.2)', '  the same for the drop-in: ', ddi
  call pressridge_ridger_free(rg)

  ! Ice strength, as CICE's step_dyn calls it once per cell; and pressridge batched.
  allocate(sic(ncol), spc(ncol), spb(ncol), sdi(ncol), ai(ncol), vi(ncol))
  do c = 1, ncol
     ai(c) = sum(a(:, c))
     vi(c) = sum(v(:, c))
  end do
  tic = huge(1.0d0)
  tpc = huge(1.0d0)
  tpb = huge(1.0d0)
  ! Icepack and pressridge alternate every 2000 cells and are timed in CPU time
  ! (cpu_time), so that both see the same load on a shared machine and time spent
  ! descheduled is not counted; best of 3 repetitions of the sums.
  tdi = huge(1.0d0)
  do rep = 1, 3
     t = 0
     d1 = 0
     op = 0
     do k = 1, ncol, 2000
        call cpu_time(d2)
        do c = k, min(k + 1999, ncol)
           sic(c) = 0
           call icepack_ice_strength(ai(c), vi(c), a0(c), a(:, c), v(:, c), sic(c))
        end do
        call cpu_time(d3)
        t = t + (d3 - d2)
        call cpu_time(d2)
        do c = k, min(k + 1999, ncol)
           call pressridge_ice_strength(ai(c), vi(c), a0(c), a(:, c), v(:, c), spc(c))
        end do
        call cpu_time(d3)
        d1 = d1 + (d3 - d2)
        call cpu_time(d2)
        do c = k, min(k + 1999, ncol)
           sdi(c) = 0
           call pressridge_icepack_ice_strength(ai(c), vi(c), a0(c), a(:, c), v(:, c), sdi(c))
        end do
        call cpu_time(d3)
        op = op + (d3 - d2)
     end do
     tic = min(tic, t)
     tpc = min(tpc, d1)
     tdi = min(tdi, op)
     call cpu_time(d2)
     call pressridge_strength(a, v, spb, aice0=a0)
     call cpu_time(d3)
     tpb = min(tpb, d3 - d2)
  end do
  if (icepack_warnings_aborted()) error stop 'icepack_ice_strength failed'
  print '(a, i0, a)', 'ice strength, ncat = 5, ', ncol, ' cells, best of 3, CPU time (ns per cell):'
  print '(a, f9.1)', '  Icepack icepack_ice_strength, per cell:      ', 1d9 * tic / ncol
  print '(a, f9.1)', '  pressridge_ice_strength, per cell:           ', 1d9 * tpc / ncol
  print '(a, f9.1)', '  pressridge_icepack_ice_strength (drop-in):   ', 1d9 * tdi / ncol
  print '(a, f9.1)', '  pressridge_strength, one call:               ', 1d9 * tpb / ncol
  print '(a, es10.2)', '  largest relative difference from Icepack: ', &
       max(maxval(abs(spc - sic) / max(1.0d0, abs(sic))), &
       maxval(abs(spb - sic) / max(1.0d0, abs(sic))), &
       maxval(abs(sdi - sic) / max(1.0d0, abs(sic))))

contains

  real(c_double) function lcg(x)
    real(c_double), intent(in) :: x
    lcg = modulo(x * 9301.0d0 + 0.49297d0, 1.0d0)
  end function lcg
end program bench_icepack_ridge
