!> Reference columns through Icepack's icepack_step_ridge for any tracer layout: reads the
!> layout and the cases as plain numbers on stdin (written by make_reference.py), calls
!> icepack_step_ridge once per case and prints every output with 18 significant digits.
!> Built against the user's Icepack checkout by make-reference.sh; no Icepack code is in
!> this repository. Input (list-directed):
!>   nilyr nslyr ntrcr n_aero n_iso nfsd
!>   20 indices nt_Tsfc nt_qice nt_qsno nt_sice nt_iage nt_FY nt_alvl nt_vlvl nt_apnd
!>     nt_hpnd nt_ipnd nt_smice nt_smliq nt_rhos nt_rsnw nt_isosno nt_isoice nt_aero nt_fsd
!>     nt_fbri (0: absent)
!>   11 flags (0/1) tr_iage tr_FY tr_lvl tr_pond_lvl tr_snow tr_iso tr_aero tr_pond_topo
!>     tr_brine tr_fsd, and snow refills (snwredist = 'ITD' with snwgrain)
!>   nblyr nbtrcr bgc (0 none, 1 skl_bgc, 2 z_tracers), then, with nbtrcr > 0, bio_index(nbtrcr)
!>   ntrcr rows: trcr_depend trcr_base(1:3) n_trcr_strata nt_strata(1:2)
!>   ncase, then per case: ncat ndtd krdg_partic krdg_redist has_closing docleanup dorebin;
!>   dt rdg_conv rdg_shear mu_rdg Tf aice0 aice closing opening; hin_max(0:ncat); aicen;
!>   vicen; vsnon; trcrn(ntrcr, ncat) in Fortran order; first_ice (0/1).
!> Output: per case a line `case K`, then `name v1 v2 ...` lines (with icepack_ice_strength
!> of the new state, N/m, 0 where the step aborted); warnings on unit 7.
program ridge_reference
  use icepack_intfc, only: icepack_step_ridge, icepack_ice_strength, icepack_init_tracer_sizes, &
       icepack_init_tracer_flags, icepack_init_tracer_indices, icepack_init_parameters, &
       icepack_warnings_flush, icepack_warnings_aborted, icepack_warnings_clear, &
       icepack_query_parameters
  implicit none
  integer, parameter :: dp = kind(1.0d0)
  integer :: nilyr, nslyr, ntrcr, n_aero, n_iso, nfsd, nt(20), fl(11), ncase, k, it, n
  integer :: nblyr, nbtrcr, bgc
  integer, allocatable :: bio_index(:)
  integer :: ncat, ndtd, kp, kr, hasc, docl, dore
  integer, allocatable :: trcr_depend(:), n_trcr_strata(:), nt_strata(:, :), fi(:)
  real(dp), allocatable :: trcr_base(:, :), hin(:), a(:), v(:), s(:), tr(:, :)
  real(dp), allocatable :: aparticn(:), krdgn(:), aredistn(:), vredistn(:), dardg1ndt(:), &
       dardg2ndt(:), dvirdgndt(:), araftn(:), vraftn(:)
  logical, allocatable :: first_ice(:)
  real(dp) :: dt, conv, shear, mu_rdg, tf, aice0, aice, closing, opening
  real(dp) :: d1, d2, d3, fpond, fresh, fhocn, fsalt, dpnd, faero(6), fiso(3), str
  real(dp), allocatable :: fbio(:)
  real(dp) :: rhosnew, rhos, rsnw_fall

  read (*, *) nilyr, nslyr, ntrcr, n_aero, n_iso, nfsd
  read (*, *) nt
  read (*, *) fl
  read (*, *) nblyr, nbtrcr, bgc
  allocate(bio_index(max(nbtrcr, 1)), fbio(max(nbtrcr, 1)))
  bio_index = 0
  if (nbtrcr > 0) read (*, *) bio_index(1:nbtrcr)
  allocate(trcr_depend(ntrcr), n_trcr_strata(ntrcr), nt_strata(ntrcr, 2), trcr_base(ntrcr, 3))
  do it = 1, ntrcr
     read (*, *) trcr_depend(it), trcr_base(it, :), n_trcr_strata(it), nt_strata(it, :)
  end do
  call icepack_init_tracer_flags(tr_iage_in=fl(1) == 1, tr_FY_in=fl(2) == 1, &
       tr_lvl_in=fl(3) == 1, tr_pond_in=fl(4) == 1, tr_pond_lvl_in=fl(4) == 1, &
       tr_snow_in=fl(5) == 1, tr_iso_in=fl(6) == 1, tr_aero_in=fl(7) == 1, &
       tr_pond_topo_in=fl(8) == 1, tr_brine_in=fl(9) == 1, tr_fsd_in=fl(10) == 1)
  if (fl(8) == 1) call icepack_init_tracer_flags(tr_pond_in=.true., tr_pond_lvl_in=.false.)
  call icepack_init_tracer_indices(nt_Tsfc_in=nt(1), nt_qice_in=nt(2), nt_qsno_in=nt(3), &
       nt_sice_in=nt(4), nt_iage_in=nt(5), nt_FY_in=nt(6), nt_alvl_in=nt(7), nt_vlvl_in=nt(8), &
       nt_apnd_in=nt(9), nt_hpnd_in=nt(10), nt_ipnd_in=nt(11), nt_smice_in=nt(12), &
       nt_smliq_in=nt(13), nt_rhos_in=nt(14), nt_rsnw_in=nt(15), nt_isosno_in=nt(16), &
       nt_isoice_in=nt(17), nt_aero_in=nt(18), nt_fsd_in=nt(19), nt_fbri_in=nt(20))
  if (nbtrcr > 0) then
     call icepack_init_tracer_indices(bio_index_in=bio_index(1:nbtrcr))
     call icepack_init_parameters(skl_bgc_in=bgc == 1, z_tracers_in=bgc == 2)
  end if
  open (7, file='warnings.txt', status='replace')
  read (*, *) ncase
  do k = 1, ncase
     read (*, *) ncat, ndtd, kp, kr, hasc, docl, dore
     read (*, *) dt, conv, shear, mu_rdg, tf, aice0, aice, closing, opening
     allocate(hin(0:ncat), a(ncat), v(ncat), s(ncat), tr(ntrcr, ncat), fi(ncat), &
          first_ice(ncat), aparticn(ncat), krdgn(ncat), aredistn(ncat), vredistn(ncat), &
          dardg1ndt(ncat), dardg2ndt(ncat), dvirdgndt(ncat), araftn(ncat), vraftn(ncat))
     read (*, *) hin
     read (*, *) a
     read (*, *) v
     read (*, *) s
     read (*, *) tr
     read (*, *) fi
     first_ice = fi == 1
     call icepack_warnings_clear()
     call icepack_init_parameters(krdg_partic_in=kp, krdg_redist_in=kr, mu_rdg_in=mu_rdg)
     if (fl(11) == 1) call icepack_init_parameters(snwredist_in='ITD', snwgrain_in=.true.)
     ! ntrcr_o, the tracers before the bio ones (Icepack's ridging does not read it; a
     ! host's driver sets it, and the pressridge drop-in asks for it).
     call icepack_init_tracer_sizes(ncat_in=ncat, nilyr_in=nilyr, nslyr_in=nslyr, &
          nblyr_in=nblyr, ntrcr_in=ntrcr, nbtrcr_in=nbtrcr, n_aero_in=n_aero, n_iso_in=n_iso, &
          nfsd_in=max(nfsd, 1), ntrcr_o_in=ntrcr - nbtrcr * merge(nblyr + 3, 1, bgc == 2))
     if (k == 1) then
        call icepack_query_parameters(rhosnew_out=rhosnew, rhos_out=rhos, &
             rsnw_fall_out=rsnw_fall)
        write (*, '(a, 3(1x, es25.17e3))') 'refill', rhosnew, rhos, rsnw_fall
     end if
     d1 = 0; d2 = 0; d3 = 0; fpond = 0; fresh = 0; fhocn = 0; fsalt = 0; dpnd = 0
     faero = 0; fiso = 0; fbio = 0
     aparticn = 0; krdgn = 0; aredistn = 0; vredistn = 0; dardg1ndt = 0; dardg2ndt = 0
     dvirdgndt = 0; araftn = 0; vraftn = 0
     if (hasc == 0) opening = 0
     ! closing present (SIS2) or absent (CICE): an absent optional is passed on absent.
     if (hasc == 1) then
        call step(closing)
     else
        call step()
     end if
     ! The strength of the new state (Icepack's kstrength, Rothrock by default).
     str = 0
     if (.not. icepack_warnings_aborted()) call icepack_ice_strength(aice=aice, &
          vice=sum(v), aice0=aice0, aicen=a, vicen=v, strength=str)
     write (*, '(a, i0)') 'case ', k
     write (*, '(a, l1)') 'aborted ', icepack_warnings_aborted()
     call put('hin_max', hin)
     call put('aicen', a)
     call put('vicen', v)
     call put('vsnon', s)
     call put('trcrn', reshape(tr, [ntrcr * ncat]))
     call put('aice0', [aice0])
     call put('aice', [aice])
     call put('closing', [closing])
     call put('opening', [opening])
     call put('dardg1dt', [d1])
     call put('dardg2dt', [d2])
     call put('dvirdgdt', [d3])
     call put('dardg1ndt', dardg1ndt)
     call put('dardg2ndt', dardg2ndt)
     call put('dvirdgndt', dvirdgndt)
     call put('aparticn', aparticn)
     call put('krdgn', krdgn)
     call put('aredistn', aredistn)
     call put('vredistn', vredistn)
     call put('araftn', araftn)
     call put('vraftn', vraftn)
     call put('fresh', [fresh])
     call put('fsalt', [fsalt])
     call put('fhocn', [fhocn])
     call put('fpond', [fpond])
     call put('dpnd_ridge', [dpnd])
     call put('strength', [str])
     call put('faero_ocn', faero(1:n_aero))
     call put('fiso_ocn', fiso(1:n_iso))
     call put('flux_bio', fbio(1:nbtrcr))
     write (*, '(a, *(1x, i0))') 'first_ice', (merge(1, 0, first_ice(n)), n = 1, ncat)
     write (7, '(a, i0)') 'case ', k
     call icepack_warnings_flush(7)
     deallocate(hin, a, v, s, tr, fi, first_ice, aparticn, krdgn, aredistn, vredistn, &
          dardg1ndt, dardg2ndt, dvirdgndt, araftn, vraftn)
  end do
  close (7)

contains

  !> Icepack's step of the case read (closing: the host's, or absent).
  subroutine step(cl)
    real(dp), intent(inout), optional :: cl
    call icepack_step_ridge(dt=dt, ndtd=ndtd, hin_max=hin, rdg_conv=conv, rdg_shear=shear, &
         aicen=a, trcrn=tr, vicen=v, vsnon=s, aice0=aice0, trcr_depend=trcr_depend, &
         trcr_base=trcr_base, n_trcr_strata=n_trcr_strata, nt_strata=nt_strata, &
         dardg1dt=d1, dardg2dt=d2, dvirdgdt=d3, opening=opening, fpond=fpond, fresh=fresh, &
         fhocn=fhocn, faero_ocn=faero, fiso_ocn=fiso, aparticn=aparticn, krdgn=krdgn, &
         aredistn=aredistn, vredistn=vredistn, dardg1ndt=dardg1ndt, dardg2ndt=dardg2ndt, &
         dvirdgndt=dvirdgndt, araftn=araftn, vraftn=vraftn, aice=aice, fsalt=fsalt, &
         first_ice=first_ice, flux_bio=fbio, closing=cl, Tf=tf, dpnd_ridge=dpnd, &
         docleanup=docl == 1, dorebin=dore == 1)
  end subroutine step

  subroutine put(name, x)
    character(len=*), intent(in) :: name
    real(dp), intent(in) :: x(:)
    write (*, '(a, *(1x, es25.17e3))') name, x
  end subroutine put

end program ridge_reference
